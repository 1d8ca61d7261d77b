#!/usr/bin/python3
"""A sweep's figures (and XDMF views for ParaView): tools/icedem_tools/figures.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.figures import main  # noqa: E402

sys.exit(main())
