"""The paper-comparison report of a friction sweep (issue 5): a Markdown file
that sets the sweep's results beside the seed paper's findings, says where they
disagree, and shows the figures of scripts/sweep_figures.py. Run
`scripts/sweep aggregate` and `scripts/sweep_figures.py` first (or
`scripts/reproduce_paper`, which runs the whole chain).

    scripts/report SWEEP.toml [--out DIR] [--report FILE] [--figures DIR] [--command TEXT]

Scenario names it looks for (as in sweeps/paper_grid.toml): small_rigid,
large_rigid, large_breakable_015, large_breakable_020; missing ones are
reported as n/a. Default report: OUT/report.md; figures: OUT/figures.
"""
import argparse
import collections
import csv
import math
import os
import sys
import tomllib

import numpy as np

from . import aggregate as agg, execute, spec

FII, FIS = "friction.ice_ice", "friction.ice_structure"
BREAKABLE = ("large_breakable_015", "large_breakable_020")
# The paper's findings this report checks, as data (sweeps/paper_targets.toml): what the paper
# says, the number, and when icedem agrees
with open(os.path.join(spec.ROOT, "sweeps", "paper_targets.toml"), "rb") as _f:
    TARGETS = tomllib.load(_f)


def agrees(key, x):
    """Whether x meets the paper's target `key` (None if x is None): within value +- tolerance
    (absolute or relative), inside range, above or below."""
    if x is None:
        return None
    t = TARGETS[key]
    if "range" in t:
        return t["range"][0] <= x <= t["range"][1]
    if "above" in t:
        return x > t["above"]
    if "below" in t:
        return x < t["below"]
    tolerance = t["tolerance"] if "tolerance" in t else t["tolerance_rel"] * abs(t["value"])
    return abs(x - t["value"]) <= tolerance


# What is known about each kind of disagreement, and where it was measured.
CAUSES = {
    "peak_interval": "peaks are detected with a prominence of one standard deviation; floe passages "
                     "that make no prominent peak are not counted, which lengthens the mean interval "
                     "(the spectral peak sits at L/v)",
    "max": "the section \"Convergence of the grid's loads\" below measures how far the max moves when the step "
           "is halved and the solve tightened tenfold; a max that does not move there is the model's, not the "
           "numerics' (the paper does not give its solver settings){paper_resolution}",
    "breakable_low": "the breakable floes load the cone less than the rigid ones at the same friction "
                     "(see the breakable / rigid rows)",
    "compliance": "a lattice's joints are compliant and its elements ride the slope separately; "
                  "the supplement `paper_joint_stiffness`, when given, compares stiff and calibrated joints"
                  "{paper_joint_stiffness}",
    "few_breaks": "the sections \"Breakage mechanisms\" and \"How close the ice comes to failure\" below give "
                  "the breaks per run and the share of the floes near the structure whose joints reached their "
                  "capacity: a floe breaks at about 45 N of edge load (docs/model/breakage.md), so the cone's load stays "
                  "near what breaking allows only if floes break as they arrive",
}
# A cause's {supplement name} is filled with that supplement's ratios when it is in the report.
# Figures in the paper's order, with the paper's figure numbers.
FIGURES = (
    ("loads_vs_fis", "Average and max surge load against f_is, one line per f_ii (paper Figs. 8, 12, 16)"),
    ("history", "Surge load time histories at f_ii = 0.5, first seed (paper Figs. 9, 13, 17)"),
    ("spectrum", "Ensemble load spectra at f_ii = 0.5 (the paper's peak interval; not a paper figure)"),
    ("topview", "Floes and cone from above: start, largest load, end (paper Figs. 4, 11, 14, 18)"),
    ("frontview", "Front view of floe trajectories near the cone (paper Fig. 10)"),
)


def read_rows(out):
    with open(os.path.join(out, "results.csv")) as f:
        return list(csv.DictReader(f))


def num(row, key):
    try:
        v = float(row[key])
        return v if math.isfinite(v) else None
    except (TypeError, KeyError, ValueError):
        return None


def fmt(v, unit="", digits=1):
    return "n/a" if v is None else f"{v:.{digits}f}{unit}"


def ci(row, key):
    m, h = num(row, key), num(row, key + "_ci95")
    if m is None:
        return "n/a"
    return f"{m:.1f} ± {h:.1f}" if h is not None else f"{m:.1f}"


def pick(rows, scenario, fii=0.5, fis=0.2):
    """The row of a scenario at the given friction (or its only row); None if absent."""
    cand = [r for r in rows if r["scenario"] == scenario]
    exact = [r for r in cand if (not r.get(FII) or float(r[FII]) == fii) and (not r.get(FIS) or float(r[FIS]) == fis)]
    return (exact or cand or [None])[0]


def grid_mean(rows, scenario, key, **fixed):
    """Mean of `key` over a scenario's rows matching fixed grid values (e.g. fis=0.1)."""
    names = {"fii": FII, "fis": FIS}
    sel = [r for r in rows if r["scenario"] == scenario
           and all(r.get(names[k]) and float(r[names[k]]) == v for k, v in fixed.items())]
    vals = [num(r, key) for r in sel]
    vals = [v for v in vals if v is not None]
    return sum(vals) / len(vals) if vals else None


