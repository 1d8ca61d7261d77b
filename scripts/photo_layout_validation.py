#!/usr/bin/python3
"""Validation of scripts/layout_from_photo on synthetic photos of known layouts: tools/icedem_tools/photo_layout_validation.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.photo_layout_validation import main  # noqa: E402

sys.exit(main())
