"""Which interval the project's verdicts should use: the coverage of each estimator of a paired change
(stats/paired_change.py) measured on the committed records of the model-error budget.

    scripts/estimator_coverage [--samples S] [--seed K] [--report PAGE]

Every change the budget judges (a variant against the run it is paired with, per criterion: the mean
load, the p99, the mean of the maxima, the maxima at 5 Hz) is a set of n pairs (a_i, b_i), one per seed.
Two worlds are made from each set, in which the true change is known:
- resampled: the n pairs themselves are the population; a sample is n pairs drawn from them with
  replacement (what the seeds could have been, if they were these);
- lognormal: the pairs' logarithms fitted by a bivariate normal (their means and covariance); a sample
  is n pairs drawn from it (a smooth population with the records' scatter and correlation).
In each, S samples are drawn, each estimator's 95 % interval is made from each, and its coverage is the
share of the intervals that hold the world's true change: the ratio of the population means for the
ratio estimators and the relative-to-mean one, the ratio of geometric means for the log ratio. An
interval that covers less than 95 % makes verdicts ("beyond", "moves") the seeds do not support.

The page says which estimator covers best over the sets and how the verdicts on the records differ
between estimators. Only the kept records are read (docs/model/load_budget_records)."""
import argparse
import datetime
import json
import os
import sys
import tomllib

import numpy as np

from ..runs import output_guard, spec
from ..reports import spans
from ..runs.spec import ROOT
from ..stats import paired_change
from ..stats.verdict import change_verdict
from .budget import STUDY_FILE, TOLERANCE

BEGIN, END = "<!-- estimator coverage: scripts/estimator_coverage writes below -->", "<!-- end of the coverage -->"
CRITERIA = {"mean": ("mean_fx_N", None), "p99": ("p99_fx_N", "window"), "max": ("max_fx_N", None),
            "max5": ("5", "lowpass")}


def value(record, criterion):
    key, where = CRITERIA[criterion]
    s, w = record.get("summary", {}), record.get("window", {})
    if where is None:
        return s.get(key)
    if where == "window":
        return w.get(key)
    return w.get("max_lowpass_fx_N", {}).get(key)


def paired_sets():
    """[(scenario, variant, against, criterion, a, b)]: each change the budget judges, from the kept
    records, over the seeds both have."""
    _, runs = spec.load(STUDY_FILE)
    study = tomllib.load(open(STUDY_FILE, "rb"))["study"]
    records = {}
    for r in runs:
        if r.record_file and os.path.isfile(r.record_file):
            with open(r.record_file) as f:
                rec = json.load(f)
            if rec.get("summary", {}).get("status") == "complete":
                records[(r.scenario, r.variant, r.seed)] = rec
    out = []
    for m in dict.fromkeys(r.scenario for r in runs):
        variants = list(dict.fromkeys(r.variant for r in runs if r.scenario == m))
        seeds = sorted({r.seed for r in runs if r.scenario == m})
        for v in variants:
            against = study.get("paired_with", {}).get(v, study["baseline"])
            if v == study["baseline"]:
                continue
            for c in CRITERIA:
                pairs = [(value(records[(m, v, s)], c), value(records[(m, against, s)], c)) for s in seeds
                         if (m, v, s) in records and (m, against, s) in records]
                pairs = [(x, y) for x, y in pairs if x is not None and y is not None and x > 0 and y > 0]
                if len(pairs) >= 3:
                    a, b = np.array(pairs).T
                    out.append((m, v, against, c, a, b))
    return out


def coverage(a, b, samples, rng):
    """{world: {estimator: (coverage, mean half-width)}} for one set of pairs."""
    n = len(a)
    la, lb = np.log(a), np.log(b)
    mu = np.array([la.mean(), lb.mean()])
    cov = np.cov(np.vstack([la, lb]))
    worlds = {}
    idx = rng.integers(0, n, size=(samples, n))
    worlds["resampled"] = (a[idx], b[idx], a.mean() / b.mean() - 1, np.expm1(np.mean(la - lb)))
    z = rng.multivariate_normal(mu, cov, size=(samples, n), check_valid="ignore")
    ratio = np.exp(mu[0] + cov[0, 0] / 2 - mu[1] - cov[1, 1] / 2) - 1
    worlds["lognormal"] = (np.exp(z[..., 0]), np.exp(z[..., 1]), ratio, np.expm1(mu[0] - mu[1]))
    out = {}
    for world, (sa, sb, ratio_true, geometric_true) in worlds.items():
        out[world] = {}
        for name, estimator in paired_change.ESTIMATORS.items():
            if estimator is paired_change.ratio_bootstrap:
                _, lo, hi = estimator(sa, sb, rng, resamples=400)
            else:
                with np.errstate(invalid="ignore", divide="ignore"):
                    _, lo, hi = estimator(sa, sb)
            truth = geometric_true if estimator is paired_change.log_ratio else ratio_true
            ok = np.isfinite(lo) & np.isfinite(hi)
            out[world][name] = (float(np.mean(ok & (lo <= truth) & (truth <= hi))),
                                float(np.nanmean((hi - lo) / 2)))
    return out


