#!/usr/bin/python3
"""Run the validation scenarios (scenarios/validation/) and plot them: tools/icedem_tools/validation_report.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.validation_report import main  # noqa: E402

sys.exit(main())
