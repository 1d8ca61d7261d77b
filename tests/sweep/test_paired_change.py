#!/usr/bin/python3
"""The estimators of a paired change (tools/icedem_tools/stats/paired_change.py) on cases with a known
answer, the coverage of the one the verdicts use, and the coverage page made again from the committed
records: its numbers are the tool's (docs/model/estimators.md)."""
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import ROOT, check, finish  # noqa: E402
from icedem_tools.stats import paired_change as pc  # noqa: E402

b = np.array([10.0, 12.0, 9.0, 11.0, 13.0])
# every seed 10 % up: each estimator says +10 %; the ratio estimators with no width (no scatter of the
# change), the estimator relative to the reference's mean with a width that is the reference's own
# scatter, not the change's (the fault the log ratio replaced it for)
for name, est in pc.ESTIMATORS.items():
    args = (1.1 * b, b, np.random.default_rng(1)) if est is pc.ratio_bootstrap else (1.1 * b, b)
    c, lo, hi = est(*args)
    if est is pc.relative_to_mean:
        check(abs(c - 0.1) < 1e-12 and hi - lo > 0.02, f"{name}: +10 % on every seed is +10 %, but "
              f"{100 * lo:.1f} to {100 * hi:.1f} %")
    else:
        check(abs(c - 0.1) < 1e-12 and abs(lo - 0.1) < 1e-9 and abs(hi - 0.1) < 1e-9,
              f"{name}: +10 % on every seed is +10 %, exactly ({c:.6f}, {lo:.6f} to {hi:.6f})")
# the reference's scatter: a variant that adds 1 to every seed changes the mean by 1 / 11 (ratio of
# means) and the geometric mean by a little more (the smaller seeds gain more)
c, lo, hi = pc.ratio_delta(b + 1, b)
check(abs(c - 1 / 11) < 1e-12, f"ratio of means: +1 on a mean of 11 is {100 * c:.3f} %")
c, lo, hi = pc.log_ratio(b + 1, b)
check(abs(c - (np.exp(np.mean(np.log((b + 1) / b))) - 1)) < 1e-12 and c > 1 / 11,
      f"log ratio: the geometric mean's change, {100 * c:.3f} % (above 9.091 %)")
# the log ratio's interval covers its target 95 % of the time where the pairs are lognormal (its own
# assumption): 4,000 samples of 10 correlated pairs, coverage within 1.5 points (3 binomial sigmas)
rng = np.random.default_rng(7)
mu, cov = np.array([np.log(110.0), np.log(100.0)]), np.array([[0.09, 0.05], [0.05, 0.09]])
z = rng.multivariate_normal(mu, cov, size=(4000, 10))
_, lo, hi = pc.log_ratio(np.exp(z[..., 0]), np.exp(z[..., 1]))
truth = np.expm1(mu[0] - mu[1])
cover = np.mean((lo <= truth) & (truth <= hi))
check(abs(cover - 0.95) < 0.015, f"log ratio covers {100 * cover:.1f} % of lognormal samples (95 % asked)")

# the page's coverage block, made again from the committed records, is the committed one (its date aside)
page = os.path.join(ROOT, "docs", "model", "estimators.md")
with tempfile.TemporaryDirectory() as d:
    out = os.path.join(d, "estimators.md")
    made = open(page).read()
    begin = made.index("<!-- estimator coverage")
    cmd = re.search(r"`scripts/estimator_coverage ([^`]*)`", made[begin:]).group(1).split()
    open(out, "w").write(made)  # the page's own text stays; the tool replaces its block
    p = subprocess.run([os.path.join(ROOT, "scripts", "estimator_coverage"), *cmd, "--report", out],
                       capture_output=True, text=True)
    again = open(out).read()
    undated = lambda s: re.sub(r"Made \d{4}-\d\d-\d\d", "Made", s)  # noqa: E731
    check(p.returncode == 0 and undated(again) == undated(made),
          "docs/model/estimators.md's coverage block is what scripts/estimator_coverage makes from the records")
finish()
