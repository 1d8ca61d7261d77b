#!/usr/bin/python3
"""scripts/full_runs judges a variant against the reference by the convergence criteria
(mean 3 %, p99 5 %, mean of maxima 10 %, failure ratio 5 %, floes breaking as often),
each difference with its 95 % interval over the paired seeds: within the bound, beyond
it, or unresolved by the seeds; each criterion on its own."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
from icedem_tools.studies.full_runs import TOLERANCE, judge  # noqa: E402


SEEDS = [1, 2, 3, 4, 5]
BASE = {"mean": 10.0, "p99": 30.0, "max": 50.0, "ratio": 0.6}
# the reference's seeds scatter as real runs do (a few % on the mean, more on maxima)
SCATTER = np.array([-0.04, 0.02, 0.05, -0.01, -0.02])


def ensemble(shift=None, noise=0.0, floes=2.0, seeds=SEEDS):
    """Per-seed values: the reference's, times (1 + shift[k]) for a variant, plus noise."""
    shift = shift or {}
    runs = {}
    for k, v in BASE.items():
        wiggle = noise * np.array([1, -1, 1, -1, 1])[: len(seeds)]
        runs[k] = v * (1 + SCATTER[: len(seeds)]) * (1 + shift.get(k, 0.0) + wiggle)
    e = {"seeds": list(seeds), "runs": runs, "breaks": (3 * floes, 0.0), "floes_broken": (floes, 0.0),
         "n": len(seeds)}
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
# floes broken: the exact test of two Poisson rates, 5 runs each (two-sided, 5 %)
check(judge(ensemble(floes=2.0), ref)[1], "as many broken floes as the reference: as often")
check(judge(ensemble(floes=3.6), ref)[1], "18 broken floes against 10: not told apart (p = 0.18)")
check(not judge(ensemble(floes=4.8), ref)[1], "24 against 10: more often (p = 0.024)")
check(not judge(ensemble(floes=0.0), ref)[1], "none against 10: fewer")
none = ensemble(floes=0.0)
check(judge(ensemble(floes=0.6), none)[1], "3 broken floes where the reference has none: not told apart (p = 0.25)")
check(judge(ensemble(floes=1.0), none)[1], "5 where the reference has none: not told apart (p = 0.06)")
check(not judge(ensemble(floes=1.2), none)[1] and judge(ensemble(floes=1.2), none)[2] == "no",
      "6 where the reference has none: more often (p = 0.03), fails")
check(judge(ensemble(floes=0.0), none)[1], "none in either: as often")
three = judge(ensemble(seeds=[1, 2, 3]), ref)
check(three[3] == 3, "only the seeds both have are paired")
finish()