def grid_values(rows, scenario, key):
    return sorted({float(r[key]) for r in rows if r["scenario"] == scenario and r.get(key)})


def trend(rows, scenario, key, axis):
    """Change of `key` (averaged over the other friction) from the lowest to the highest value
    of `axis`, and whether it rises at every step between."""
    vals = grid_values(rows, scenario, axis)
    if len(vals) < 2:
        return None, None
    name = "fis" if axis == FIS else "fii"
    means = [grid_mean(rows, scenario, key, **{name: v}) for v in vals]
    if any(m is None for m in means):
        return None, None
    return means[-1] - means[0], all(b > a for a, b in zip(means, means[1:]))


def run_records(runs, out):
    """{scenario: [(run, record dict)]} of the finished runs (tools/icedem_tools/aggregate.py)."""
    res = {}
    for r in runs:
        if execute.status(r, out).state == "done":
            res.setdefault(r.scenario, []).append((r, agg.load_record(r, out)))
    return res


def run_summaries(records):
    """{scenario: [(run, summary dict)]} from run_records()."""
    return {s: [(r, rec["summary"]) for r, rec in v] for s, v in records.items()}


def joblog_span(out):
    """(busy wall span s, summed job time s, jobs) of the GNU parallel job log: the wall
    time during which the engine ran jobs, over every logged session."""
    path = os.path.join(out, "joblog.txt")
    if not os.path.isfile(path):
        return None
    spans = []
    with open(path) as f:
        for line in f:
            parts = line.split("\t")
            if len(parts) < 7 or parts[0] == "Seq":
                continue
            try:
                start, dur = float(parts[2]), float(parts[3])
            except ValueError:
                continue
            spans.append((start, start + dur))
    if not spans:
        return None
    spans.sort()
    busy, cur_s, cur_e = 0.0, spans[0][0], spans[0][1]
    for s, e in spans[1:]:
        if s > cur_e:
            busy += cur_e - cur_s
            cur_s, cur_e = s, e
        else:
            cur_e = max(cur_e, e)
    busy += cur_e - cur_s
    return busy, sum(e - s for s, e in spans), len(spans)


