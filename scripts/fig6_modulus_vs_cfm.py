#!/usr/bin/python3
"""The seed paper's Figure 6 for this solver: elastic modulus against the joints' CFM: tools/icedem_tools/fig6_modulus_vs_cfm.py (--help for its use)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "tools"))
from icedem_tools.fig6_modulus_vs_cfm import main  # noqa: E402

sys.exit(main())
