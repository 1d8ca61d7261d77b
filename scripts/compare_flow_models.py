#!/usr/bin/python3
"""The flow models compared on one scenario: still water, analytic and OpenFOAM potential flow: tools/icedem_tools/compare_flow_models.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.compare_flow_models import main  # noqa: E402

sys.exit(main())
