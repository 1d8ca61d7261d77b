"""The analytic level tows (the sheet cut by closed forms, scenarios/level_ice/level_ice_analytic.toml) over
an ensemble of starts, for docs/model/level_ice.md (scripts/level_ice_report --analytic SWEEP): each
configuration's loads over its starts beside ISO 19906's and Ralston's for its cone, ice and friction, and
what activation.leave_behind does to them, paired start by start against the tow without it.

A level sheet has no random layout: the ensemble's members are one tow started a millimetre apart
(structure.start_x), whose paths part at the first breaks (the tow is chaotic). A configuration is the
sweep's scenario with its activation.leave_behind; its members are its starts."""
import math
import os
import tomllib

import numpy as np

from ..runs import spec
from ..stats import intervals, verdict
from ..sweeps import aggregate as agg, execute
from ..reports.report_tables import fmt

START, LEAVE = "structure.start_x", "activation.leave_behind"
# the 5 Hz low-passed maximum (aggregate.lowpass_maxima): a rigid contact's largest loads are single steps of the
# pieces locked between the cone and the held sheet, set by the step, not the ice
LOWPASS = "max_lowpass_fx_N/5"
CRITERIA = {"mean": "mean_fx_N", "p99": "p99_fx_N", "max": "max_fx_N", "max 5 Hz": LOWPASS}


def _value(record, key):
    s, w = record["summary"], record.get("window", {})
    if "/" in key:
        name, cutoff = key.split("/")
        v = w.get(name, {}).get(cutoff)
    else:
        v = s.get(key, w.get(key))
    return None if v is None else float(v)


def mean_text(values):
    """The mean of `values` (None left out) with Student's 95 % half-width where there are two or more, as the
    pages print it ("22.0 ± 5.0"); "n/a" for none."""
    v = [x for x in values if x is not None]
    if not v:
        return "n/a"
    m, h = intervals.mean_ci(v)
    return f"{m:.1f}" + (f" ± {h:.1f}" if len(v) > 1 else "")


def ensemble_step(members):
    """The Bullet step (s) of an ensemble's records (summary bullet_step_s), None unless they share one."""
    steps = {rec["summary"].get("bullet_step_s") for _, rec in members.values()}
    return steps.pop() if len(steps) == 1 and None not in steps else None


def cap_counts(records):
    """(k, n): of the n records that describe their window's largest steps (aggregate.largest_steps), the k whose
    largest load fell at a step whose solve reached its cap (an island handed over there, or left capped)."""
    steps = [rec.get("window", {}).get("largest_steps") for rec in records]
    steps = [s[0] for s in steps if s]
    return sum(bool(s.get("handovers")) or bool(s.get("capped")) for s in steps), len(steps)


def at_the_cap(records):
    """cap_counts as "k/n"; "n/a" when no record describes its largest steps."""
    k, n = cap_counts(records)
    return f"{k}/{n}" if n else "n/a"


# how near an overloaded break (aggregate.sheet_record) a start's largest load must fall to be its: a zone bears its
# overload at the break's step and the few before, while the sheet stands
OVERLOAD_WITHIN_S = 0.1


def at_an_overload(records):
    """(k, n): of the n records that describe both their window's largest step and their sheet's overloaded breaks,
    the k whose largest load fell within OVERLOAD_WITHIN_S of a break whose zone bore more than aggregate.OVERLOAD
    times its breaking load."""
    k = n = 0
    for rec in records:
        steps = (rec.get("window") or {}).get("largest_steps")
        times = (rec.get("sheet") or {}).get("overload_times_s")
        if not steps or times is None:
            continue
        n += 1
        k += any(abs(t - steps[0]["time_s"]) <= OVERLOAD_WITHIN_S + 1e-9 for t in times)
    return k, n


def configurations(sweep, out):
    """{(scenario, leave_behind m): {start_x: (run, record)}} of the sweep's finished runs."""
    _, runs = spec.load(sweep)
    found = {}
    for r in runs:
        if execute.status(r, out).state != "done":
            continue
        grid = dict(r.grid)
        key = (r.scenario, float(grid.get(LEAVE, 0.0)))
        found.setdefault(key, {})[float(grid.get(START, math.nan))] = (r, agg.load_record(r, out))
    return found


def thickness(run):
    """The run's ice.thickness (m) (spec.run_value); None if its scenario file cannot be read."""
    try:
        return float(spec.run_value(run, "ice.thickness"))
    except (OSError, KeyError, ValueError, tomllib.TOMLDecodeError):
        return None


def lc_h(configs, design_loads):
    """(l_c, h) in m: the characteristic length `icedem cone-load` gives for the sweep's ice, and its
    thickness; None for one that cannot be had."""
    run = next(iter(next(iter(configs.values())).values()))[0]
    loads, _ = design_loads(run)
    return (loads["characteristic_length_m"] if loads else None), thickness(run)


