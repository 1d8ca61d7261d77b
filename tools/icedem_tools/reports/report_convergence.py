"""Are the report's findings converged? Each headline number of the grid (the mean, p99 and
max load per case, the larger/smaller floe ratios, breaks per run, the shares of the break
mechanisms) at the default numerics and with a halved step or a tenfold tighter solve, over
the same seeds, with the change and its 95 % interval (tools/icedem_tools/reports/report.py).

The numbers are at the friction of the convergence runs: for the grid's models the paper's
reference friction (f_ii 0.5, f_is 0.2). Each seed is run at both numerics, so a change is taken seed by seed
(paired), which cancels most of the scatter between layouts:
  - a load, or a ratio of loads, changes by the mean over seeds of log(here / default),
    with Student's t interval, given back as a percentage;
  - breaks per run by the mean over seeds of (here - default), with Student's t interval;
  - a mechanism's share of the breaks (pooled over the seeds) by the difference of shares in
    points, with a bootstrap interval that resamples the seeds (the breaks of one run are
    not independent; report_breakage.py resamples runs for the same reason); with fewer than
    MIN_BOOTSTRAP_SEEDS seeds there are too few distinct resamples for an interval, and the
    share is unresolved.
Each change gets the verdict of the project's one rule (verdict.change_verdict, which
scripts/full_runs uses too): "within" when its interval lies inside the tolerance, **beyond**
when the whole interval lies outside it, **moves** when the interval excludes no change but
straddles the tolerance (a change the seeds cannot size against it), otherwise "unresolved"
(the seeds are too few to tell). The tolerances: the convergence study's for loads (5 % for
a mean, 10 % for a p99 and a max: sweeps/studies/convergence.toml), the max's 10 % of the default's breaks per run for breaks,
and 5 points for a mechanism's share: the Fig. 18 shift the report looks for is of the order
of 10 points, so an error of the numerics must stay well below that not to make or hide it.
"""
import math
import tomllib
import zlib

import numpy as np
from scipy import stats

from ..stats.intervals import mean_ci
from ..stats.verdict import change_verdict, family, log_change, paired_p
from ..runs import spec
from .report_breakage import BOOTSTRAP, interval, resampled_shares

with open(f"{spec.ROOT}/sweeps/studies/convergence.toml", "rb") as _f:
    _STUDY = tomllib.load(_f)["study"]
MEAN_TOLERANCE, PEAK_TOLERANCE = _STUDY["mean_tolerance"], _STUDY["peak_tolerance"]
SHARE_TOLERANCE = 0.05  # of the breaks: see above
# a bootstrap over fewer seeds has too few distinct resamples to give an interval (3 seeds: 10)
MIN_BOOTSTRAP_SEEDS = 5
RIGID_PAIR = ("large_rigid", "small_rigid")  # the paper's larger/smaller floe ratio
# the p99 (the load a run exceeds 1 % of its window) beside the max: a run's max is one event,
# which a change of the numerics can make or miss, while the p99 is the level of the peaks
LOADS = (("mean_fx_N", "mean load", MEAN_TOLERANCE), ("p99_fx_N", "p99 load", PEAK_TOLERANCE),
         ("max_fx_N", "max load", PEAK_TOLERANCE))


def verdict(iv, tolerance):
    """verdict.change_verdict's word for the report, a change emphasised (None: one seed)."""
    word = change_verdict(iv, tolerance)
    return f"**{word}**" if word in ("beyond", "moves") else word


def seeds_for_tolerance(iv, tolerance, n, log=False, student=True):
    """About how many seeds would narrow a change's interval to a half-width of the tolerance
    (the width a verdict "within" needs for a change near 0), from its interval over n seeds:
    the half-width shrinks as 1 / sqrt(seeds), and a Student's t interval (student) also as its
    quantile falls towards the normal one (at 3 seeds t is 4.30, against 1.96 for many). log:
    the interval and tolerance are fractions of a ratio, compared as logs. A string for the
    table, empty without an interval or tolerance."""
    if iv is None or not tolerance:
        return ""
    lo, hi = iv
    half = (math.log1p(hi) - math.log1p(lo)) / 2 if log else (hi - lo) / 2
    scale = (stats.norm.ppf(0.975) / stats.t.ppf(0.975, n - 1)) ** 2 if student and n > 1 else 1.0
    return str(max(n, math.ceil(scale * n * (half / (math.log1p(tolerance) if log else tolerance)) ** 2)))


