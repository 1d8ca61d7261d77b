#!/usr/bin/python3
"""The joint breaks of one run: count by mode, and where they happened: tools/icedem_tools/fracture_events.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.fracture_events import main  # noqa: E402

sys.exit(main())
