"""Estimators of the relative change of a number between two settings run on the same seeds (pairs
(a_i, b_i): the setting's run and the reference's run of seed i, the same floe layout), each with its
95 % interval over the seeds. Each takes arrays of shape (..., n): the last axis is the seeds, so that
a coverage study (studies/estimator_coverage.py) evaluates thousands of samples at once.

- relative_to_mean: mean of (a_i - b_i) / mean(b), Student's interval; the reference's mean taken as
  exact (its own scatter left out of the interval);
- log_ratio: mean of log(a_i / b_i), Student's interval, as exp(.) - 1: the change of the geometric
  mean, a ratio the reference's scatter enters per seed;
- ratio_delta: mean(a) / mean(b) - 1, the ratio of means, with the delta method's interval
  (Student's quantile on the residuals a_i - R b_i), which carries the denominator's scatter;
- ratio_bootstrap: the same ratio with the percentile interval of a paired bootstrap over seeds.

Each returns (change, lo, hi) as fractions (0.1: +10 %)."""
import numpy as np
from scipy import stats

LEVEL = 0.95


def _t(n):
    return stats.t.ppf(0.5 + LEVEL / 2, n - 1)


def relative_to_mean(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    n = a.shape[-1]
    d = (a - b) / b.mean(axis=-1, keepdims=True)
    m = d.mean(axis=-1)
    h = _t(n) * d.std(axis=-1, ddof=1) / np.sqrt(n)
    return m, m - h, m + h


def log_ratio(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    n = a.shape[-1]
    d = np.log(a / b)
    m = d.mean(axis=-1)
    h = _t(n) * d.std(axis=-1, ddof=1) / np.sqrt(n)
    return np.expm1(m), np.expm1(m - h), np.expm1(m + h)


def ratio_delta(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    n = a.shape[-1]
    mb = b.mean(axis=-1)
    r = a.mean(axis=-1) / mb
    resid = a - r[..., None] * b
    h = _t(n) * resid.std(axis=-1, ddof=1) / np.sqrt(n) / mb
    return r - 1, r - 1 - h, r - 1 + h


def ratio_bootstrap(a, b, rng, resamples=1000):
    a, b = np.asarray(a, float), np.asarray(b, float)
    n = a.shape[-1]
    r = a.mean(axis=-1) / b.mean(axis=-1)
    idx = rng.integers(0, n, size=(resamples, n))
    rb = a[..., idx].mean(axis=-1) / b[..., idx].mean(axis=-1)  # (..., resamples)
    lo, hi = np.percentile(rb, [50 * (1 - LEVEL), 50 * (1 + LEVEL)], axis=-1)
    return r - 1, lo - 1, hi - 1


ESTIMATORS = {"relative to the reference's mean": relative_to_mean, "log ratio": log_ratio,
              "ratio of means, delta method": ratio_delta, "ratio of means, paired bootstrap": ratio_bootstrap}