def verdicts(sets, rng):
    """{estimator: [verdict per set]} on the records themselves."""
    out = {}
    for name, estimator in paired_change.ESTIMATORS.items():
        words = []
        for m, v, against, c, a, b in sets:
            if estimator is paired_change.ratio_bootstrap:
                _, lo, hi = estimator(a, b, rng, resamples=4000)
            else:
                _, lo, hi = estimator(a, b)
            words.append(change_verdict((float(lo), float(hi)), TOLERANCE[c]))
        out[name] = words
    return out


def page(sets, results, words, samples, seed):
    names = list(paired_change.ESTIMATORS)
    lines = [BEGIN, "", f"Made {datetime.date.today().isoformat()} by `scripts/estimator_coverage --samples {samples} "
             f"--seed {seed}` from the kept records of `{os.path.relpath(STUDY_FILE, ROOT)}`: {len(sets)} paired "
             f"changes (variant against the run it is paired with, per criterion), "
             f"{min(len(s[4]) for s in sets)}-{max(len(s[4]) for s in sets)} seeds each; {samples} samples per "
             "change and world.", ""]
    lines += ["| estimator | world | mean coverage | lowest decile | changes below 90 % | below 80 % | "
              "mean half-width, % |", "|---|---|---|---|---|---|---|"]
    summary = {}
    for name in names:
        for world in ("resampled", "lognormal"):
            cov = np.array([r[world][name][0] for r in results])
            hw = np.array([r[world][name][1] for r in results])
            summary[(name, world)] = cov.mean()
            lines.append(f"| {name} | {world} | {100 * cov.mean():.1f} % | {100 * np.percentile(cov, 10):.1f} % | "
                         f"{int((cov < 0.90).sum())} of {len(cov)} | {int((cov < 0.80).sum())} | "
                         f"{100 * np.nanmean(hw):.1f} |")
    lines += ["", "Verdicts on the records themselves (the budget's tolerances: 5 % for the mean, 10 % for the p99 "
              "and the maxima):", "", "| estimator | within | beyond | moves | unresolved | differ from the first |",
              "|---|---|---|---|---|---|"]
    first = words[names[0]]
    for name in names:
        w = words[name]
        lines.append(f"| {name} | " + " | ".join(str(w.count(k)) for k in ("within", "beyond", "moves", "unresolved"))
                     + f" | {sum(x != y for x, y in zip(w, first))} |")
    # the choice: the estimator whose worse world covers most (ties: the simpler, listed first)
    best = max(names, key=lambda n: min(summary[(n, "resampled")], summary[(n, "lognormal")]))
    lines += ["", f"Best covered in its worse world: **{best}** "
              f"({100 * min(summary[(best, 'resampled')], summary[(best, 'lognormal')]):.1f} %).", "", END]
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--samples", type=int, default=1000, help="samples per change and world")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--report", help="the page (default: docs/model/estimators.md)")
    a = ap.parse_args(argv)
    path = a.report or os.path.join(ROOT, "docs", "model", "estimators.md")
    output_guard.guard([("--report", path, output_guard.FILE)], [STUDY_FILE])
    rng = np.random.default_rng(a.seed)
    sets = paired_sets()
    if not sets:
        sys.exit("scripts/estimator_coverage: no kept records of the budget")
    results = [coverage(s[4], s[5], a.samples, rng) for s in sets]
    words = verdicts(sets, rng)
    text = page(sets, results, words, a.samples, a.seed)
    print(text)
    old = open(path).read() if os.path.isfile(path) else ""
    output_guard.write_text(path, spans.replace_block(old, text, BEGIN, END))
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
