"""The project's one verdict on a change: a number of a setting against the reference's, with its 95 %
interval over seeds (paired: the log ratio, chosen by its coverage on the records,
docs/model/estimators.md), judged against a tolerance (change_verdict), per criterion over the seeds
both ran (judge); breaks compared as Poisson rates (breaks_agree); a change as a log ratio from
pairs that may hold gaps (log_change)."""
import math

import numpy as np
from scipy import stats

from . import paired_change


def change_verdict(interval, tolerance):
    """The project's one rule for a change of a number with its 95 % interval (lo, hi),
    against a tolerance (the same units; None: no tolerance): "within" when the whole interval
    lies inside +-tolerance, "beyond" when the whole interval lies outside it, "moves" when it
    excludes no change but the seeds cannot tell its size against the tolerance (it straddles
    a bound), "unresolved" otherwise (or without an interval). scripts/full_runs accepts a
    setting on it and the paper report judges its findings' convergence on it."""
    if interval is None:
        return "unresolved"
    lo, hi = interval
    if tolerance is not None and -tolerance <= lo and hi <= tolerance:
        return "within"
    if tolerance is not None and (lo > tolerance or hi < -tolerance):
        return "beyond"
    return "moves" if lo > 0 or hi < 0 else "unresolved"


def breaks_agree(e, ref):
    """Whether a setting's floes break as often as the reference's ("floes_broken" per run in
    both ensembles): the exact test of two Poisson rates (given the total count, the setting's
    share is binomial with its share of the runs), two-sided at 5 %. Floes, not joints: joints
    break in clusters (a floe at several in a step or two), the floes are the independent events.
    At the paper's strength a floe breaks in one run of several, where Student's interval of the
    reference would be [0, 0] after five runs without one."""
    from scipy.stats import binomtest
    k1, k2 = round(e["floes_broken"][0] * e["n"]), round(ref["floes_broken"][0] * ref["n"])
    if k1 + k2 == 0:
        return True
    return binomtest(k1, k1 + k2, e["n"] / (e["n"] + ref["n"])).pvalue >= 0.05


def paired(a, b):
    """The change of `a` over `b` (arrays over the same seeds) and its 95 % interval (None for one
    seed): the log ratio (paired_change.log_ratio), the estimator whose interval covers best on the
    records (docs/model/estimators.md); where a value is not positive (a share that is 0 in a run),
    the ratio of means with the delta method's interval, which takes zeros."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    estimator = paired_change.log_ratio if (a > 0).all() and (b > 0).all() else paired_change.ratio_delta
    if len(a) < 2:
        d = float(a.mean() / b.mean() - 1)
        return d, None
    d, lo, hi = estimator(a, b)
    return float(d), (float(lo), float(hi))


def paired_values(e, ref, k):
    """(a, b): criterion `k` of two ensembles over the seeds both ran, in the same order; None where
    one has no such criterion, they share no seed, or the reference's mean is 0."""
    common = [x for x in e["seeds"] if x in ref["seeds"]]
    if k not in e["runs"] or k not in ref["runs"] or not common:
        return None
    a = np.array([e["runs"][k][e["seeds"].index(x)] for x in common])
    b = np.array([ref["runs"][k][ref["seeds"].index(x)] for x in common])
    return None if not b.mean() else (a, b)


def paired_p(a, b):
    """The two-sided p-value of "no change" for the pairs `paired` judges, by the same estimator:
    Student's t on the seeds' log ratios (on the delta method's residuals where a value is not
    positive). 1 for fewer than two seeds or no change at all."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    n = len(a)
    if n < 2:
        return 1.0
    if (a > 0).all() and (b > 0).all():
        d = np.log(a / b)
        m, s = d.mean(), d.std(ddof=1) / math.sqrt(n)
    else:
        r = a.mean() / b.mean()
        m, s = r - 1, (a - r * b).std(ddof=1) / math.sqrt(n) / b.mean()
    if s == 0:
        return 1.0 if m == 0 else 0.0
    return float(2 * stats.t.sf(abs(m / s), n - 1))


def family(pvalues, level=0.05):
    """A page's family of changes judged at 95 % each, corrected for their number: (which hold under
    Holm's correction, controlling the chance of any false "moves" at `level`; which under
    Benjamini-Hochberg's, the expected share of false ones among those that hold), as boolean lists."""
    from statsmodels.stats.multitest import multipletests
    if not len(pvalues):
        return [], []
    holm = multipletests(pvalues, alpha=level, method="holm")[0]
    bh = multipletests(pvalues, alpha=level, method="fdr_bh")[0]
    return [bool(x) for x in holm], [bool(x) for x in bh]


