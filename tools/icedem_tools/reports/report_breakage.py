"""The report's sections on breakage: the mechanism of every break per f_ii against the
paper's Fig. 18, with pictures, and how close the floes near the structure came to breaking
(tools/icedem_tools/reports/report.py)."""
import collections
import os

import numpy as np

from ..sweeps import aggregate as agg
from .report_tables import BREAKABLE, FII, fmt, quantile

def breaks_of(records, scenario, fii=None):
    """Every break of a scenario's runs (at one f_ii, or all): [(run, event dict)], and the runs."""
    runs = [(r, rec) for r, rec in records.get(scenario, []) if fii is None or dict(r.grid).get(FII) == fii]
    return [(r, e) for r, rec in runs for e in rec.get("fracture_events", [])], runs

# Intervals of mechanism shares: breaks cluster in runs (a floe breaks at several joints
# in a step or two, and one run's jam breaks several floes), so the runs, not the breaks,
# are the independent samples; the shares' 95 % intervals resample the runs (a cluster
# bootstrap, seeded so that a report is reproducible).
BOOTSTRAP = 2000


def run_counts(runs, mechanisms):
    """Per run, its breaks by mechanism: an array (runs x mechanisms)."""
    rows = []
    for _, rec in runs:
        c = collections.Counter(e.get("mechanism_name", "") for e in rec.get("fracture_events", []))
        rows.append([c[m] for m in mechanisms])
    return np.array(rows, dtype=float).reshape(len(rows), len(mechanisms))


def resampled_shares(counts, picks):
    """The mechanism shares of all breaks of each resample of the runs (`picks`: resamples x
    runs, indices into counts' rows); rows whose resample has no break are NaN."""
    totals = counts[picks].sum(axis=1)  # resamples x mechanisms
    with np.errstate(invalid="ignore", divide="ignore"):
        return totals / totals.sum(axis=1, keepdims=True)


def bootstrap_shares(counts, rng):
    """BOOTSTRAP resampled share vectors (resampled_shares of runs drawn with replacement)."""
    n = counts.shape[0]
    return resampled_shares(counts, rng.integers(0, n, size=(BOOTSTRAP, n)))


def interval(samples):
    """The 2.5 and 97.5 percentiles of bootstrap samples, ignoring NaN: (lo, hi) or None."""
    ok = samples[~np.isnan(samples)]
    return (float(np.percentile(ok, 2.5)), float(np.percentile(ok, 97.5))) if ok.size else None


def shift_verdict(diff_interval, paper_sign):
    """Whether a difference of shares, with its interval, shows the paper's shift: 'appears'
    when the interval lies on the paper's side of 0, 'reversed' on the other, 'not resolved'."""
    if diff_interval is None:
        return "not resolved"
    lo, hi = diff_interval
    if paper_sign * lo > 0 and paper_sign * hi > 0:
        return "appears"
    if paper_sign * lo < 0 and paper_sign * hi < 0:
        return "reversed"
    return "not resolved"


def fig18_shift(low, high, mechanisms, rng):
    """The paper's Fig. 18 shift between f_ii 0.3 (`low`, per-run counts) and 0.7 (`high`):
    pressed under falls and on the slope rises. Returns {mechanism: (difference 0.7 - 0.3,
    its 95 % interval, verdict)} for those two."""
    a, b = bootstrap_shares(low, rng), bootstrap_shares(high, rng)
    out = {}
    for m, sign in (("pressed under", -1), ("on the slope", +1)):
        k = mechanisms.index(m)
        point = high[:, k].sum() / max(high.sum(), 1) - low[:, k].sum() / max(low.sum(), 1)
        iv = interval(b[:, k] - a[:, k])
        out[m] = (float(point), iv, shift_verdict(iv, sign))
    return out


def mechanism_names(records):
    """The mechanisms as the events name them (icedem declares them; every summary counts all)."""
    return [m.replace("_", " ") for m in agg.break_names(
        [rec["summary"] for v in records.values() for _, rec in v], "breaks_by_mechanism")]


