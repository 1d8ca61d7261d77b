#!/usr/bin/python3
"""A run's snapshots as an XDMF view for ParaView: tools/icedem_tools/xdmf.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.xdmf import main  # noqa: E402

sys.exit(main())