def judged_change(a, b):
    """The change of `a` over `b` (values over the same seeds, two or more) as a page's family lists it:
    (change, 95 % interval, verdict without a tolerance, p-value of no change, seeds)."""
    d, iv = paired(a, b)
    return d, iv, change_verdict(iv, None), paired_p(a, b), len(a)


def family_text(changes, name):
    """The multiplicity sentence of a page's family of changes ({key: judged_change's tuple}), each named
    by name(key): how many move at 95 % each, and which hold under Holm's and Benjamini-Hochberg's
    corrections (family)."""
    keys = sorted(changes)
    holm, bh = family([changes[k][3] for k in keys])
    raw = [k for k in keys if changes[k][2] == "moves"]
    return (f"{len(keys)} changes judged at 95 % each; {len(raw)} move ({', '.join(map(name, raw)) or 'none'}); "
            f"under Holm's correction for the family {sum(holm)} hold "
            f"({', '.join(name(k) for k, h in zip(keys, holm) if h) or 'none'}), under Benjamini-Hochberg's {sum(bh)}.")


def judge(e, ref, tolerances):
    """A setting's ensemble against the reference's, by the project's one rule: per criterion of
    `tolerances` ({name: bound on the relative change}) that both have, the relative change over
    the seeds both ran, paired seed by seed (the same seed is the same floe layout, so a layout's
    own effect drops out; `paired`), with its 95 % interval and change_verdict's verdict (with one
    common seed its point estimate alone is judged); whether floes break as often (breaks_agree,
    where both count them); overall "yes" when every criterion is within and the floes agree, "no"
    when one is beyond or they do not, else "undecided".
    Returns (changes {name: (change, (lo, hi) or None, verdict)}, floes agree, overall, seeds paired)."""
    common = [x for x in e["seeds"] if x in ref["seeds"]]
    out = {}
    for k, bound in tolerances.items():
        pairs = paired_values(e, ref, k)
        if pairs is None:
            continue
        d, iv = paired(*pairs)
        out[k] = (d, iv, change_verdict(iv if iv else (d, d), bound))
    floes_ok = breaks_agree(e, ref) if "floes_broken" in e and "floes_broken" in ref else True
    verdicts = [v for _, _, v in out.values()]
    overall = ("no" if "beyond" in verdicts or not floes_ok
               else "yes" if verdicts and all(v == "within" for v in verdicts) else "undecided")
    return out, floes_ok, overall, len(common)


def change_text(change, digits=1):
    """A change of judge's as the pages print it: "+12.3 % (+4.0 to +21.2) (moves)"."""
    d, iv, word = change
    interval = f" ({100 * iv[0]:+.{digits}f} to {100 * iv[1]:+.{digits}f})" if iv else ""
    return f"{100 * d:+.{digits}f} %{interval} ({word})"


def log_change(pairs):
    """(change, (lo, hi), n): paired_change's log ratio of the pairs (here, default) whose values are
    both positive (a seed without one left out), as fractions; the interval is None for one seed."""
    kept = [(a, b) for a, b in pairs if a and b and a > 0 and b > 0]
    if not kept:
        return None
    if len(kept) < 2:
        return math.expm1(math.log(kept[0][0] / kept[0][1])), None, 1
    change, lo, hi = paired_change.log_ratio([a for a, _ in kept], [b for _, b in kept])
    return float(change), (float(lo), float(hi)), len(kept)
