"""A number of a run taken block by block (its 10 s blocks' means or maxima, sweeps/aggregate.block_loads),
pooled over an ensemble's runs: its mean with a 95 % interval, and the change of that mean between two
ensembles (two settings, the runs not paired: a chaotic tow's start at another setting is another draw).

A tow's blocks are not independent: the rubble at the cone builds up and clears over more than a block, so a
block's load is like its neighbour's. The intervals take that in as a first-order autoregression: with r1
the lag-1 correlation of the blocks within their runs (pooled over the ensemble's runs, each run about its
own mean), the variance of a mean of n blocks is that of n (1 - r1) / (1 + r1) independent ones (the
effective number, Bayley and Hammersley 1946; r1 below 0 taken as 0). Student's quantile on the effective
number (Welch-Satterthwaite's degrees of freedom for a change). The change is the ratio of the two means,
its interval that of the log ratio by the delta method: the log of a mean has the standard error
s / (m sqrt(n_eff)).

Each function takes `runs`: a list of the ensemble's runs, each a sequence of its blocks' values in time order."""
import math

import numpy as np
from scipy import stats

LEVEL = 0.95


def lag1(runs):
    """The lag-1 correlation of the blocks within their runs, pooled (sum over runs of (x_k - m)(x_k+1 - m) over
    the sum of (x_k - m)^2, m each run's own mean), corrected for its bias over short runs: for n blocks a run it
    falls short of the autoregression's phi by about (1 + 3 phi) / n (Marriott and Pope 1954), so
    phi = (n r + 1) / (n - 3); uncorrected, the intervals over a tow's ~24 blocks would fall short of their 95 %
    (tests/sweep/test_block_change.py checks the coverage with it). 0 where no run has two blocks or none varies."""
    num = den = 0.0
    lengths = []
    for r in runs:
        x = np.asarray(r, dtype=float)
        if len(x) < 2:
            continue
        d = x - x.mean()
        num += float(np.dot(d[:-1], d[1:]))
        den += float(np.dot(d, d))
        lengths.append(len(x))
    if den <= 0:
        return 0.0
    r, n = num / den, float(np.mean(lengths))
    return (n * r + 1) / (n - 3) if n > 3 else r


def summary(runs):
    """(mean, standard error of the mean, effective number of blocks, blocks, r1) of the ensemble's blocks pooled;
    the standard error is nan for fewer than two blocks. The spread is the pooled blocks' (within and between
    runs)."""
    x = np.concatenate([np.asarray(r, dtype=float) for r in runs]) if runs else np.zeros(0)
    n = len(x)
    if n == 0:
        return math.nan, math.nan, 0.0, 0, math.nan
    r1 = lag1(runs)
    n_eff = n * (1 - max(r1, 0.0)) / (1 + max(r1, 0.0))
    n_eff = min(float(n), max(n_eff, 2.0)) if n >= 2 else 1.0
    se = float(np.std(x, ddof=1)) / math.sqrt(n_eff) if n >= 2 else math.nan
    return float(x.mean()), se, n_eff, n, r1


def mean_ci(runs):
    """(mean, half-width of its 95 % interval, r1): Student's quantile on the effective number of blocks."""
    m, se, n_eff, n, r1 = summary(runs)
    if n < 2:
        return m, math.nan, r1
    return m, float(stats.t.ppf(0.5 + LEVEL / 2, n_eff - 1)) * se, r1


def change(runs_a, runs_b):
    """The change of ensemble a's block mean over b's, as a page's family lists it (stats/verdict.judged_change's
    tuple): (mean_a / mean_b - 1, its 95 % interval (lo, hi) or None, verdict, two-sided p-value of no change,
    blocks of a + blocks of b). Both means must be positive."""
    from . import verdict
    ma, sa, na, ka, _ = summary(runs_a)
    mb, sb, nb, kb, _ = summary(runs_b)
    if ka < 2 or kb < 2 or not (ma > 0 and mb > 0):
        return (ma / mb - 1 if mb else math.nan), None, "unresolved", 1.0, ka + kb
    d = math.log(ma / mb)
    va, vb = (sa / ma) ** 2, (sb / mb) ** 2  # variances of the log means
    se = math.sqrt(va + vb)
    if se == 0:  # no spread at all: the change is exact
        iv = (math.expm1(d), math.expm1(d))
        return math.expm1(d), iv, verdict.change_verdict(iv, None), (1.0 if d == 0 else 0.0), ka + kb
    df = (va + vb) ** 2 / (va ** 2 / (na - 1) + vb ** 2 / (nb - 1))
    h = float(stats.t.ppf(0.5 + LEVEL / 2, df)) * se
    iv = (math.expm1(d - h), math.expm1(d + h))
    p = float(2 * stats.t.sf(abs(d) / se, df))
    return math.expm1(d), iv, verdict.change_verdict(iv, None), p, ka + kb
