#!/usr/bin/python3
"""The change of a block mean between two ensembles of runs (tools/icedem_tools/stats/block_change.py) on cases
with a known answer: its point value, and the coverage of its 95 % interval on blocks that are correlated as a
tow's are (a first-order autoregression), with and without the correction for that correlation."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
from icedem_tools.stats import block_change as bc  # noqa: E402

rng = np.random.default_rng(11)


def ar1(n, phi):
    """n blocks of a stationary first-order autoregression, unit variance, lag-1 correlation phi."""
    x, out = rng.normal(), []
    for _ in range(n):
        x = phi * x + np.sqrt(1 - phi ** 2) * rng.normal()
        out.append(x)
    return np.array(out)


# every block 10 % up: +10 % exactly, with no width
b = [np.array([10.0, 12.0, 9.0, 11.0]), np.array([13.0, 8.0, 10.0, 12.0])]
d, iv, word, p, n = bc.change([1.1 * x for x in b], b)
check(abs(d - 0.1) < 1e-12 and iv[0] < 0.1 < iv[1] and n == 16,
      f"+10 % on every block: {100 * d:.3f} % ({100 * iv[0]:.1f} to {100 * iv[1]:.1f}), 16 blocks")
# white noise: the corrected lag-1 correlation is near 0 (uncorrected it averages -1/24); over 2,000 runs of 24
# blocks its mean has a standard error of about 0.005, so within 0.02
r = np.mean([bc.lag1([ar1(24, 0.0)]) for _ in range(2000)])
check(abs(r) < 0.02, f"white blocks: the corrected lag-1 correlation averages {r:.4f}, 0 within 0.02")
r = np.mean([bc.lag1([ar1(24, 0.5), ar1(24, 0.5)]) for _ in range(2000)])
check(abs(r - 0.5) < 0.03, f"phi 0.5: the corrected lag-1 correlation averages {r:.3f}, 0.5 within 0.03")

# coverage: two ensembles of 2 runs x 24 blocks (a 280 s tow's window), means 110 and 100, 25 % scatter, phi 0.5.
# 2,000 samples: a binomial sigma of 0.5 points; the corrected interval within 93-98 %, the one that takes the
# blocks as independent well below (about 76 %: its variance short by (1 + phi) / (1 - phi) = 3)
N, covered, naive = 2000, 0, 0
for _ in range(N):
    A = [110 * (1 + 0.25 * ar1(24, 0.5)) for _ in range(2)]
    B = [100 * (1 + 0.25 * ar1(24, 0.5)) for _ in range(2)]
    d, iv, *_ = bc.change(A, B)
    covered += iv[0] <= 0.1 <= iv[1]
    lag1 = bc.lag1
    bc.lag1 = lambda runs: 0.0  # the blocks taken as independent
    d, iv0, *_ = bc.change(A, B)
    bc.lag1 = lag1
    naive += iv0[0] <= 0.1 <= iv0[1]
check(0.93 <= covered / N <= 0.98, f"phi 0.5, 2 x 24 blocks: the interval covers +10 % in {100 * covered / N:.1f} % "
      "of samples (93-98 %)")
check(naive / N < 0.85, f"the same taken as independent blocks covers {100 * naive / N:.1f} % (below 85 %)")
finish()