def findings(rows, summaries, modes):
    """The paper's findings checked on one grid: [(finding, paper, icedem, agrees or None, cause
    key)]. summaries: {scenario: [(run, summary)]}, or None for a grid known only by its
    results.csv (then the per-run counts come from the table's break columns, or are n/a)."""
    out = []

    def row(finding, paper, ours, ok, cause=None):
        out.append((finding, paper, ours, ok, cause))

    small, large = pick(rows, "small_rigid"), pick(rows, "large_rigid")
    breakable = {s: pick(rows, s) for s in BREAKABLE}
    sp = num(small, "peak_interval_s") if small else None
    spec_p = num(small, "spectral_peak_period_s") if small else None
    row("smaller floes: interval of load peaks (±1 s)", TARGETS["small_peak_interval"]["paper"],
        f"{fmt(sp, ' s', 2)}; spectral peak {fmt(spec_p, ' s', 2)}", agrees("small_peak_interval", sp), "peak_interval")
    lp = num(large, "peak_interval_s") if large else None
    lsp = num(large, "spectral_peak_period_s") if large else None
    row("larger floes: interval of load peaks", "not given (L/v = 8.57 s)",
        f"{fmt(lp, ' s', 2)}; spectral peak {fmt(lsp, ' s', 2)}", None)
    for key, label, target in (("mean_fx_N", "mean", "ratio_mean_large_small"),
                               ("max_fx_N", "max", "ratio_max_large_small")):
        for s, lab in (("large_rigid", "rigid"), ("large_breakable_015", "breakable 0.15 m")):
            lr = pick(rows, s)
            a, b = (num(lr, key) if lr else None), (num(small, key) if small else None)
            r = a / b if a is not None and b else None
            row(f"ratio larger ({lab}) / smaller floes, {label} load (±0.3)", TARGETS[target]["paper"],
                fmt(r, "", 2), agrees(target, r), "breakable_low" if "breakable" in s else "max")
    smax = num(small, "max_fx_N") if small else None
    row("smaller floes: max load (±20 %)", TARGETS["small_max"]["paper"], fmt(smax, " N"), agrees("small_max", smax),
        "max")
    lo, hi = pick(rows, "small_rigid", 0.3, 0.1), pick(rows, "small_rigid", 0.5, 0.3)
    a, b = (num(lo, "mean_fx_N") if lo else None), (num(hi, "mean_fx_N") if hi else None)
    rise = b - a if a is not None and b is not None else None
    row("smaller floes: mean load rise with friction (half to twice 10 N)", TARGETS["small_friction_rise"]["paper"],
        f"{fmt(rise, ' N')} from f_ii 0.3, f_is 0.1 to f_ii 0.5, f_is 0.3", agrees("small_friction_rise", rise))
    lmax = num(large, "max_fx_N") if large else None

    def over_300(s):
        if summaries is None:
            return ""
        recs = summaries.get(s, [])
        return f"; {sum(1 for _, x in recs if (x.get('max_fx_N') or 0) > 300)} of {len(recs)} runs over 300 N"
    row("larger rigid floes: max load", TARGETS["large_rigid_max"]["paper"],
        f"{fmt(lmax, ' N')}{over_300('large_rigid')}", agrees("large_rigid_max", lmax), "max")
    for s, r in breakable.items():
        bmax = num(r, "max_fx_N") if r else None
        row(f"larger breakable floes ({s[-3:]}): max load (±20 %)", TARGETS["large_breakable_max"]["paper"],
            f"{fmt(bmax, ' N')}{over_300(s)}", agrees("large_breakable_max", bmax), "few_breaks")
    for s in BREAKABLE:
        cfg = [r for r in rows if r["scenario"] == s]
        tot = {m: int(sum(num(r, "breaks_" + m) or 0 for r in cfg)) for m in modes}
        total = sum(tot.values())
        n_runs = int(sum(num(r, "seeds") or 0 for r in cfg))
        where = f"{total} breaks in {n_runs} runs ({total / n_runs:.1f} per run)" if n_runs else "no runs"
        if summaries is not None:
            broke = sum(1 for _, x in summaries.get(s, []) if (x.get("breaks") or 0) > 0)
            where += f", in {broke} of them"
        row(f"failure modes ({s[-3:]}), all frictions", TARGETS["failure_modes"]["paper"],
            (f"{where}: " + ", ".join(f"{m} {k}" for m, k in tot.items() if k)) if total else where,
            None if total == 0 else tot["bending"] == total)
    for s in BREAKABLE:
        rr, br = num(large, "max_fx_N") if large else None, num(breakable[s], "max_fx_N") if breakable[s] else None
        r = br / rr if rr and br is not None else None
        row(f"breakage lowers the max load ({s[-3:]} / rigid, below 0.8)", TARGETS["breakable_over_rigid_max"]["paper"],
            fmt(r, "", 2), agrees("breakable_over_rigid_max", r), "compliance")
    for s in BREAKABLE:
        a, b = grid_mean(rows, s, "mean_fx_N"), grid_mean(rows, "large_rigid", "mean_fx_N")
        r = a / b if a is not None and b else None
        row(f"breakable ({s[-3:]}) / rigid larger floes, mean load over all frictions (within 20 %)",
            TARGETS["breakable_over_rigid_mean"]["paper"], fmt(r, "", 2), agrees("breakable_over_rigid_mean", r),
            "compliance")
    for s in ("small_rigid", "large_rigid") + BREAKABLE:
        d, mono = trend(rows, s, "mean_fx_N", FIS)
        row(f"{s}: mean load rises with f_is", TARGETS["mean_rises_with_fis"]["paper"], f"{fmt(d, ' N')} from f_is 0.1 to 0.3"
            + ("" if mono is None else (", at every step" if mono else ", not at every step")),
            None if d is None else d > 0)
    for s in ("small_rigid",) + BREAKABLE:
        d, _ = trend(rows, s, "max_fx_N", FIS)
        row(f"{s}: max load rises with f_is", TARGETS["max_rises_with_fis"]["paper"], f"{fmt(d, ' N')} from f_is 0.1 to 0.3",
            None if d is None else d > 0)
    d, _ = trend(rows, "small_rigid", "mean_fx_N", FII)
    row("small_rigid: mean load rises with f_ii", TARGETS["small_mean_rises_with_fii"]["paper"], f"{fmt(d, ' N')} from f_ii 0.3 to 0.7",
        None if d is None else d > 0)
    a, b = grid_mean(rows, "large_breakable_015", "mean_fx_N"), grid_mean(rows, "large_breakable_020", "mean_fx_N")
    rel = (a - b) / b if a is not None and b else None
    row("element size changes the mean load little (0.15 against 0.20 m, all frictions, within 15 %)",
        TARGETS["element_size_effect"]["paper"], fmt(None if rel is None else 100 * rel, " %"),
        agrees("element_size_effect", rel))
    return out


def side_by_side(now, before=None, before_label="", now_label="icedem"):
    """The table of the paper's findings against one or two grids (findings() of each; before
    first, in its own columns) and the rows of `now` that disagree: (lines, [(finding, paper,
    icedem, cause key)])."""
    def agree(ok):
        return "n/a" if ok is None else ("yes" if ok else "**no**")
    L = ["## Side by side with the paper", "",
         "At the paper's reference friction f_ii = 0.5, f_is = 0.2 unless the row says otherwise. "
         "\"Agrees\" uses the tolerance given in the row.", ""]
    if before is None:
        L += [f"| finding | paper | {now_label} | agrees? |", "|---|---|---|---|"]
    else:
        L += [f"| finding | paper | {before_label} | agrees? | {now_label} | agrees? |", "|---|---|---|---|---|---|"]
    old = {f[0]: f for f in before or []}
    disagreements = []
    for finding, paper, ours, ok, cause in now:
        if before is None:
            L.append(f"| {finding} | {paper} | {ours} | {agree(ok)} |")
        else:
            b = old.get(finding)
            L.append(f"| {finding} | {paper} | {b[2] if b else 'n/a'} | {agree(b[3]) if b else 'n/a'} | "
                     f"{ours} | {agree(ok)} |")
        if ok is False:
            disagreements.append((finding, paper, ours, cause))
    return L, disagreements


