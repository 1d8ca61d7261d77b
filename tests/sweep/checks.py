"""The check-list test scripts' common part: the repository's root, the tools package on the
import path, `check` (prints ok or FAIL and keeps the failures) and `finish` (exit 1 if any
failed). A script beside this file:

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
    from checks import ROOT, check, finish  # noqa: E402
"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def finish():
    """Exit 1 naming how many checks failed, or say all passed."""
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    print("all checks passed")
