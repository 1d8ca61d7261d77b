#!/usr/bin/python3
"""scripts/full_runs judges a variant against the reference by the convergence criteria
(mean 3 %, p99 5 %, mean of maxima 10 %, breaks inside the reference's 95 % interval):
each criterion on its own, just inside and just outside its bound."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "tools"))
from icedem_tools.full_runs import judge  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


ref = {"n": 5, "mean": 10.0, "p99": 30.0, "max": 50.0, "breaks": 6.0, "breaks_hw": 2.0}


def variant(**changes):
    v = dict(ref)
    v.update(changes)
    return v


err, breaks_ok, ok = judge(variant(), ref)
check(ok and breaks_ok and all(e == 0 for e in err.values()), "the reference itself passes")
for key, bound in (("mean", 0.03), ("p99", 0.05), ("max", 0.10)):
    inside = judge(variant(**{key: ref[key] * (1 + 0.9 * bound)}), ref)
    outside = judge(variant(**{key: ref[key] * (1 - 1.1 * bound)}), ref)
    check(inside[2], f"{key} {90 * bound:.1f} % high passes")
    check(not outside[2] and abs(outside[0][key] + 1.1 * bound) < 1e-12, f"{key} {110 * bound:.1f} % low fails")
check(judge(variant(breaks=7.9), ref)[1], "breaks inside the reference's interval pass")
check(not judge(variant(breaks=8.5), ref)[1], "breaks outside the reference's interval fail")
check(not judge(variant(breaks=1.0), variant(breaks=0.0, breaks_hw=0.0))[2], "breaks where the reference has none fail")
check(judge(variant(breaks=0.0, breaks_hw=0.0), variant(breaks=0.0, breaks_hw=0.0))[1], "no breaks in either pass")
sys.exit(1 if failures else 0)