def numerics(summaries):
    """How the grid's runs were solved, from their summaries: one sentence."""
    solver = [x.get("solver") or {} for v in summaries.values() for _, x in v]
    caps = sorted({x.get("cap") for x in solver if x.get("cap") is not None})
    tols = sorted({x.get("tolerance") for x in solver if x.get("tolerance") is not None})
    sweeps = [x["iterations_mean"] for x in solver if x.get("iterations_mean") is not None]
    if not caps:
        return ""
    how = (f"at most {'/'.join(map(str, caps))} sweeps, ending at a residual of "
           f"{'/'.join(f'{t:g}' for t in tols)}" if any(t > 0 for t in tols)
           else f"{'/'.join(map(str, caps))} sweeps every step")
    return (f"Every run of this grid solved its contacts with {how}: {sum(sweeps) / len(sweeps):.1f} sweeps "
            "per step on average over the runs.")


def disagreement_section(disagreements, causes, summaries):
    L = ["## Where icedem disagrees with the paper", ""]
    if not disagreements:
        L.append("Nowhere among the rows above.")
    for finding, paper, ours, cause in disagreements:
        why = causes.get(cause)
        L.append(f"- **{finding}**: paper {paper}, icedem {ours}." + (f" Why: {why}." if why else ""))
    return L + ["", numerics(summaries), ""]


def supplement_rows(sweep_file):
    """(name, runs, output directory, results rows or None if not aggregated) of a supplement."""
    name, runs = spec.load(sweep_file)
    out = os.path.join(spec.ROOT, "sweeps", name)
    rows = read_rows(out) if os.path.isfile(os.path.join(out, "results.csv")) else None
    return name, runs, out, rows


def ratio_to_first(rows, r, key):
    """A supplement configuration's value against its first configuration's, formatted."""
    a, b = num(r, key), num(rows[0], key)
    return fmt(a / b if a is not None and b else None, "", 2)


def supplement_ratios(rows):
    """What a supplement measured, for the causes that cite it: every configuration's mean and
    max against the first configuration's; nothing until the first and another have runs."""
    if not rows or num(rows[0], "mean_fx_N") is None:
        return ""
    rows = [r for r in rows if num(r, "mean_fx_N") is not None]
    if len(rows) < 2:
        return ""
    first = rows[0]["configuration"].split("/")[0]
    return (f" (mean / max against `{first}`: "
            + ", ".join(f"`{r['configuration'].split('/')[0]}` {ratio_to_first(rows, r, 'mean_fx_N')} / "
                        f"{ratio_to_first(rows, r, 'max_fx_N')}" for r in rows[1:]) + ")")


def filled_causes(supplements):
    """CAUSES with each {supplement name} replaced by its ratios, or by nothing; supplements:
    (sweep file, *supplement_rows) of each."""
    evidence = collections.defaultdict(str)
    for _, name, _, _, rows in supplements:
        if rows:
            evidence[name] = supplement_ratios(rows)
    return {k: v.format_map(evidence) for k, v in CAUSES.items()}


def supplement_section(sweep_file, name, runs, out, rows):
    """The configurations of another aggregated sweep (its supplement_rows), with their max
    against the first one's."""
    if rows is None:
        return [f"## Supplement: sweep `{name}`", "", f"Not aggregated yet (`scripts/sweep aggregate {sweep_file}`).", ""]
    done = sum(1 for r in runs if execute.status(r, out).state == "done")
    with open(sweep_file) as f:  # its opening comment says what it is for
        about = [l[2:].rstrip() for l in f if l.startswith("# ") and not l[2:].lstrip().startswith("scripts/")]
    L = [f"## Supplement: sweep `{name}`", "", " ".join(about), "",
         f"{done} of {len(runs)} runs finished. Ratios: against the first configuration.", "",
         "| configuration | seeds | mean N | max N | mean ratio | max ratio | run time per run s |",
         "|---|---|---|---|---|---|---|"]
    for r in rows:
        per = num(r, "run_wall_time_s")
        n = int(float(r["seeds"])) if r.get("seeds") else 0
        L.append(f"| {r['configuration']} | {r['seeds']} | {ci(r, 'mean_fx_N')} | {ci(r, 'max_fx_N')} | "
                 f"{ratio_to_first(rows, r, 'mean_fx_N')} | {ratio_to_first(rows, r, 'max_fx_N')} | "
                 f"{fmt(per / n if per is not None and n else None, '', 0)} |")
    return L + [""]


