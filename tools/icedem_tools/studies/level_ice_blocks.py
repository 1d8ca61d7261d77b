"""The analytic level tows in 10 s blocks, for docs/model/level_ice.md (scripts/level_ice_report --analytic with
--crushing, --step and --solve): each ensemble's block means and block maxima pooled over its starts, against
ISO 19906, and the changes of the crushing law, the halved step and the tighter solve judged on them
(stats/block_change.py).

A tow's one maximum is one draw, and two or three starts give its change an interval too wide to say anything
(the sections above: "unresolved" over -90 to +400 %). Its window holds some twenty 10 s blocks, each a few
breaking cycles: the mean of the blocks' maxima is the load a tow reaches every 10 s or so, and its interval,
over all the blocks of all the starts (their correlation within a tow taken in), is what a change of setting
is judged against here. It answers a narrower question than the maximum's: whether the typical peak moves,
not the rarest one."""
import os

from ..runs import spec
from ..stats import block_change, verdict
from ..reports.report_tables import fmt
from . import level_ice_analytic as la

# the page's block criteria: (label, the window's blocks key, its low-pass cut-off or None)
CRITERIA = (("block mean", "mean_fx_N", None), ("block max", "max_fx_N", None),
            ("block max 5 Hz", "max_lowpass_fx_N", "5"))


def record_blocks(record, key, cutoff):
    """A record's blocks of one criterion (aggregate.block_loads: `key`, at the low-pass `cutoff` or None), in time
    order; None for a record without them."""
    v = ((record.get("window") or {}).get("blocks") or {}).get(key)
    return (v.get(cutoff) if cutoff is not None and v is not None else v) or None


def block_runs(members, key, cutoff):
    """The blocks of each start's record (record_blocks), a list per start; starts without blocks left out."""
    return [v for v in (record_blocks(rec, key, cutoff) for _, rec in members.values()) if v]


def _text(runs):
    m, h, _ = block_change.mean_ci(runs)
    return "n/a" if not runs else f"{m:.1f}" + (f" ± {h:.1f}" if h == h else "")


def _law(members):
    """The contact law at the structure of an ensemble's tows (spec.run_value of contact.model)."""
    run = next(iter(members.values()))[0]
    try:
        return str(spec.run_value(run, "contact.model"))
    except (OSError, KeyError, ValueError):
        return "n/a"


def section(ensembles, comparisons, design_loads):
    """The page's lines. `ensembles`: [(sweep file, its configurations (level_ice_analytic.configurations))], the
    tows without leave_behind of each shown; `comparisons`: [(changed sweep file, base_of)], each of its scenarios
    against the scenario base_of(name) among the other ensembles; design_loads(run) as level_ice_analytic's."""
    L = ["### 10 s blocks", "",
         "The tows above without leave_behind cut into 10 s blocks from the start of their analysis window (a last "
         "part block left out), pooled over their starts: the mean of the blocks' means, of their maxima, and of "
         "their maxima low-passed at 5 Hz, each with its 95 % interval over the blocks. A block holds a few breaking "
         "cycles, so the mean block maximum is the peak a tow reaches every 10 s or so, not its rarest; over some "
         "twenty blocks a tow it has an interval that two or three starts do not give the tow's one maximum. A tow's "
         "blocks are correlated (the rubble at the cone builds up and clears over more than a block): the intervals "
         "count the blocks as n (1 - r1) / (1 + r1) independent ones, r1 their lag-1 correlation within a tow "
         "(of the maxima, in the table; each criterion its own), corrected for its bias over short runs "
         "(docs/model/estimators.md). Loads in N, surge.", ""]
    shown = [(sweep, {sc: m for (sc, leave), m in configs.items() if leave == 0.0}) for sweep, configs in ensembles]
    rows = [(sweep, sc, m) for sweep, by in shown for sc, m in sorted(by.items())
            if block_runs(m, "max_fx_N", None)]
    if not rows:
        return L + ["No finished run with blocks yet.", ""]
    L += ["| run | sweep | law | step s | starts | blocks | r1 of the maxima | block mean | block max | "
          "block max 5 Hz | ISO 19906 | block max / ISO | block max 5 Hz / ISO |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for sweep, sc, members in rows:
        runs = {label: block_runs(members, key, cut) for label, key, cut in CRITERIA}
        run = next(iter(members.values()))[0]
        loads, _ = design_loads(run)
        iso = loads["total_N"] if loads else None
        step = la.ensemble_step(members)
        m_max = block_change.mean_ci(runs["block max"])[0]
        m_5 = block_change.mean_ci(runs["block max 5 Hz"])[0] if runs["block max 5 Hz"] else None
        L.append(f"| {sc} | {os.path.basename(sweep)} | {_law(members)} | {'n/a' if step is None else f'{step:g}'} | "
                 f"{len(runs['block max'])} | {sum(len(r) for r in runs['block max'])} | "
                 f"{block_change.lag1(runs['block max']):.2f} | "
                 + " | ".join(_text(runs[label]) for label, _, _ in CRITERIA)
                 + f" | {fmt(iso)} | {fmt(m_max / iso if iso else None, digits=2)} | "
                 f"{fmt(m_5 / iso if iso and m_5 else None, digits=2)} |")
    changes, names, lines = {}, {}, []
    for sweep, base_of in comparisons:
        for sc, members in sorted(next((by for s, by in shown if s == sweep), {}).items()):
            # the first other sweep that has the scenario's base name (the step's tows share their names with the
            # crushing tows they halve)
            base = next((by[base_of(sc)] for s, by in shown if s != sweep and base_of(sc) in by), None)
            if not base:
                continue
            for label, key, cut in CRITERIA:
                a, b = block_runs(members, key, cut), block_runs(base, key, cut)
                if not a or not b:
                    continue
                k = (sc, base_of(sc), label)
                changes[k] = block_change.change(a, b)
                names[k] = f"{sc} against {base_of(sc)}: {label}"
                lines.append(f"| {sc} | {base_of(sc)} | {label} | {_text(b)} | {_text(a)} | "
                             f"{verdict.change_text(changes[k][:3])} | {sum(map(len, b))} / {sum(map(len, a))} |")
    if not changes:
        return L + [""]
    L += ["", "Each changed ensemble against the one it changes (the crushing law against rigid contacts, the halved "
          "step and the tighter solve against the crushing tows), judged on the blocks: the ratio of the two block "
          "means with its 95 % interval (the log ratio's, by the delta method, Welch's degrees of freedom on each "
          "side's effective number of blocks), and its verdict (docs/model/estimators.md).",
          "", "| run | against | criterion | against's | these | change | blocks, against / these |",
          "|---|---|---|---|---|---|---|"] + lines
    return L + ["", verdict.family_text(changes, lambda k: names[k]), ""]
