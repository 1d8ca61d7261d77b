"""The intervals of the project's statistics: a mean's Student interval over seeds, a share's exact
(Clopper-Pearson) interval, and the Gumbel fit of sample maxima."""
import math

import numpy as np
from scipy import stats

EULER_GAMMA = 0.5772156649


def mean_ci(values, level=0.95):
    """(mean, half-width of the two-sided confidence interval); half-width nan for n < 2."""
    x = np.asarray(values, dtype=float)
    n = len(x)
    if n == 0:
        return float("nan"), float("nan")
    m = float(np.mean(x))
    if n < 2:
        return m, float("nan")
    half = float(stats.t.ppf(0.5 + level / 2, n - 1) * np.std(x, ddof=1) / math.sqrt(n))
    return m, half


def share_text(k, n):
    """A share k/n with its Clopper-Pearson (exact) 95 % interval, as "k/n (lo-hi %)": the runs of a
    setting that reach a value (the tank's largest load), which few seeds cannot give Student's
    interval for."""
    ci = stats.binomtest(k, n).proportion_ci(confidence_level=0.95, method="exact")
    return f"{k}/{n} ({100 * ci.low:.0f}-{100 * ci.high:.0f} %)"


def gumbel_fit(maxima):
    """Moment fit of a Gumbel type I distribution to sample maxima (docs/model/validation_targets.md §7):
    beta = sqrt(6) s / pi, u = mean - 0.5772 beta. (nan, nan) for fewer than 2."""
    x = np.asarray(maxima, dtype=float)
    if len(x) < 2:
        return float("nan"), float("nan")
    beta = math.sqrt(6.0) * float(np.std(x, ddof=1)) / math.pi
    return float(np.mean(x)) - EULER_GAMMA * beta, beta