def before_section(rows, before_out, note):
    """Every configuration against the same sweep run with an earlier build (its output
    directory): mean and max load before and now, their ratio, and whether the change is
    within the seeds' scatter (the two 95 % half-widths combined)."""
    if not os.path.isfile(os.path.join(before_out, "results.csv")):
        return ["## Against an earlier build", "", f"No results.csv in `{before_out}`.", ""]
    before = {r["configuration"]: r for r in read_rows(before_out)}
    L = ["## Against an earlier build", "", note, "",
         f"The earlier runs: `{os.path.relpath(before_out, spec.ROOT)}`. A change is within the seed "
         "scatter when it is smaller than the two 95 % half-widths combined (root of the sum of squares).", "",
         "| configuration | seeds before / now | mean N before → now | ratio | within scatter | "
         "max N before → now | ratio | within scatter |", "|---|---|---|---|---|---|---|---|"]
    ratios = {}

    def change(a, b, key):
        """(table cells "before → now | ratio | within scatter", the ratio or None)"""
        x, y = num(a, key), num(b, key)
        if x is None or y is None or x == 0:
            return "n/a | n/a | n/a", None
        h = math.hypot(num(a, key + "_ci95") or 0.0, num(b, key + "_ci95") or 0.0)
        return f"{x:.1f} → {y:.1f} | {y / x:.2f} | {'yes' if abs(y - x) <= h else '**no**'}", y / x

    for r in rows:
        b = before.get(r["configuration"])
        if b is None:
            continue
        cells = []
        for key, column in (("mean", "mean_fx_N"), ("max", "max_fx_N")):
            text, ratio = change(b, r, column)
            cells.append(text)
            if ratio is not None:
                ratios.setdefault((r["scenario"], key), []).append(ratio)
        L.append(f"| {r['configuration']} | {b['seeds']} / {r['seeds']} | {cells[0]} | {cells[1]} |")
    L.append("")
    for scen in dict.fromkeys(r["scenario"] for r in rows):
        parts = [f"{key} {sum(v) / len(v):.2f}" for key in ("mean", "max")
                 if (v := ratios.get((scen, key)))]
        if parts:
            L.append(f"- {scen}: now / before, averaged over its configurations: " + ", ".join(parts) + ".")
    return L + [""]


def quantile(values, q):
    """The q-quantile (linear between order statistics), None for no values."""
    return float(np.quantile(values, q)) if len(values) else None


def breaks_of(records, scenario, fii=None):
    """Every break of a scenario's runs (at one f_ii, or all): [(run, event dict)], and the runs."""
    runs = [(r, rec) for r, rec in records.get(scenario, []) if fii is None or dict(r.grid).get(FII) == fii]
    return [(r, e) for r, rec in runs for e in rec.get("fracture_events", [])], runs


def mechanism_section(records, figs, report):
    """Breaks by mechanism per f_ii (dem/break_context.hpp), against the paper's Fig. 18."""
    L = ["## Breakage mechanisms", "",
         "Every break is recorded with what its floe was doing in the step of the break "
         "(`/fracture/events`; docs/model/breakage.md): whether an element of it touched the structure, the "
         "depth of the joint below the waterline, the contact force of other floes on it (down and "
         "towards the structure axis) and its distance from the structure. Classes: **on the slope** "
         "(touching the structure), **pressed under** (touching, submerged at least one thickness and "
         "pressed by another floe), **in the rubble** (not touching, submerged), **in the pack** (not "
         "touching, afloat). Summed over f_is and seeds.", ""]
    share = {}
    # the mechanisms as the events name them (icedem declares them; every summary counts all)
    mechanisms = [m.replace("_", " ") for m in agg.break_names(
        [rec["summary"] for v in records.values() for _, rec in v], "breaks_by_mechanism")]
    for s in BREAKABLE:
        if s not in records:
            continue
        L += [f"### {s}", "",
              "| f_ii | runs | breaks | per run | " + " | ".join(mechanisms) + " | median depth mm | "
              "median distance m | median force of other floes N |", "|---" * (7 + len(mechanisms)) + "|"]
        fiis = sorted({dict(r.grid).get(FII) for r, _ in records[s]} - {None})
        for fii in fiis:
            ev, runs = breaks_of(records, s, fii)
            counts = collections.Counter(e.get("mechanism_name", "") for _, e in ev)
            n = len(ev)
            share[(s, fii)] = {m: counts[m] / n for m in mechanisms} if n else None
            cells = " | ".join(f"{counts[m]} ({100 * counts[m] / n:.0f} %)" if n else "0" for m in mechanisms)
            depth = quantile([1e3 * e["depth"] for _, e in ev if "depth" in e], 0.5)
            dist = quantile([e["distance"] for _, e in ev if "distance" in e], 0.5)
            press = quantile([e["press_down"] + e["press_toward"] for _, e in ev if "press_down" in e], 0.5)
            L.append(f"| {fii:g} | {len(runs)} | {n} | {n / len(runs):.2f} | {cells} | {fmt(depth, '', 0)} | "
                     f"{fmt(dist, '', 2)} | {fmt(press, '', 1)} |")
        L.append("")
        lo, hi = share.get((s, 0.3)), share.get((s, 0.7))
        if lo and hi:
            pu = (lo["pressed under"], hi["pressed under"])
            sl = (lo["on the slope"], hi["on the slope"])
            agree = pu[0] > pu[1] and sl[1] > sl[0]
            L += [f"Fig. 18 says: at f_ii 0.3 a submerged floe pressed against the cone by an approaching floe "
                  f"breaks; at 0.7 floes break sliding on the slope. Here pressed under is {100 * pu[0]:.0f} % of "
                  f"the breaks at f_ii 0.3 and {100 * pu[1]:.0f} % at 0.7; on the slope {100 * sl[0]:.0f} % and "
                  f"{100 * sl[1]:.0f} %: the shift with f_ii {'agrees' if agree else '**does not agree**'} with "
                  "the paper's picture.", ""]
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