def _signed(x, digits=0):
    """x with its sign, and no "-0" for a change that rounds to nothing."""
    s = f"{x:+.{digits}f}"
    return "+" + s[1:] if float(s) == 0 else s


def _pct(change):
    c, iv, _ = change
    return f"{_signed(100 * c)} %" + (f" ({_signed(100 * iv[0])} to {_signed(100 * iv[1])})" if iv else "")


def paired_load_change(got, model, numerics, key):
    """(seeds, log_change) of a case's load `key` from the default to `numerics`, over the
    seeds run at both; the change is None when no seed has both."""
    base, runs = got.get((model, "default"), {}), got.get((model, numerics), {})
    seeds = sorted(set(runs) & set(base))
    return seeds, log_change([(runs[s].get(key), base[s].get(key)) for s in seeds])


def load_pvalues(got, numerics_list):
    """The p-values of "no change" of load_rows' changes, in their order (stats.verdict.paired_p: the
    same log ratios the rows' intervals are made of)."""
    out = []
    for model in dict.fromkeys(m for m, _ in got):
        base = got.get((model, "default"), {})
        for key, _, _ in LOADS:
            for numerics in numerics_list:
                runs = got.get((model, numerics), {})
                pairs = [(runs[s].get(key), base[s].get(key)) for s in sorted(set(runs) & set(base))]
                pairs = [(a, b) for a, b in pairs if a and b and a > 0 and b > 0]
                if pairs:
                    out.append(paired_p([a for a, _ in pairs], [b for _, b in pairs]))
    return out


def load_rows(got, numerics_list):
    """Mean, p99 and max per case: (number, numerics, seeds, default, here, change, verdict,
    seeds for the tolerance) rows; the other *_rows give the same columns."""
    rows = []
    for model in dict.fromkeys(m for m, _ in got):
        base = got.get((model, "default"), {})
        for key, label, tol in LOADS:
            for numerics in numerics_list:
                seeds, ch = paired_load_change(got, model, numerics, key)
                if ch is None:
                    continue
                d = np.mean([base[s][key] for s in seeds])
                h = np.mean([got[(model, numerics)][s][key] for s in seeds])
                rows.append((f"{model} {label}", numerics, ch[2], f"{d:.1f} N", f"{h:.1f} N", _pct(ch),
                             verdict(ch[1], tol), seeds_for_tolerance(ch[1], tol, ch[2], log=True)))
    return rows


def max_bounds(got, numerics_list):
    """Per case, the largest mean of maxima the numerics could give at the 95 % level: the
    default's mean of maxima (over the case's default runs) times 1 + the upper end of the
    max's change, the highest over the numerics; with the numerics it comes from. The number
    to set beside a measured peak: a gap wider than it is the model's, not the solve's."""
    out = {}
    for model in dict.fromkeys(m for m, _ in got):
        base = got.get((model, "default"), {})
        peaks = [x["max_fx_N"] for x in base.values() if x.get("max_fx_N")]
        for numerics in numerics_list:
            _, ch = paired_load_change(got, model, numerics, "max_fx_N")
            if ch is None or ch[1] is None or not peaks:
                continue
            bound = float(np.mean(peaks)) * (1 + ch[1][1])
            if model not in out or bound > out[model][1]:
                out[model] = (float(np.mean(peaks)), bound, numerics)
    return out


def ratio_rows(got, numerics_list):
    """The larger/smaller rigid floes' ratios of the mean and max: per seed, the change of
    log(large) minus that of log(small), over the seeds both have at both numerics."""
    big, small = RIGID_PAIR
    rows = []
    for key, label, tol in (x for x in LOADS if x[0] != "p99_fx_N"):  # the paper's ratios
        for numerics in numerics_list:
            sets = [got.get((m, n), {}) for m in (big, small) for n in ("default", numerics)]
            seeds = sorted(set.intersection(*(set(s) for s in sets))) if all(sets) else []
            bd, bh, sd, sh = sets if seeds else ({},) * 4
            # log((bh / bd) / (sh / sd)) per seed: the pair (bh sd, bd sh)
            ch = log_change([(bh[s][key] * sd[s][key], bd[s][key] * sh[s][key]) for s in seeds
                             if all(x[s].get(key) for x in (bd, bh, sd, sh))])
            if ch is None:
                continue
            ratio = (lambda a, b: np.mean([a[s][key] for s in seeds]) / np.mean([b[s][key] for s in seeds]))
            rows.append((f"larger / smaller rigid floes, {label}", numerics, ch[2], f"{ratio(bd, sd):.2f}",
                         f"{ratio(bh, sh):.2f}", _pct(ch), verdict(ch[1], tol),
                         seeds_for_tolerance(ch[1], tol, ch[2], log=True)))
    return rows


