#!/usr/bin/python3
"""scripts/full_runs judges a variant against the reference by the convergence criteria
(mean 3 %, p99 5 %, mean of maxima 10 %, failure ratio 5 %, breaks inside the
reference's 95 % interval), each difference with its 95 % interval over the paired seeds:
within the bound, beyond it, or unresolved by the seeds; each criterion on its own."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "tools"))
from icedem_tools.full_runs import TOLERANCE, judge  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


SEEDS = [1, 2, 3, 4, 5]
BASE = {"mean": 10.0, "p99": 30.0, "max": 50.0, "ratio": 0.6}
# the reference's seeds scatter as real runs do (a few % on the mean, more on maxima)
SCATTER = np.array([-0.04, 0.02, 0.05, -0.01, -0.02])


def ensemble(shift=None, noise=0.0, breaks=(6.0, 2.0), seeds=SEEDS):
    """Per-seed values: the reference's, times (1 + shift[k]) for a variant, plus noise."""
    shift = shift or {}
    runs = {}
    for k, v in BASE.items():
        wiggle = noise * np.array([1, -1, 1, -1, 1])[: len(seeds)]
        runs[k] = v * (1 + SCATTER[: len(seeds)]) * (1 + shift.get(k, 0.0) + wiggle)
    e = {"seeds": list(seeds), "runs": runs, "breaks": breaks, "n": len(seeds)}
    for k, v in runs.items():
        e[k] = (float(v.mean()), 0.0)
    return e


ref = ensemble()
out, breaks_ok, overall, paired = judge(ensemble(), ref)
check(overall == "yes" and paired == 5 and all(abs(d) < 1e-12 and v == "within" for d, _, v in out.values()),
      "the reference against itself: every criterion within, passes")
for key, bound in TOLERANCE.items():
    inside = judge(ensemble({key: 0.9 * bound}, noise=0.001), ref)
    beyond = judge(ensemble({key: -1.5 * bound}, noise=0.001), ref)
    loose = judge(ensemble({key: 0.5 * bound}, noise=0.5 * bound), ref)
    check(inside[0][key][2] == "within" and inside[2] == "yes", f"{key} {90 * bound:.1f} % high, seeds agreeing: within")
    check(beyond[0][key][2] == "beyond" and beyond[2] == "no" and abs(beyond[0][key][0] + 1.5 * bound) < 1e-3,
          f"{key} {150 * bound:.1f} % low, seeds agreeing: beyond, fails")
    check(loose[0][key][2] == "unresolved" and loose[2] == "undecided",
          f"{key} {50 * bound:.1f} % high with seeds scattering by {50 * bound:.1f} %: unresolved, undecided")
# the reference's 6 breaks a run over 5 runs: 30, Poisson's 95 % interval 20.2-42.8, per run 4.05-8.57
check(judge(ensemble(breaks=(8.4, 2.0)), ref)[1] and judge(ensemble(breaks=(4.2, 2.0)), ref)[1],
      "breaks inside the reference's Poisson interval (4.05-8.57 a run) pass")
check(not judge(ensemble(breaks=(8.7, 2.0)), ref)[1] and not judge(ensemble(breaks=(3.9, 2.0)), ref)[1],
      "breaks outside it fail")
# none in 5 runs: 0-0.74 a run (3.69 / 5), where Student's interval would be 0-0
none = ensemble(breaks=(0.0, 0.0))
check(judge(ensemble(breaks=(0.6, 1.0)), none)[1], "a break in 2 of 5 runs where the reference has none passes")
check(judge(ensemble(breaks=(1.0, 1.0)), none)[2] == "no", "a break a run where the reference has none fails")
check(judge(ensemble(breaks=(0.0, 0.0)), none)[1], "no breaks in either pass")
three = judge(ensemble(seeds=[1, 2, 3]), ref)
check(three[3] == 3, "only the seeds both have are paired")
sys.exit(1 if failures else 0)
