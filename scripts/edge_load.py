#!/usr/bin/python3
"""The vertical edge load that breaks a square floe floating on water, in bending: tools/icedem_tools/edge_load.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.edge_load import main  # noqa: E402

sys.exit(main())