def breaks_rows(got, numerics_list):
    """Breaks per run of the breakable cases: the mean over seeds of here - default."""
    rows = []
    for model in dict.fromkeys(m for m, _ in got):
        base = got.get((model, "default"), {})
        if not any(x.get("breaks", 0) for x in base.values()):
            continue
        for numerics in numerics_list:
            runs = got.get((model, numerics), {})
            seeds = sorted(set(runs) & set(base))
            if not seeds:
                continue
            diff = [runs[s].get("breaks", 0) - base[s].get("breaks", 0) for s in seeds]
            m, h = mean_ci(diff)
            iv = (m - h, m + h) if math.isfinite(h) else None
            d = np.mean([base[s].get("breaks", 0) for s in seeds])
            tol = PEAK_TOLERANCE * d  # breaks per run, absolute
            rows.append((f"{model} breaks per run", numerics, len(seeds), f"{d:.1f}", f"{d + m:.1f}",
                         _signed(m, 1) + (f" ({_signed(iv[0], 1)} to {_signed(iv[1], 1)})" if iv else ""),
                         verdict(iv, tol), seeds_for_tolerance(iv, tol, len(seeds))))
    return rows


def _counts(summaries, seeds, names):
    return np.array([[summaries[s].get("breaks_by_mechanism", {}).get(n, 0) for n in names] for s in seeds],
                    dtype=float).reshape(len(seeds), len(names))


def comparison_rng(model, numerics):
    """The bootstrap's generator of one comparison, seeded by its names: a report is
    reproducible, and a comparison's interval does not change when another is added (one
    generator shared down the rows moved every later row's interval by a few points)."""
    return np.random.default_rng(zlib.crc32(f"{model}+{numerics}".encode()))


def mechanism_rows(got, numerics_list):
    """Each mechanism's share of the breaks of a breakable case, pooled over the seeds both
    numerics have: the difference in points, its interval resampling the seeds (paired)."""
    rows = []
    for model in dict.fromkeys(m for m, _ in got):
        base = got.get((model, "default"), {})
        for numerics in numerics_list:
            runs = got.get((model, numerics), {})
            seeds = sorted(set(runs) & set(base))
            names = sorted({n for x in list(base.values()) + list(runs.values())
                            for n, c in x.get("breaks_by_mechanism", {}).items() if c})
            if not seeds or not names:
                continue
            a, b = _counts(base, seeds, names), _counts(runs, seeds, names)
            if not a.sum() or not b.sum():
                continue
            enough = len(seeds) >= MIN_BOOTSTRAP_SEEDS
            picks = comparison_rng(model, numerics).integers(0, len(seeds), size=(BOOTSTRAP, len(seeds)))  # paired
            diff = resampled_shares(b, picks) - resampled_shares(a, picks)
            for k, name in enumerate(names):
                iv = interval(diff[:, k]) if enough else None
                sa, sb = a[:, k].sum() / a.sum(), b[:, k].sum() / b.sum()
                rows.append((f"{model} share {name.replace('_', ' ')}", numerics, len(seeds),
                             f"{100 * sa:.0f} % of {a.sum():.0f}", f"{100 * sb:.0f} % of {b.sum():.0f}",
                             f"{_signed(100 * (sb - sa))} points" +
                             (f" ({_signed(100 * iv[0])} to {_signed(100 * iv[1])})" if iv else
                              f" (no interval: {len(seeds)} seeds)" if not enough else ""),
                             verdict(iv, SHARE_TOLERANCE),
                             seeds_for_tolerance(iv, SHARE_TOLERANCE, len(seeds), student=False)))
    return rows


def step_label(numerics, model, steps):
    """The numerics with the two Bullet steps its change compares, "dt_half (0.01 s against 0.02 s)";
    the name alone where the steps are not known (a model of the ratios: its two models' steps)."""
    here, default = steps.get((model, numerics)), steps.get((model, "default"))
    if here is None or default is None:
        return numerics
    return f"{numerics} ({here:g} s against {default:g} s)"