def flow_section(flow_sweep, rows):
    """The flow models over seeds (a sweep of the small floes under other flow models) against the
    grid's own small-floe runs at f_ii 0.5, f_is 0.2 (the analytic potential flow, the default):
    whether a model moves the mean or the max beyond the seeds' scatter."""
    name, runs, out, frows = supplement_rows(flow_sweep)
    L = ["## Flow models over seeds", ""]
    with open(flow_sweep) as f:
        L += [" ".join(l[2:].rstrip() for l in f if l.startswith("# ") and not l[2:].lstrip().startswith("scripts/")), ""]
    if frows is None:
        return L + [f"Not aggregated yet (`scripts/sweep aggregate {os.path.relpath(flow_sweep, spec.ROOT)}`).", ""]
    ref = pick(rows, "small_rigid")
    table = ([("analytic potential (the grid's small_rigid runs)", ref)] if ref else []) + \
            [(r["configuration"].split("/")[0], r) for r in frows]
    L += ["| flow model | seeds | mean N | max N | mean − potential N | beyond scatter? | max − potential N | "
          "beyond scatter? | CPU per run s |", "|---|---|---|---|---|---|---|---|---|"]

    def diff(r, key):
        if ref is None or r is ref:
            return "", ""
        a, b = num(r, key), num(ref, key)
        if a is None or b is None:
            return "n/a", "n/a"
        h = math.hypot(num(r, key + "_ci95") or 0.0, num(ref, key + "_ci95") or 0.0)
        return f"{a - b:+.1f} (± {h:.1f})", ("**yes**" if abs(a - b) > h else "no")
    for label, r in table:
        dm, bm = diff(r, "mean_fx_N")
        dx, bx = diff(r, "max_fx_N")
        n = num(r, "seeds") or 0
        cpu = num(r, "run_cpu_time_s")
        L.append(f"| {label} | {r['seeds']} | {ci(r, 'mean_fx_N')} | {ci(r, 'max_fx_N')} | {dm} | {bm} | {dx} | {bx} | "
                 f"{fmt(cpu / n if cpu is not None and n else None, '', 0)} |")
    return L + ["", "± are 95 % confidence half-widths over the seeds; a difference is beyond the scatter when "
                "it exceeds the root sum of squares of the two half-widths.", ""]


def convergence_section(conv_sweep, records):
    """The grid's numbers against a halved step and a tighter solve (a sweep whose scenarios are
    <model>+<numerics>, e.g. sweeps/paper_convergence.toml), compared seed by seed, and whether
    its default runs repeat the grid's runs of the same seeds."""
    name, runs, out, _ = supplement_rows(conv_sweep)
    L = ["## Convergence of the grid's loads", ""]
    with open(conv_sweep) as f:
        L += [" ".join(l[2:].rstrip() for l in f if l.startswith("# ") and not l[2:].lstrip().startswith("scripts/")), ""]
    got = collections.defaultdict(dict)  # (model, numerics) -> {seed: summary}
    for r in runs:
        if execute.status(r, out).state == "done":
            model, _, numerics = r.scenario.partition("+")
            got[(model, numerics)][r.seed] = agg.load_record(r, out)["summary"]
    if not got:
        return L + [f"No finished runs yet (`scripts/sweep run {os.path.relpath(conv_sweep, spec.ROOT)}`).", ""]
    L += ["| model | numerics | seeds | mean: ratio to default | max: ratio to default | breaks per run | "
          "sweeps per step | CPU per run s |", "|---|---|---|---|---|---|---|---|"]

    def spread(values):
        return f"{sum(values) / len(values):.2f} ({min(values):.2f}-{max(values):.2f})" if values else "n/a"
    models = list(dict.fromkeys(m for m, _ in got))
    for model in models:
        base = got.get((model, "default"), {})
        for numerics in [n for m, n in got if m == model]:
            runs_ = got[(model, numerics)]
            seeds = sorted(set(runs_) & set(base))
            ratios = {k: [runs_[sd][k] / base[sd][k] for sd in seeds if runs_[sd].get(k) and base[sd].get(k)]
                      for k in ("mean_fx_N", "max_fx_N")}
            br = [x.get("breaks", 0) for x in runs_.values()]
            sw = [(x.get("solver") or {}).get("iterations_mean") for x in runs_.values()]
            sw = [v for v in sw if v is not None]
            cpu = [x.get("cpu_time_s") for x in runs_.values() if x.get("cpu_time_s")]
            L.append(f"| {model} | {numerics} | {len(runs_)} | "
                     f"{spread(ratios['mean_fx_N']) if numerics != 'default' else '1'} | "
                     f"{spread(ratios['max_fx_N']) if numerics != 'default' else '1'} | "
                     f"{sum(br) / len(br):.1f} | {fmt(sum(sw) / len(sw) if sw else None)} | "
                     f"{fmt(sum(cpu) / len(cpu) if cpu else None, '', 0)} |")
    L += ["", "Ratios: the mean over seeds of each seed's value against the same seed's default run, with "
          "the range over seeds in brackets."]
    # the default runs are the grid's runs of the same seeds at f_ii 0.5, f_is 0.2: they must agree
    same, differ = 0, []
    for (model, numerics), by_seed in got.items():
        if numerics != "default":
            continue
        for r, rec in records.get(model, []):
            g = dict(r.grid)
            if g.get(FII) == 0.5 and g.get(FIS) == 0.2 and r.seed in by_seed:
                a, b = rec["summary"].get("max_fx_N"), by_seed[r.seed].get("max_fx_N")
                if a == b:
                    same += 1
                else:
                    differ.append(f"{model} seed {r.seed}: {a} against {b} N")
    if same or differ:
        L += ["", f"The default runs repeat the grid's: {same} of {same + len(differ)} runs give the same max load "
              "to the last digit" + (" (**not**: " + "; ".join(differ) + ")" if differ else "") + "."]
    return L + [""]


