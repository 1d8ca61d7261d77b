"""The seed paper's findings checked on a grid (their numbers and tolerances are data:
sweeps/paper_targets.toml): the side-by-side table, the disagreements and what is known of
their causes (tools/icedem_tools/reports/report.py)."""
import collections
import os
import re
import tomllib

from ..runs import spec
from .report_tables import BREAKABLE, FII, FIS, fmt, grid_mean, num, pick, ratio_to_first, trend

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
    "max": "the section \"Are the findings converged?\" below measures how far the max moves when the step "
           "is halved and the solve tightened tenfold, and bounds the max each case could reach with them; a gap "
           "wider than that bound is the model's, not the numerics' (the paper does not give its solver "
           "settings){paper_resolution}",
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
    def agree(ok, link=False):
        no = "**no** ([why](#where-icedem-disagrees-with-the-paper))" if link else "**no**"
        return "n/a" if ok is None else ("yes" if ok else no)
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
            L.append(f"| {finding} | {paper} | {ours} | {agree(ok, link=True)} |")
        else:
            b = old.get(finding)
            L.append(f"| {finding} | {paper} | {b[2] if b else 'n/a'} | {agree(b[3]) if b else 'n/a'} | "
                     f"{ours} | {agree(ok, link=True)} |")
        if ok is False:
            disagreements.append((finding, paper, ours, cause))
    return L, disagreements

MOVED_FINDING = 0.10  # a finding's number that moves by more than this is named in a sentence


def _first_number(text):
    """(the first number in a finding's text, whether it is a percentage), or (None, False)."""
    m = re.search(r"(-?\d+(?:\.\d+)?)( ?%)?", text or "")
    return (float(m.group(1)), bool(m.group(2))) if m else (None, False)


def changed_findings(now, before, before_label, now_label):
    """A sentence for every finding whose agreement with the paper changed from the earlier
    grid (`before`) to this one (findings() of each), and for every finding whose number (the
    first in its text) moved by more than MOVED_FINDING: lines."""
    if before is None:
        return []
    old = {f[0]: f for f in before}
    flips, moved, same = [], [], 0
    for finding, _, ours, ok, _ in now:
        b = old.get(finding)
        if b is None:
            continue
        if b[3] is not None and ok is not None and bool(b[3]) != bool(ok):
            turn = "now agrees with the paper" if ok else "no longer agrees with the paper"
            flips.append(f"- **{finding}** {turn}: {b[2]} with {before_label}, {ours} with {now_label}.")
            continue
        (x0, percent), (x1, _) = _first_number(b[2]), _first_number(ours)
        # a percentage moves by points (a relative change of a share near 0 says nothing)
        change = (None if x0 is None or x1 is None else (x1 - x0) / 100 if percent else
                  (x1 / x0 - 1) if x0 else None)
        if change is not None and abs(change) > MOVED_FINDING:
            agrees = "" if ok is None else (", and agrees with the paper as before" if ok else
                                            ", and disagrees with the paper as before")
            by = f"{100 * change:+.0f} points" if percent else f"{100 * change:+.0f} %"
            moved.append(f"- **{finding}** moved by {by}: {b[2]} with {before_label}, {ours} with {now_label}{agrees}.")
        else:
            same += 1
    L = [f"### Findings that changed from {before_label} to {now_label}", ""]
    L += flips or ["No finding changed its agreement with the paper."]
    if moved:
        L += ["", f"Numbers that moved by more than {100 * MOVED_FINDING:.0f} % ({100 * MOVED_FINDING:.0f} points "
              "for a percentage):", ""] + moved
    L += ["", f"The other {same} findings moved by {100 * MOVED_FINDING:.0f} % ({100 * MOVED_FINDING:.0f} points "
          "for a percentage) or less, or give no number to compare.", ""]
    return L


def numerics(summaries):
    """How the grid's runs were solved, from their summaries: one sentence (or two)."""
    solver = [x.get("solver") or {} for v in summaries.values() for _, x in v]
    caps = sorted({x.get("cap") for x in solver if x.get("cap") is not None})
    tols = sorted({x.get("tolerance") for x in solver if x.get("tolerance") is not None})
    sweeps = [x["iterations_mean"] for x in solver if x.get("iterations_mean") is not None]
    if not caps:
        return ""
    methods = sorted({x.get("method", "pgs") for x in solver})
    if methods != ["pgs"]:
        # the accelerated projected gradient (and any other method with a merit): its steps and how
        # many of the analysis windows' steps stopped at the cap
        joints = sorted({x.get("joint_tolerance") for x in solver if x.get("joint_tolerance")})
        capped = [x.get("capped_window_fraction") or 0.0 for x in solver]
        return (f"Every run of this grid solved its contacts with {'/'.join(methods)}, at most "
                f"{'/'.join(map(str, caps))} steps a step, to a merit of {'/'.join(f'{t:g}' for t in tols)}"
                + (f" (islands with joints {'/'.join(f'{t:g}' for t in joints)})" if joints else "")
                + f": {sum(sweeps) / len(sweeps):.1f} steps per step on average over the runs. "
                f"{sum(c > 0 for c in capped)} of {len(capped)} runs stopped a step of their analysis window at the "
                f"cap (at most {100 * max(capped):.2f} % of a window's steps).")
    how = (f"at most {'/'.join(map(str, caps))} sweeps, ending at a residual of "
           f"{'/'.join(f'{t:g}' for t in tols)}" if any(t > 0 for t in tols)
           else f"{'/'.join(map(str, caps))} sweeps every step")
    return (f"Every run of this grid solved its contacts with {how}: {sum(sweeps) / len(sweeps):.1f} sweeps "
            "per step on average over the runs.")

# where the report (docs/paper_reproduction/report.md) finds the model's measured budget against the tank
BUDGET_LINK = ("What each part of the model does to the loads, one factor at a time over seeds: "
               "[the load budget](../model/load_budget.md); the tank's one largest load against the runs' maxima: "
               "[tank_maxima.md](../model/tank_maxima.md).")


def disagreement_section(disagreements, causes, summaries):
    L = ["## Where icedem disagrees with the paper", ""]
    if not disagreements:
        L.append("Nowhere among the rows above.")
    for finding, paper, ours, cause in disagreements:
        why = causes.get(cause)
        L.append(f"- **{finding}**: paper {paper}, icedem {ours}." + (f" Why: {why}." if why else "")
                 + f" {BUDGET_LINK}")
    return L + ["", numerics(summaries), ""]

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