def headline_section(got, pooled=True, steps=None):
    """Markdown lines: the table of every headline number's change with the numerics, and a
    sentence listing those that move. `got`: {(model, numerics): {seed: summary}}; `pooled`:
    whether it holds the supplements' and the grid's runs too (the report's), or one sweep's;
    `steps`: {(model, numerics): Bullet step s}, to label each change with the steps it compares."""
    numerics_list = sorted({n for _, n in got} - {"default"})
    rows = (load_rows(got, numerics_list) + ratio_rows(got, numerics_list) + breaks_rows(got, numerics_list)
            + mechanism_rows(got, numerics_list))
    if not rows:
        return []
    if steps:
        models = sorted({m for m, _ in got}, key=len, reverse=True)
        def model_of(number):
            return next((m for m in models if number.startswith(m + " ")), None)
        rows = [(r[0], step_label(r[1], model_of(r[0]), steps)) + tuple(r[2:]) for r in rows]
    L = ["### Are the findings converged?", "",
         "Each headline number at the friction of the convergence runs (the grid's models: the reference "
         "f_ii 0.5, f_is 0.2) at the default numerics "
         "and with other numerics, over the seeds run at both; the change is taken seed by seed, with its "
         "95 % interval (loads and ratios: Student's t on the log of each seed's ratio; breaks: on each "
         f"seed's difference; mechanism shares: the seeds resampled, given {MIN_BOOTSTRAP_SEEDS} seeds or more). "
         "A number is within its tolerance "
         f"({100 * MEAN_TOLERANCE:.0f} % for a mean, {100 * PEAK_TOLERANCE:.0f} % for a p99, a max and breaks "
         f"per run, {100 * SHARE_TOLERANCE:.0f} points for a mechanism's share, well below the Fig. 18 shift "
         "looked for) when its whole interval is, **beyond** it when its whole interval lies outside, "
         "**moves** when its interval excludes no change but straddles the tolerance (a real change the seeds "
         "cannot size against it), and is unresolved otherwise."
         + (" Runs of the supplements at these numerics, and the grid's own runs at this friction (the default "
            "numerics), count here too." if pooled else ""), "",
         "The last column estimates how many seeds would narrow the interval to a half-width of the "
         "tolerance (the half-width shrinks as one over the root of the seeds, and Student's t towards the "
         "normal quantile): the seeds a verdict needs "
         "where the runs' scatter, not the numerics, is what leaves a number unresolved.", "",
         "| number | numerics | seeds | default | here | change (95 % interval) | verdict | seeds for ± tolerance |",
         "|---|---|---|---|---|---|---|---|"]
    L += [f"| {' | '.join(str(c) for c in r)} |" for r in rows]
    beyond = [f"{r[0]} with {r[1]} ({r[5]})" for r in rows if r[6] == "**beyond**"]
    moved = [f"{r[0]} with {r[1]} ({r[5]})" for r in rows if r[6] == "**moves**"]
    within = sum(1 for r in rows if r[6] == "within")
    L += [""]
    ps = load_pvalues(got, numerics_list)
    if ps:
        holm, bh = family(ps)
        L += [f"Of its {len(ps)} load changes, {sum(p < 0.05 for p in ps)} exclude no change at 95 % each (about "
              f"{0.05 * len(ps):.1f} would by chance if nothing changed); {sum(holm)} hold under Holm's correction over "
              f"the {len(ps)}, {sum(bh)} under Benjamini-Hochberg's.", ""]
    if beyond:
        L += [f"Beyond tolerance with the numerics: {'; '.join(beyond)}."]
    if moved:
        L += [f"Moving with the numerics, by an amount the seeds cannot size against the tolerance: "
              f"{'; '.join(moved)}."]
    if not beyond and not moved:
        L += ["No headline number is resolved to move with the numerics."]
    L += [f"Of the {len(rows)} numbers, within tolerance: {within}; unresolved by these seeds: "
          f"{len(rows) - within - len(beyond) - len(moved)}."]
    bounds = max_bounds(got, numerics_list)
    if bounds:
        L += ["", "The largest mean of maxima the numerics could give, at the 95 % level (the default's over "
              "all its runs here, times the upper end of its change's interval; the numerics giving the "
              "highest): " + "; ".join(f"{m} {d:.1f} N → at most {b:.1f} N ({n})" for m, (d, b, n) in bounds.items())
              + ". A measured peak above this bound is beyond what the solve's error can explain; where a "
              "case's max moves with the numerics, the bound holds for these numerics only (a still finer "
              "solve may move it further)."]
    L += [""]
    return L