def configuration_table(rows):
    L = ["## Every configuration", "",
         "Gumbel u and β: the moment fit of the seed maxima (docs/model/validation_targets.md §7); the expected max of an "
         "N-times longer record is u + β ln N. CoV: the coefficient of variation of the seed maxima; "
         "n(±10 %): the seeds a mean of maxima within ±10 % at 95 % needs, (1.96 CoV / 0.1)².", "",
         "| configuration | seeds | mean N | max N | Gumbel u, β N | CoV of max | n(±10 %) | peak interval s "
         "| spectral peak s | breaks (bending) |",
         "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        u, beta = num(r, "max_fx_gumbel_u_N"), num(r, "max_fx_gumbel_beta_N")
        cov = num(r, "max_fx_cov")
        need = math.ceil((1.96 * cov / 0.1) ** 2) if cov is not None else None
        L.append(f"| {r['configuration']} | {r['seeds']} | {ci(r, 'mean_fx_N')} | {ci(r, 'max_fx_N')} | "
                 f"{fmt(u)}, {fmt(beta)} | {fmt(cov, '', 2)} | {need if need is not None else 'n/a'} | "
                 f"{fmt(num(r, 'peak_interval_s'), '', 2)} | "
                 f"{fmt(num(r, 'spectral_peak_period_s'), '', 2)} | {r.get('breaks_bending', '0')} |")
    return L + [""]


def run_time_section(summaries, out, total_runs):
    L = ["## Run time", "", "| scenario | runs | wall time per run s | CPU time per run s | real-time factor | "
         "share of the grid's CPU |", "|---|---|---|---|---|---|"]
    total = sum(x.get("wall_time_s") or 0 for v in summaries.values() for _, x in v)
    total_cpu = sum(x.get("cpu_time_s") or 0 for v in summaries.values() for _, x in v)
    done = sum(len(v) for v in summaries.values())
    for s, v in summaries.items():
        w = [x.get("wall_time_s") or 0 for _, x in v]
        c = [x.get("cpu_time_s") or 0 for _, x in v]
        rtf = [x.get("realtime_factor") or 0 for _, x in v]
        share = f"{100 * sum(c) / total_cpu:.0f} %" if total_cpu else "n/a"
        L.append(f"| {s} | {len(v)} | {sum(w) / len(w):.0f} | {sum(c) / len(c):.0f} | {sum(rtf) / len(rtf):.1f} | "
                 f"{share} |")
    L += ["", f"The finished runs took {total / 3600:.2f} h of wall time and {total_cpu / 3600:.2f} h of CPU time "
          "(each run on one core; wall time grows when the machine is shared, CPU time does not)."]
    span = joblog_span(out)
    if span and done:
        busy, summed, n = span
        # the log also holds jobs that were stopped or whose runs were deleted and rerun:
        # they ran beside the others, so they count for how many ran at once
        L.append(f"GNU parallel's job log holds {n} jobs (stopped and rerun ones included): "
                 f"{summed / 3600:.2f} h of run time in "
                 f"{busy / 3600:.2f} h of wall time, {summed / busy:.2f} runs at once on average on this "
                 f"{os.cpu_count()}-core machine. At that rate the whole grid takes about "
                 f"{total * total_runs / done / (summed / busy) / 3600:.1f} h of wall time.")
    return L + [""]


def figure_section(runs, out, figs, report):
    rel = os.path.relpath(figs, os.path.dirname(report))
    present = set(os.listdir(figs)) if os.path.isdir(figs) else set()
    L = ["## Figures", ""]
    for kind, caption in FIGURES:
        files = [f"{kind}_{s}.png" for s in dict.fromkeys(r.scenario for r in runs) if f"{kind}_{s}.png" in present]
        if files:
            L += [f"### {caption}", ""]
            for fn in files:
                L += [f"![{fn}]({rel}/{fn})", ""]
    views = [os.path.relpath(os.path.join(out, r.path, "run.xdmf"), spec.ROOT) for r in runs
             if os.path.isfile(os.path.join(out, r.path, "run.xdmf"))]
    if views:
        L += ["### Snapshots in ParaView", "",
              "The runs of the top views, every snapshot (floes and elements as prisms in the tank frame, "
              "floe id and awake flag per body), for ParaView's XDMF reader (not committed: they sit beside "
              "the runs):", ""] + [f"- `{v}`" for v in views] + [""]
    return L


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sweep")
    ap.add_argument("--out", help="the sweep's output directory (default sweeps/<name>)")
    ap.add_argument("--report", help="the Markdown file (default OUT/report.md)")
    ap.add_argument("--figures", help="where sweep_figures.py put the PNGs (default OUT/figures)")
    ap.add_argument("--command", help="the command that made the report, quoted at its top")
    ap.add_argument("--supplement", action="append", default=[],
                    help="another aggregated sweep (e.g. sweeps/paper_resolution.toml) whose "
                         "configurations get a table of their own; repeatable")
    ap.add_argument("--before", help="the output directory of the same sweep run with an earlier "
                                     "build: a section compares every configuration with it")
    ap.add_argument("--before-note", default="", help="what changed since the earlier build")
    ap.add_argument("--before-label", default="icedem before",
                    help="the column heading of the earlier build's findings")
    ap.add_argument("--label", default="icedem", help="the column heading of this sweep's findings")
    ap.add_argument("--flow", help="a sweep of the small floes under other flow models (e.g. "
                                   "sweeps/flow_models.toml), compared with this grid's small_rigid runs")
    ap.add_argument("--convergence", help="a sweep of the grid's models with other numerics (e.g. "
                                          "sweeps/paper_convergence.toml), compared seed by seed")
    args = ap.parse_args(argv)
    name, runs = spec.load(args.sweep)
    out = os.path.abspath(args.out or os.path.join(spec.ROOT, "sweeps", name))
    rows = read_rows(out)
    report = os.path.abspath(args.report or os.path.join(out, "report.md"))
    figs = os.path.abspath(args.figures or os.path.join(out, "figures"))
    sweep_rel = os.path.relpath(os.path.abspath(args.sweep), spec.ROOT)
    records = run_records(runs, out)
    summaries = run_summaries(records)
    done = sum(len(v) for v in summaries.values())
    seeds = sorted({r.seed for r in runs})

    L = [f"# icedem against the seed paper: sweep `{name}`", "",
         "Made with " + (f"`{args.command}`" if args.command else
                         f"`scripts/sweep run {sweep_rel}`, `scripts/sweep aggregate {sweep_rel}`, "
                         f"`scripts/sweep_figures.py {sweep_rel}` and `scripts/report {sweep_rel}`") + ".", "",
         f"{done} of {len(runs)} runs finished, {len({r.config for r in runs})} configurations, "
         f"seeds {seeds[0]}-{seeds[-1]}" + ("" if done == len(runs) else
                                             " (**the grid is not complete**: configurations average "
                                             "over the seeds finished, see the seeds column)") + ". "
         "Loads are the surge load (the component resisting the tow, N) over each run's analysis "
         "window, given as the mean over seeds ± the half-width of the 95 % confidence interval "
         "(Student's t).", ""]
    failed = [st for st in (execute.status(r, out) for r in runs) if st.state == "failed"]
    if failed:
        # a failed run is reported, never silently dropped: its configuration averages the other seeds
        L += [f"**{len(failed)} run(s) failed**, left out of the averages:", ""]
        L += [f"- `{st.run.path}`: {st.error}" for st in failed] + [""]
    supplements = [(f, *supplement_rows(f)) for f in args.supplement]  # read once, cited twice
    causes = filled_causes(supplements)
    modes = agg.break_names([x for v in summaries.values() for _, x in v], "breaks_by_mode")
    now = findings(rows, summaries, modes)
    before_rows = None
    if args.before:
        before_out = os.path.abspath(args.before)
        if os.path.isfile(os.path.join(before_out, "results.csv")):
            before_rows = read_rows(before_out)
    before = findings(before_rows, None, modes) if before_rows else None
    table, disagreements = side_by_side(now, before, args.before_label, args.label)
    L += table + [""] + disagreement_section(disagreements, causes, summaries)
    L += mechanism_section(records, figs, report) + margin_section(records, figs, report)
    if args.flow:
        L += flow_section(os.path.abspath(args.flow), rows)
    if args.convergence:
        L += convergence_section(os.path.abspath(args.convergence), records)
    for sup in supplements:
        L += supplement_section(*sup)
    if args.before:
        L += before_section(rows, os.path.abspath(args.before), args.before_note)
    L += configuration_table(rows) + run_time_section(summaries, out, len(runs))
    L += figure_section(runs, out, figs, report)
    os.makedirs(os.path.dirname(report), exist_ok=True)
    with open(report, "w") as fh:
        fh.write("\n".join(L) + "\n")
    print(f"wrote {report}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