def overload_text(sheets):
    """Of a configuration's starts' sheet records: the breaks a tow whose zone bore more than aggregate.OVERLOAD times
    its breaking load, those of them that broke off no piece in brackets, and the largest ratio over the starts;
    "n/a" for records made before they were kept."""
    if not sheets or any("overloaded" not in s for s in sheets):
        return "n/a | n/a"
    ratios = [s["largest_overload"] for s in sheets if s.get("largest_overload") is not None]
    over = np.mean([s["overloaded"] for s in sheets])
    no_piece = np.mean([s["overloaded_no_piece"] for s in sheets])
    return f"{over:.1f} ({no_piece:.1f}) | {fmt(max(ratios) if ratios else None, digits=1)}"


def underload_text(sheets):
    """Of a configuration's starts' sheet records: the breaks a tow below aggregate.UNDERLOAD times their breaking
    load and the smallest ratio over the starts; "n/a" for records made before they were kept."""
    if not sheets or any("underloaded" not in s for s in sheets):
        return "n/a"
    ratios = [s["smallest_load_ratio"] for s in sheets if s.get("smallest_load_ratio") is not None]
    return f"{np.mean([s['underloaded'] for s in sheets]):.1f} ({fmt(min(ratios) if ratios else None, digits=2)})"


def sheet_table(configs, lengths, intro=True):
    """Where the sheet broke and what it broke into, per configuration: each start's median (its record's
    sheet block, aggregate.sheet_record), averaged over the starts, its overloaded breaks (overload_text) and those
    below their load (underload_text); `intro`: the paragraph that says so first."""
    lc, h = lengths
    L = ["", "Where the sheet broke and what it broke into (each start's median, averaged over its starts): the "
         "crack distance x* of the closed forms (docs/model/breakage.md), against the characteristic length "
         + (f"l_c = {lc:.3f} m" if lc else "l_c") + " and the thickness h" + (f" = {h:.3f} m" if h else "")
         + "; at the JZ20-2 platform's downward 45-degree cones the field's breaking length was about 7 h (Li, Yue, "
         "Shkhinek and Kärnä), of ice whose l_c / h differs from the model ice's. The pieces at the tow's end "
         "(the rigid floes broken off, each split floe counted as its two pieces; pieces smaller than h^2 or "
         "narrower than h are crushed ice and not made): their equivalent diameters sqrt(4 A / pi) and the "
         "area-weighted mean diameter. Overloaded: the breaks a tow whose zone bore more than "
         f"{agg.OVERLOAD:g} times its breaking load (the check follows the step's solve, so a zone passes its load by "
         "what one step adds; further where a cut broke off no piece, in brackets, and the sheet stood: "
         "docs/model/breakage.md, \"A piece's corner on the edge\"), and the largest load over breaking load of the "
         f"starts. Below: the breaks a tow at less than {agg.UNDERLOAD:g} of their breaking load, and the smallest "
         "ratio of the starts (a floe the contact solve held at its patch's bound breaks the sheet after the step, "
         "where the patch its forces then make can plan a higher load: docs/model/breakage.md, \"The edge's bound "
         "in the solve\"; n/a: records made before they were kept). By floes: the breaks a tow a floe's push on the "
         "sheet's edge made, the rest the cone's crushed zone's (n/a: records made before they were kept).", ""
         ] if intro else [""]
    L += ["| run | leave m | starts | breaks a tow | by floes a tow | x* median m | x* / l_c | x* / h | pieces a tow | "
          "diameter median m (quartiles) | area-weighted diameter m | its / l_c | overloaded a tow (no piece) | "
          "largest load / breaking load | below a tow (smallest) |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for (scenario, leave), members in sorted(configs.items()):
        sheets = [rec["sheet"] for _, rec in members.values() if rec.get("sheet")]
        if not sheets:
            continue
        qi = sheets[0]["quantiles"].index(0.5)
        x = np.mean([s["crack_distance_m"][qi] for s in sheets if s["crack_distance_m"]])
        d = [np.mean([s["piece_diameter_m"][qi + k] for s in sheets if s["piece_diameter_m"]]) for k in (-1, 0, 1)]
        w = np.mean([s["area_weighted_diameter_m"] for s in sheets if s.get("area_weighted_diameter_m")])
        by_floe = [s["by_floe"] for s in sheets if s.get("by_floe") is not None]
        by_floe_text = f"{np.mean(by_floe):.0f}" if len(by_floe) == len(sheets) else "n/a"
        L.append(f"| {scenario} | {leave:g} | {len(sheets)} | {np.mean([s['breaks'] for s in sheets]):.0f} | "
                 f"{by_floe_text} | {x:.3f} | {fmt(x / lc if lc else None, digits=2)} | "
                 f"{fmt(x / h if h else None, digits=1)} | "
                 f"{np.mean([s['pieces'] for s in sheets]):.0f} | {d[1]:.3f} ({d[0]:.3f}-{d[2]:.3f}) | {w:.3f} | "
                 f"{fmt(w / lc if lc else None, digits=2)} | {overload_text(sheets)} | "
                 f"{underload_text(sheets)} |")
    return L


def section(sweep, configs, design_loads):
    """The page's lines on the analytic tows of `sweep`, its configurations `configs` (configurations of the sweep);
    design_loads(run) is (`icedem cone-load` of the run, None) or (None, why not)."""
    L = ["## Level ice cut by closed forms", "",
         f"Runs of `{os.path.relpath(sweep, spec.ROOT)}` finished so far: the sheet as one held body cut by closed "
         "forms (docs/model/breakage.md, \"Level ice cut by closed forms\"), its pieces rigid floes, rigid contacts. "
         "The tow is chaotic and the sheet has no random layout, so a configuration's members are the same tow "
         "started a millimetre apart (structure.start_x); its loads are the mean over its starts with Student's "
         "95 % interval (none for one start). leave m: `activation.leave_behind`, the pieces farther than it behind "
         "the cone's axis out of the run (0: none leaves).", ""]
    if not configs:
        return L + ["No finished run yet.", ""]
    L += ["Loads in N, surge, over the analysis window; max 5 Hz: the largest of the load low-passed at 5 Hz (a "
          "rigid contact's largest loads can be single steps of a piece locked between the cone and the held sheet: "
          "the step sets them, not the ice). Max at the cap: of the starts whose records describe their largest "
          "steps, those whose largest load fell at a step whose solve reached its iteration cap (handed over there, "
          "or left capped): a piece locked between the moving cone and the held sheet has no rigid answer, and "
          "the solve runs to its cap.", "",
          "| run | mu | leave m | starts | mean | p99 | max (mean of the starts') | max 5 Hz | largest max | "
          "ISO 19906 | Ralston | largest max / ISO | largest max 5 Hz / ISO | breaks a tow | real time (CPU) | "
          "max at the cap |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for (scenario, leave), members in sorted(configs.items()):
        recs = [rec for _, rec in members.values()]
        run = next(iter(members.values()))[0]
        loads, why = design_loads(run)
        cells = [mean_text(_value(rec, key) for rec in recs) for key in CRITERIA.values()]
        largest = max((_value(rec, "max_fx_N") or 0.0) for rec in recs)
        largest_5 = max((_value(rec, LOWPASS) or 0.0) for rec in recs)
        breaks = np.mean([rec["summary"].get("breaks", 0) for rec in recs])
        rtf = [rec["summary"]["sim_time_s"] / rec["summary"]["cpu_time_s"] for rec in recs
               if rec["summary"].get("cpu_time_s")]
        rtf = fmt(float(np.mean(rtf)) if rtf else None, digits=2)
        if loads:
            iso = loads["total_N"]
            mu = f"{loads['friction']:g}"
            design = [fmt(iso), fmt(loads["ralston_total_N"]), fmt(largest / iso, digits=2),
                      fmt(largest_5 / iso, digits=2)]
        else:
            mu, design = "n/a", [f"n/a ({why})", "n/a", "n/a", "n/a"]
        L.append(f"| {scenario} | {mu} | {leave:g} | {len(recs)} | {' | '.join(cells)} | {largest:.1f} | "
                 f"{' | '.join(design)} | {breaks:.0f} | {rtf} | {at_the_cap(recs)} |")
    L += sheet_table(configs, lc_h(configs, design_loads))
    # leave_behind against none, start by start
    changes, names = {}, {}
    for (scenario, leave), members in sorted(configs.items()):
        base = configs.get((scenario, 0.0))
        if leave == 0.0 or not base:
            continue
        common = sorted(set(members) & set(base))
        for label, key in CRITERIA.items():
            a = [_value(members[s][1], key) for s in common]
            b = [_value(base[s][1], key) for s in common]
            pairs = [(x, y) for x, y in zip(a, b) if x is not None and y is not None]
            if len(pairs) < 2:
                continue
            k = (scenario, leave, label)
            changes[k] = verdict.judged_change([x for x, _ in pairs], [y for _, y in pairs])
            names[k] = f"{scenario}, leave {leave:g} m: {label}"
    L += ["", "What leaving the channel behind does, against the tow without it from the same starts (the log "
          "ratio's change over the starts both ran, its 95 % interval and verdict, docs/model/estimators.md):", ""]
    if not changes:
        return L + ["No pair of starts yet.", ""]
    L += ["| run | leave m | criterion | change | starts |", "|---|---|---|---|---|"]
    for k in sorted(changes):
        d, iv, word, _, n = changes[k]
        L.append(f"| {k[0]} | {k[1]:g} | {k[2]} | {verdict.change_text((d, iv, word))} | {n} |")
    return L + ["", verdict.family_text(changes, lambda k: names[k]), ""]
