#!/usr/bin/python3
"""Pictures of breaks like the seed paper's Fig. 18: tools/icedem_tools/break_pictures.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.break_pictures import main  # noqa: E402

sys.exit(main())
