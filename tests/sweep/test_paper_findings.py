#!/usr/bin/python3
"""The report names every finding whose agreement with the paper changed between an earlier
grid and this one, or whose number moved by more than 10 % (tools/icedem_tools/reports/paper_findings.py,
changed_findings), in a sentence with both numbers, and counts the others."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
from icedem_tools.reports.paper_findings import changed_findings  # noqa: E402


# (finding, paper, icedem, agrees?, cause)
before = [("max load", "75 N", "36.8 N", False, None), ("ratio", "1.5", "1.45", True, None),
          ("interval", "4 s", "5.09 s", False, None), ("trend", "yes", "n/a", None, None)]
now = [("max load", "75 N", "70.1 N", True, None), ("ratio", "1.5", "1.10", False, None),
       ("interval", "4 s", "5.20 s", False, None), ("trend", "yes", "9 N", True, None),
       ("new finding", "x", "y", True, None)]
text = "\n".join(changed_findings(now, before, "PGS", "converged"))
print(text)
check("**max load** now agrees with the paper: 36.8 N with PGS, 70.1 N with converged." in text,
      "a finding that came to agree says so with both numbers")
check("**ratio** no longer agrees with the paper: 1.45 with PGS, 1.10 with converged." in text,
      "a finding that stopped agreeing says so with both numbers")
check("interval" not in text.split("The other")[0], "a finding that disagrees as before, 2 % apart, is not listed")
check("**trend** moved by" not in text, "a finding without an earlier number is not said to move")
check("The other 2 findings moved by 10 % (10 points for a percentage) or less" in text,
      "they are counted; a finding absent from the earlier grid is not")
check(changed_findings(now, None, "PGS", "converged") == [], "no earlier grid: no section")
check("No finding changed its agreement" in "\n".join(changed_findings(before, before, "a", "b")),
      "nothing changed: says so")
moved = [("max load", "75 N", "50.0 N", False, None), ("ratio", "1.5", "1.46", True, None)]
text = "\n".join(changed_findings(moved, before, "PGS", "converged"))
print(text)
check("- **max load** moved by +36 %: 36.8 N with PGS, 50.0 N with converged, and disagrees with the paper as "
      "before." in text, "a number 36 % up, still disagreeing, says so in a sentence")
check("**ratio** moved" not in text, "a number 1 % apart does not")
shares = [("size", "small", "1.0 %", True, None)], [("size", "small", "0.0 %", True, None)]
check("**size** moved" not in "\n".join(changed_findings(shares[1], shares[0], "a", "b")),
      "a percentage from 1.0 % to 0.0 % moved by 1 point, not by -100 %")
shares = [("size", "small", "-13.2 %", False, None)], [("size", "small", "1.0 %", True, None)]
check("now agrees" in "\n".join(changed_findings(shares[1], shares[0], "a", "b")), "agreement first")

finish()
