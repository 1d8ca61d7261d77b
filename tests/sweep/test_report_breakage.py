#!/usr/bin/python3
"""The report's mechanism shares and the paper's Fig. 18 shift are judged with intervals
that take the runs, not the breaks, as the samples (tools/icedem_tools/reports/report_breakage.py):
a shift every run shows is found, no shift is not, and one run's burst of breaks is not
taken for a shift (a binomial interval over the breaks would take it)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
from icedem_tools.reports.report_breakage import bootstrap_shares, fig18_shift, interval  # noqa: E402

MECHANISMS = ["on the slope", "pressed under", "in the rubble", "in the pack"]


def runs(*rows, times=1):
    """Per-run counts in MECHANISMS order, each row repeated `times`."""
    return np.array([list(r) for r in rows] * times, dtype=float)


# every run at f_ii 0.3 breaks pressed under, every run at 0.7 on the slope: the paper's shift
low = runs((0, 3, 1, 0), (1, 4, 0, 0), (0, 2, 1, 0), times=4)
high = runs((3, 0, 1, 0), (4, 1, 0, 0), (2, 0, 1, 0), times=4)
shift = fig18_shift(low, high, MECHANISMS, np.random.default_rng(1))
check(shift["pressed under"][2] == "appears", f"pressed under falls in every run: {shift['pressed under']}")
check(shift["on the slope"][2] == "appears", f"on the slope rises in every run: {shift['on the slope']}")
rev = fig18_shift(high, low, MECHANISMS, np.random.default_rng(1))
check(rev["pressed under"][2] == "reversed" and rev["on the slope"][2] == "reversed",
      f"the opposite shift is reversed: {rev}")

# the same runs at both frictions: no shift
same = fig18_shift(low, low.copy(), MECHANISMS, np.random.default_rng(2))
check(all(v[2] == "not resolved" for v in same.values()), f"no shift is not resolved: {same}")
check(all(v[1][0] < 0 < v[1][1] for v in same.values()), f"its intervals straddle 0: {same}")

# ten runs at each friction, one break each pressed under, except one run at 0.7 that broke
# 30 joints on the slope (a floe and its neighbours in one jam): 77 % of the breaks at 0.7 are
# on the slope, but one run in ten says so. A binomial interval over the 39 breaks would call
# the shift resolved; over runs it is not.
low = runs((0, 1, 0, 0), times=10)
high = np.vstack([runs((0, 1, 0, 0), times=9), runs((30, 0, 0, 0))])
burst = fig18_shift(low, high, MECHANISMS, np.random.default_rng(3))
d, iv, verdict = burst["on the slope"]
check(abs(d - 30 / 39) < 1e-12, f"the point share moves by 30/39: {d}")
check(verdict == "not resolved" and iv[0] <= 0.0, f"one run's burst is not resolved: {burst['on the slope']}")
p = 30 / 39
binomial_lo = p - 1.96 * np.sqrt(p * (1 - p) / 39)
check(binomial_lo > 0.5, f"(the binomial interval over breaks would have said resolved: from {binomial_lo:.2f})")

# the shares' interval covers the point share, and resamples without breaks are left out
shares = bootstrap_shares(runs((0, 0, 0, 0), (1, 1, 0, 0), (0, 2, 0, 0)), np.random.default_rng(4))
iv = interval(shares[:, 1])
check(iv is not None and iv[0] <= 3 / 4 <= iv[1], f"pressed under 3/4 inside its interval {iv}")

finish()