def mechanism_table(records, s, mechanisms, rng):
    """Scenario `s`'s breaks by mechanism per f_ii, with intervals, and whether Fig. 18's shift
    appears: Markdown lines."""
    L = ["| f_ii | runs | breaks | per run | " + " | ".join(mechanisms) + " | median depth mm | "
         "median distance m | median force of other floes N |", "|---" * (7 + len(mechanisms)) + "|"]
    per_run = {}
    fiis = sorted({dict(r.grid).get(FII) for r, _ in records[s]} - {None})
    for fii in fiis:
        ev, runs = breaks_of(records, s, fii)
        n = len(ev)
        per_run[fii] = run_counts(runs, mechanisms)
        counts = per_run[fii].sum(axis=0)  # breaks by mechanism, over the runs
        boot = bootstrap_shares(per_run[fii], rng) if n else None

        def cell(k):
            if not n:
                return "0"
            iv = interval(boot[:, k])
            return (f"{counts[k]:.0f} ({100 * counts[k] / n:.0f} %" +
                    (f", {100 * iv[0]:.0f}-{100 * iv[1]:.0f}" if iv else "") + ")")
        cells = " | ".join(cell(k) for k in range(len(mechanisms)))
        depth = quantile([1e3 * e["depth"] for _, e in ev if "depth" in e], 0.5)
        dist = quantile([e["distance"] for _, e in ev if "distance" in e], 0.5)
        press = quantile([e["press_down"] + e["press_toward"] for _, e in ev if "press_down" in e], 0.5)
        L.append(f"| {fii:g} | {len(runs)} | {n} | {n / len(runs):.2f} | {cells} | {fmt(depth, '', 0)} | "
                 f"{fmt(dist, '', 2)} | {fmt(press, '', 1)} |")
    L.append("")
    low, high = per_run.get(0.3), per_run.get(0.7)
    if (low is not None and high is not None and low.sum() and high.sum()
            and "pressed under" in mechanisms and "on the slope" in mechanisms):
        shift = fig18_shift(low, high, mechanisms, rng)

        def said(m):
            d, iv, verdict = shift[m]
            return (f"{m} {100 * d:+.0f} points" + (f" ({100 * iv[0]:+.0f} to {100 * iv[1]:+.0f})" if iv else "")
                    + f": {verdict}")
        both = {shift[m][2] for m in shift}
        overall = ("**appears**" if both == {"appears"} else "**is reversed**" if "reversed" in both
                   and "appears" not in both else "**is not resolved**" if "appears" not in both
                   else "appears in part")
        L += ["Fig. 18 says: at f_ii 0.3 a submerged floe pressed against the cone by an approaching floe "
              "breaks; at 0.7 floes break sliding on the slope. From f_ii 0.3 to 0.7 here (shares of the "
              f"breaks, 95 % intervals over runs): {said('pressed under')}; {said('on the slope')}. "
              f"The paper's shift {overall}.", ""]
    return L


def mechanism_section(records, figs, report):
    """Breaks by mechanism per f_ii (dem/fracture/break_context.hpp), against the paper's Fig. 18."""
    L = ["## Breakage mechanisms", "",
         "Every break is recorded with what its floe was doing in the step of the break "
         "(`/fracture/events`; docs/model/breakage.md): whether an element of it touched the structure, the "
         "depth of the joint below the waterline, the contact force of other floes on it (down and "
         "towards the structure axis) and its distance from the structure. Classes: **on the slope** "
         "(touching the structure), **pressed under** (touching, submerged at least one thickness and "
         "pressed by another floe), **in the rubble** (not touching, submerged), **in the pack** (not "
         "touching, afloat). Summed over f_is and seeds; each share with its 95 % interval "
         "(a bootstrap over the runs: breaks cluster in runs, so the runs are the samples).", ""]
    rng = np.random.default_rng(18)
    mechanisms = mechanism_names(records)
    for s in BREAKABLE:
        if s not in records:
            continue
        L += [f"### {s}", ""] + mechanism_table(records, s, mechanisms, rng)
        pictures = [f for f in sorted(os.listdir(figs)) if f.startswith(f"break_{s}_")] if os.path.isdir(figs) else []
        if pictures:
            L += ["Just before a break, like the paper's Fig. 18 (scripts/break_pictures.py: side and top view, the "
                  "broken floe in red):", ""]
            L += [f"![{f}]({os.path.relpath(figs, os.path.dirname(report))}/{f})" for f in pictures] + [""]
    return L

def margin_section(records, figs, report):
    """How close the floes that reach the structure come to breaking: the largest joint load ratio
    per floe (summary near_structure_max_ratio), its distribution per scenario and f_ii."""
    rel = os.path.relpath(figs, os.path.dirname(report))
    L = ["## How close the ice comes to failure", "",
         "For every floe whose joints came within 1 m of the structure, the largest load / capacity "
         "ratio any of its joints reached under any criterion (eq. 1-3) during the run; 1 breaks the joint. "
         "A 0.6 m floe on water breaks when about 45 N of vertical load presses one edge "
         "(docs/model/breakage.md: a beam on an elastic foundation, 47 N at the first joint line of 0.15 m "
         "elements, 45 N at 0.20 m), far below the loads the cone carries; a distribution far below 1 "
         "means the cone's load does not reach the joints as edge bending.", ""]
    present = set(os.listdir(figs)) if os.path.isdir(figs) else set()
    for s in BREAKABLE:
        if s not in records:
            continue
        L += [f"### {s}", "", "| f_ii | runs | floes near the structure per run | median ratio | 90 % | 99 % | "
              "share ≥ 0.5 | share ≥ 1 (broke) |", "|---|---|---|---|---|---|---|---|"]
        fiis = sorted({dict(r.grid).get(FII) for r, _ in records[s]} - {None})
        for fii in fiis + [None]:
            runs = [rec for r, rec in records[s] if fii is None or dict(r.grid).get(FII) == fii]
            ratios = [x for rec in runs for x in rec["summary"].get("near_structure_max_ratio", [])]
            if not runs:
                continue
            n = len(ratios)
            L.append(f"| {'all' if fii is None else f'{fii:g}'} | {len(runs)} | {n / len(runs):.1f} | "
                     f"{fmt(quantile(ratios, 0.5), '', 2)} | {fmt(quantile(ratios, 0.9), '', 2)} | "
                     f"{fmt(quantile(ratios, 0.99), '', 2)} | "
                     f"{fmt(100 * sum(x >= 0.5 for x in ratios) / n if n else None, ' %', 0)} | "
                     f"{fmt(100 * sum(x >= 1 for x in ratios) / n if n else None, ' %', 0)} |")
        L.append("")
        if f"ratios_{s}.png" in present:
            L += [f"![ratios_{s}.png]({rel}/ratios_{s}.png)", ""]
    return L
