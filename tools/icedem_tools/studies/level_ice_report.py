"""Level ice against the design methods: each finished run of a level-ice sweep
(sweeps/studies/level_ice.toml, ice.cover = "level") beside ISO 19906's and Ralston's loads for its
own cone, ice and friction (`icedem cone-load`), and where its sheet broke against the
characteristic-length estimate of the breaking length. Reported, not tuned: the standards' loads
are upper references (ISO's over-predicted 50 field events by a factor of about 1.6).

    scripts/level_ice_report SWEEP.toml [--out DIR] [--icedem PATH] [--report PAGE.md]
                             [--analytic SWEEP.toml [--analytic-out DIR]
                              [--step SWEEP.toml [--step-out DIR]] [--crushing SWEEP.toml [--crushing-out DIR]]
                              [--solve SWEEP.toml [--solve-out DIR]]
                              [--sheet-crushing SWEEP.toml [--sheet-crushing-out DIR]]
                              [--solve-ladder SWEEP.toml [--solve-ladder-out DIR]]
                              [--thickness-speed SWEEP.toml [--thickness-speed-out DIR]]]

--out is the sweep's run directory (default sweeps/<name>); finished runs count (or their kept records), so it
can report while the sweep runs. Without --report the page is printed. --analytic adds the tows of the sheet
cut by closed forms over their starts (studies/level_ice_analytic.py), their runs in --analytic-out (default
sweeps/<its name>); with it, --crushing adds the same tows under the crushing contact law, --step the crushing
tows at a halved step, --solve them solved tighter and --sheet-crushing them crushing against the sheet's edge
too, each against the tows of its scenario's name (studies/level_ice_against.py), all of them also in 10 s
blocks (studies/level_ice_blocks.py), --solve-ladder the crushing tows' first 45 s over a ladder of solves,
who breaks the sheet on each rung (studies/level_ice_solve_ladder.py), and --thickness-speed the tows over ice
thickness and speed with their figure, written beside --report (studies/level_ice_thickness_speed.py); and the
page says which model of level ice, the lattice or the sheet cut by closed forms, lies closer to ISO 19906,
criterion by criterion."""
import os
import tomllib

import numpy as np

from ..sweeps import aggregate as agg, execute
from ..runs import pieces, spec
from . import level_ice_against, level_ice_analytic, level_ice_blocks, level_ice_solve_ladder, level_ice_thickness_speed
from ..reports import report_sweeps
from ..reports.report_tables import fmt


def design_loads(icedem, run):
    """(`icedem cone-load --json` for the run's scenario and --set's, None) or (None, why not)."""
    return execute.cone_load(icedem, run.scenario_file, run.sets)


def bullet_step(run, summary):
    """The run's Bullet step, time.dt / time.substeps (s): its summary's bullet_step_s; for a
    record made before the summary carried it, from its scenario file and its --set's (the
    keys' defaults 0.02 s and 1 where neither gives them); None if the file cannot be read.
    The 0.15 m sheet's loads move with it (docs/model/breakage.md, "Level ice"), so runs at two
    steps are not one sample."""
    if summary.get("bullet_step_s"):
        return float(summary["bullet_step_s"])
    try:
        return spec.bullet_step(run)
    except (OSError, tomllib.TOMLDecodeError):
        return None


def breaking_lengths(record):
    """The horizontal distances (m) of the broken joints from the structure's section at their
    height (/fracture/events distance): how far from the cone the sheet broke."""
    return np.array([e["distance"] for e in record.get("fracture_events", []) if "distance" in e], dtype=float)


def sheet_ratios(configs, design):
    """{(mu, criterion): the analytic tows' mean over their starts over ISO 19906} of the configurations `configs`
    (level_ice_analytic.configurations of a sweep), its tows without leave_behind."""
    ratios = {}
    for (scenario, leave), members in sorted(configs.items()):
        if leave != 0.0:
            continue
        loads, _ = design(next(iter(members.values()))[0])
        if not loads:
            continue
        for label, key in level_ice_analytic.CRITERIA.items():
            v = [x for x in (level_ice_analytic._value(rec, key) for _, rec in members.values()) if x]
            if v:
                ratios[(loads["friction"], label)] = float(np.mean(v)) / loads["total_N"]
    return ratios


def closer_to_iso(lattice, sheets):
    """Which model of level ice lies closer to ISO 19906, per friction and criterion: the lattice's runs
    (`lattice`: [(run, mu, {criterion: value over ISO})]) and the cut sheet's tows (`sheets`: [(name,
    sheet_ratios)]); the closest is the one of smallest |log ratio|."""
    names = [n for n, _ in sheets]
    L = ["## Which model lies closer to ISO 19906", "",
         "Each model's loads over ISO 19906's for its own run (the lattice's runs one by one; the sheet cut by "
         "closed forms as the mean of its starts without leave_behind), criterion by criterion; closest: the "
         "smallest distance on a log scale (a factor 2 above is as far as a factor 2 below). ISO's load is an "
         "upper reference for design, not a measurement: closer is not right.", "",
         "| mu | criterion | lattice runs / ISO | " + " | ".join(f"cut sheet, {n} / ISO" for n in names)
         + " | closest |", "|---|---|---|" + "---|" * len(names) + "---|"]
    order = list(level_ice_analytic.CRITERIA)
    keys = sorted({k for _, r in sheets for k in r}, key=lambda k: (k[0], order.index(k[1])))
    rows, wins = 0, {}
    for mu, label in keys:
        runs = [(name, ratios[label]) for name, m, ratios in lattice if m == mu and ratios.get(label)]
        if not runs:
            continue
        mine = [(n, r.get((mu, label))) for n, r in sheets]
        candidates = [(f"lattice {n}", r) for n, r in runs] + [(f"cut sheet, {n}", r) for n, r in mine if r]
        closest = min(candidates, key=lambda c: abs(np.log(c[1])))[0]
        model = "the lattice" if closest.startswith("lattice") else closest
        wins[model] = wins.get(model, 0) + 1
        L.append(f"| {mu:g} | {label} | {', '.join(f'{n} {r:.2f}' for n, r in runs)} | "
                 + " | ".join("n/a" if r is None else f"{r:.2f}" for _, r in mine) + f" | {closest} |")
        rows += 1
    if not rows:
        return L + ["No friction both models ran at yet.", ""]
    return L + ["", f"Of the {rows} criteria and frictions compared, the closest: "
                + ", ".join(f"{m} {k}" for m, k in sorted(wins.items(), key=lambda w: (-w[1], w[0]))) + ".", ""]


def sheet_breaking(configs, design):
    """{mu: (breaks a metre of tow, crack distance over l_c, force on the zone that broke in N, (k, n) of
    level_ice_analytic.at_an_overload, (k, n) of level_ice_analytic.cap_counts)} of the analytic
    tows of `configs` (as sheet_ratios takes) without leave_behind, each the mean over the starts of the start's
    own: its sheet's breaks over the distance it was towed, its median crack distance, and the median magnitude of
    the cone's force on the zone of the edge whose load broke it (the breaks by the cone, /fracture/events
    structure_force of the sheet's events, floe -1)."""
    found = {}
    for (scenario, leave), members in sorted(configs.items()):
        loads, _ = design(next(iter(members.values()))[0])
        if leave != 0.0 or not loads:
            continue
        per, x, force = [], [], []
        for run, rec in members.values():
            sheet, s = rec.get("sheet"), rec["summary"]
            if not sheet or not s.get("sim_time_s"):
                continue
            per.append(sheet["breaks"] / (float(spec.run_value(run, "structure.speed")) * s["sim_time_s"]))
            if sheet.get("crack_distance_m"):
                x.append(sheet["crack_distance_m"][sheet["quantiles"].index(0.5)] / loads["characteristic_length_m"])
            f = [e["structure_force"] for e in rec.get("fracture_events", [])
                 if e.get("floe") == -1 and e.get("touching_structure") and "structure_force" in e]
            if f:
                force.append(float(np.median(f)))
        if per and x and force:
            recs = [rec for _, rec in members.values()]
            found[loads["friction"]] = (float(np.mean(per)), float(np.mean(x)), float(np.mean(force)),
                                        level_ice_analytic.at_an_overload(recs), level_ice_analytic.cap_counts(recs))
    return found


def why_below_iso(iso, lattice, sheets, breaking):
    """The paragraph on why both models lie where they do against ISO 19906, per friction both ran at: `iso`
    {mu: `icedem cone-load`}, `lattice` and `sheets` as closer_to_iso takes, `breaking` {sheet's name: {mu:
    sheet_breaking's}}. Every number is the records'."""
    L = []
    for mu in sorted(iso):
        d = iso[mu]
        runs = [r for _, m, r in lattice if m == mu]
        mine = [(n, r) for n, r in sheets if any(k[0] == mu for k in r)]
        if not runs or not mine:
            continue

        def span(label):
            v = sorted(r[label] for r in runs if r.get(label))
            return f"{v[0]:.2f}-{v[-1]:.2f}" if v else "n/a"

        def sheet_text(label):
            return ", ".join(f"{n} {r[(mu, label)]:.2f}" for n, r in mine if r.get((mu, label)))

        # the cut sheets whose starts had their largest load at a step the solve ran to its cap on
        locked = [(name, by_mu[mu][4]) for name, by_mu in breaking.items() if mu in by_mu and by_mu[mu][4][0]]
        text = (f"At mu {mu:g}, ISO's load is {d['total_N']:.1f} N: {d['breaking_N']:.1f} N the breaking term, the "
                f"sheet in front of the cone failing in bending at once along one circumferential crack w = D + "
                f"pi^2 l_c / 4 = {d['crack_width_m']:.2f} m wide, and {d['total_N'] - d['breaking_N']:.1f} N pushing "
                "the broken ice up the slope and turning it. It is the peak of a breaking cycle; a tow's mean is over "
                "the cycles, the load falling back after each break, so the means lie far below it in both models "
                f"(over ISO: the lattice's runs {span('mean')}, the cut sheet's {sheet_text('mean')}) and the maxima "
                f"are what compare with it (the lattice's {span('max')}, the cut sheet's {sheet_text('max')}; "
                f"low-passed at 5 Hz {span('max 5 Hz')} and {sheet_text('max 5 Hz')}"
                + "".join(f"; {k} of the {name} cut sheet's {n} starts had their largest load at a step whose solve "
                          "ran to its cap (a piece locked between the cone and the held sheet, above)"
                          for name, (k, n) in locked) + ").")
        for name, by_mu in breaking.items():
            if mu in by_mu:
                per, x, force, (k, n), _ = by_mu[mu]
                largest = dict(mine).get(name, {}).get((mu, "max"))
                text += (f" Neither model fails the front in one crack: the cut sheet ({name}) broke {per:.0f} times "
                         f"a metre of tow, its cracks {x:.2f} l_c from the edge, each break a zone of the front; the "
                         f"cone's force on the zone that broke had a median of {force:.1f} N (its magnitude, surge "
                         f"and heave together), {force / d['breaking_N']:.2f} of ISO's breaking term"
                         + (f", and its maximum (the mean of its starts') is {largest * d['total_N'] / force:.1f} "
                            "times that force" if largest else "") + "."
                         + (f" Of its {n} starts, {k} had their largest load within "
                            f"{level_ice_analytic.OVERLOAD_WITHIN_S:g} s of a break whose zone bore more than "
                            f"{agg.OVERLOAD:g} times its breaking load"
                            + (" (a floe's push on the sheet's edge within one step; what a build bounds of it: "
                               "docs/model/breakage.md, \"A piece's corner on the edge\" and \"The edge's bound in "
                               "the solve\"): those maxima are the model's, not the ice's." if k else ".")
                            if n else ""))
                break
        inside = [(label, n) for n, r in mine for label in level_ice_analytic.CRITERIA
                  if r.get((mu, label)) and any(x.get(label) for x in runs)
                  and min(x[label] for x in runs if x.get(label)) <= r[(mu, label)]
                  <= max(x[label] for x in runs if x.get(label))]
        compared = sum(1 for n, r in mine for label in level_ice_analytic.CRITERIA
                       if r.get((mu, label)) and any(x.get(label) for x in runs))
        text += (f" Of the {compared} ratios of the cut sheet's ensembles compared, {len(inside)} lie within the range "
                 "of the lattice's runs (their spread over element size, lattice shape and step)"
                 + (": " + ", ".join(f"{n} {label}" for label, n in inside) + "; there, which model is the closer is "
                    "a margin inside what the lattice's own discretisation moves, not a difference the runs resolve."
                    if inside else "."))
        L += [text, ""]
    return (["### Why", ""] + L) if L else []


def page(sweep, out, icedem, analytic=None, analytic_out=None, against=(), thickness_speed=None,
         thickness_speed_out=None, figure=None, ladder=None, ladder_out=None):
    """The page's Markdown lines for the sweep file `sweep` with its runs in `out`, and, with `analytic`
    (a sweep file of analytic tows, runs in `analytic_out`), their section, the same tows changed in one thing
    (`against`: [(sweep file, run directory, what, base_of)], the crushing tows first, each against the
    analytic tows and the crushing ones), the ladder of solves (`ladder`, runs in `ladder_out`), the tows over
    thickness and speed (`thickness_speed`, runs in `thickness_speed_out`, their figure written to `figure`), and
    which model lies closer to ISO 19906."""
    name, runs = spec.load(sweep)
    L = [f"# {name}: level ice against ISO 19906 and Ralston", "",
         f"Runs of `{os.path.relpath(sweep, spec.ROOT)}` finished so far (`scripts/level_ice_report`). "
         "Loads over each run's analysis window, surge, N. ISO 19906 (Croasdale and Cammaert) and "
         "Ralston (IEC 61400-3) are `icedem cone-load` for the run's own cone, ice and friction "
         "(dem/validation/iso19906.hpp, ralston.hpp): loads of level ice failing in bending, the "
         "references a designer checks against, with about 40 % between methods and ISO's bias of about "
         "1.6 against field events (docs/model/validation_targets.md, 4a).", ""]
    rows, lengths, piece_rows, lc, lattice, iso_by_mu = [], [], [], None, [], {}
    for r in runs:
        if execute.status(r, out).state != "done":
            continue
        rec = agg.load_record(r, out)
        s, w = rec["summary"], rec.get("window", {})
        loads, why = design_loads(icedem, r)
        lc = loads["characteristic_length_m"] if loads else lc
        d = breaking_lengths(rec)
        lengths.append((r.scenario, d, s.get("held_edge_overloads"), s.get("breaks_by_mode")))
        piece_rows.append((r.scenario, rec.get("pieces")))
        cpu, sim = s.get("cpu_time_s"), s.get("sim_time_s")
        if loads:
            values = {"mean": s.get("mean_fx_N"), "p99": w.get("p99_fx_N"), "max": s.get("max_fx_N"),
                      "max 5 Hz": (w.get("max_lowpass_fx_N") or {}).get("5")}
            iso_by_mu.setdefault(loads["friction"], loads)
            lattice.append((r.scenario, loads["friction"],
                            {k: v / loads["total_N"] for k, v in values.items() if v}))
        step = bullet_step(r, s)
        rows.append([r.scenario, f"{loads['friction']:g}" if loads else "n/a", f"{step:g}" if step else "n/a",
                     s.get("mean_fx_N"), w.get("p99_fx_N"), s.get("max_fx_N"),
                     loads["total_N"] if loads else None, loads["ralston_total_N"] if loads else None,
                     s.get("breaks"), sim / cpu if cpu and sim else None,
                     (s.get("solver") or {}).get("capped_window_fraction"), why])
    if not rows:
        return L + ["No finished run yet.", ""]

    L += ["| run | mu | Bullet step, s | mean | p99 | max | ISO 19906 | Ralston | max / ISO | max / Ralston | breaks "
          "| real time (CPU) | window steps capped |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for name_, mu, step, mean, p99, mx, iso, ral, breaks, rtf, capped, why in rows:
        L.append(f"| {name_} | {mu} | {step} | {fmt(mean)} | {fmt(p99)} | {fmt(mx)} | {fmt(iso)} | {fmt(ral)} | "
                 f"{fmt(mx / iso if mx and iso else None, digits=2)} | {fmt(mx / ral if mx and ral else None, digits=2)} | "
                 f"{breaks} | {fmt(rtf, digits=2)} | {'n/a' if capped is None else f'{100 * capped:.1f} %'} |")
    L += ["", "Window steps capped: the share of the analysis window's steps whose solve stopped at "
          "solver.method_iterations above its merit tolerance (the summary's solver block): the loads of those "
          "steps are not converged, and a run with many of them is labelled so, not corrected. Bullet step: "
          "time.dt / time.substeps; at 0.02 s the 0.15 m sheet's loads fall short of 0.01 s's (docs/model/"
          "breakage.md, \"Level ice\"), so only runs at one step compare."]
    for name_, *_, why in rows:
        if why:
            L.append(f"\n{name_}: no design loads ({why}).")
    L += ["", "Where the sheet broke: the broken joints' horizontal distance from the cone's section at their "
          "height (/fracture/events distance), against the characteristic-length estimate of the breaking "
          "length, pi/(4 beta) = pi sqrt(2) l_c / 4 = 1.11 l_c for a semi-infinite floating beam under an "
          "edge load" + (f" ({1.11 * lc:.3f} m, l_c {lc:.3f} m)" if lc else "") + ". A cone's breaking "
          "front is a wedge, not a beam, and field breaking lengths are shorter. Held-edge overloads: "
          "how often a joint between the free sheet and the held sheet reached its capacity (not broken: the "
          "held sheet's clamp, summary held_edge_overloads); many say the radius is too small.", "",
          "| run | breaks | median m | quartiles m | median / (1.11 l_c) | held-edge overloads | modes |",
          "|---|---|---|---|---|---|---|"]
    for name_, d, held, modes in lengths:
        held = "n/a" if held is None else str(held)
        modes = ", ".join(f"{m} {n}" for m, n in (modes or {}).items() if n) or "n/a"
        if d.size == 0:
            L.append(f"| {name_} | 0 | n/a | n/a | n/a | {held} | {modes} |")
            continue
        q1, med, q3 = np.quantile(d, [0.25, 0.5, 0.75])
        L.append(f"| {name_} | {d.size} | {med:.3f} | {q1:.3f}-{q3:.3f} | "
                 f"{fmt(med / (1.11 * lc) if lc else None, digits=2)} | {held} | {modes} |")
    L += ["", "The pieces broken off the sheet at the run's end (every fragment but the sheet, `scripts/piece_sizes`): "
          "their true areas and equivalent diameters, and the share of the broken-off area in pieces of one "
          "element, the lattice's grain.", ""]
    L += pieces.table(piece_rows)
    L += [""]
    if analytic:
        # one `icedem cone-load` per scenario and --set's: the sections ask again for the same runs
        known = {}

        def design(run):
            key = (run.scenario_file, tuple(run.sets))
            if key not in known:
                known[key] = design_loads(icedem, run)
            return known[key]
        # each sweep's records read once, for every section that shows them
        rigid = level_ice_analytic.configurations(analytic, analytic_out)
        read = [(o, level_ice_analytic.configurations(o, o_out), what, base_of) for o, o_out, what, base_of in against]
        crushed = [c for _, c, what, _ in read if what == level_ice_against.CRUSHING]
        L += level_ice_analytic.section(analytic, rigid, design)
        # each changed ensemble against the tows of its scenario's base name among the analytic and crushing sweeps
        for other, changed_configs, what, base_of in read:
            L += level_ice_against.section([rigid] + crushed, other, changed_configs, what, base_of)
        # the blocks: the rigid tows, then the changed ones in `against`'s order, each against its base
        ensembles = [(analytic, rigid)] + [(o, c) for o, c, _, _ in read]
        comparisons = [(o, base_of) for o, _, _, base_of in read]
        # where the changed tows' sheet broke, a table a sweep (their scenarios share names)
        changed = [(o, c) for o, c in ensembles[1:] if c]
        if changed:
            L += ["### Where the changed tows' sheet broke", "",
                  "As for the tows above (\"Where the sheet broke and what it broke into\"), for each changed sweep."]
            lengths = level_ice_analytic.lc_h(rigid, design) if rigid else (None, None)
            for o, c in changed:
                L += ["", f"`{os.path.relpath(o, spec.ROOT)}`:"]
                L += level_ice_analytic.sheet_table(c, lengths, intro=False)
            L += [""]
        L += level_ice_blocks.section(ensembles, comparisons, design)
        if ladder:
            L += level_ice_solve_ladder.section(ladder, ladder_out, design)
        if thickness_speed:
            L += level_ice_thickness_speed.section(thickness_speed, thickness_speed_out, design, figure)
        sheets = [("rigid", sheet_ratios(rigid, design))] + [("crushing", sheet_ratios(c, design)) for c in crushed]
        L += closer_to_iso(lattice, sheets)
        # the crushing law's breaks first: they are the tows not set by a locked piece
        breaking = {"crushing": sheet_breaking(c, design) for c in crushed[:1]}
        breaking["rigid"] = sheet_breaking(rigid, design)
        L += why_below_iso(iso_by_mu, lattice, sheets, breaking)
    return L


def main(argv=None):
    def options(ap):
        ap.add_argument("--icedem", default=execute.DEFAULT_ICEDEM, help="the build whose `cone-load` gives the "
                        "design loads (default build/dem/icedem)")
        ap.add_argument("--analytic", help="a sweep file of analytic level tows over starts "
                        "(sweeps/studies/level_ice_analytic.toml): their section")
        ap.add_argument("--analytic-out", help="its run directory (default: sweeps/<its name>)")
        ap.add_argument("--step", help="with --analytic: a sweep file of the same tows at a halved step, its scenarios "
                        "named as the tows they are compared with (sweeps/studies/level_ice_analytic_step.toml)")
        ap.add_argument("--step-out", help="its run directory (default: sweeps/<its name>)")
        ap.add_argument("--crushing", help="with --analytic: a sweep file of the same tows under the crushing "
                        "contact law, its scenarios named <analytic scenario>_crushing "
                        "(sweeps/studies/level_ice_analytic_crushing.toml)")
        ap.add_argument("--crushing-out", help="its run directory (default: sweeps/<its name>)")
        ap.add_argument("--solve", help="with --analytic: a sweep file of the crushing tows solved to a tighter merit, "
                        "its scenarios named as the crushing tows (sweeps/studies/level_ice_analytic_solve.toml)")
        ap.add_argument("--solve-out", help="its run directory (default: sweeps/<its name>)")
        ap.add_argument("--sheet-crushing", help="with --analytic: a sweep file of the crushing tows with the floes "
                        "crushing against the sheet's edge too, its scenarios named as the crushing tows "
                        "(sweeps/studies/level_ice_analytic_sheet_crushing.toml)")
        ap.add_argument("--sheet-crushing-out", help="its run directory (default: sweeps/<its name>)")
        ap.add_argument("--solve-ladder", help="with --analytic: a sweep file of the crushing tows' first 45 s over a "
                        "ladder of solves (sweeps/studies/level_ice_analytic_solve_ladder.toml)")
        ap.add_argument("--solve-ladder-out", help="its run directory (default: sweeps/<its name>)")
        ap.add_argument("--thickness-speed", help="with --analytic: a sweep file of analytic tows over thickness and "
                        "speed (sweeps/studies/level_ice_thickness_speed.toml); its figure is written beside --report")
        ap.add_argument("--thickness-speed-out", help="its run directory (default: sweeps/<its name>)")

    def run_dir(sweep_file, given):
        """A sweep file's run directory: the one given, else sweeps/<its name>; None without the file."""
        if not sweep_file:
            return None
        return os.path.abspath(given) if given else os.path.join(spec.ROOT, "sweeps", spec.load(sweep_file)[0])

    def make(sweep, out, args):
        analytic, step, crushing, solve, sheet, ts, ladder = (os.path.abspath(f) if f else None for f in (
            args.analytic, args.step, args.crushing, args.solve, args.sheet_crushing, args.thickness_speed,
            args.solve_ladder))
        if not analytic and (step or crushing or solve or sheet or ts or ladder):
            raise SystemExit("--step, --crushing, --solve, --sheet-crushing, --solve-ladder and --thickness-speed "
                             "compare with the analytic tows: give --analytic too")
        # the crushing tows first: the halved step and the tighter solve are theirs, changed
        against = []
        if crushing:
            against.append((crushing, run_dir(crushing, args.crushing_out), level_ice_against.CRUSHING,
                            lambda name: name.removesuffix("_crushing")))
        if step:
            against.append((step, run_dir(step, args.step_out), level_ice_against.STEP, lambda name: name))
        if solve:
            against.append((solve, run_dir(solve, args.solve_out), level_ice_against.SOLVE, lambda name: name))
        if sheet:
            against.append((sheet, run_dir(sheet, args.sheet_crushing_out), level_ice_against.SHEET_CRUSHING,
                            lambda name: name))
        figure = (os.path.join(os.path.dirname(os.path.abspath(args.report)), "level_ice_thickness_speed.png")
                  if ts and args.report else None)
        return page(sweep, out, args.icedem, analytic, run_dir(analytic, args.analytic_out), against, ts,
                    run_dir(ts, args.thickness_speed_out), figure, ladder, run_dir(ladder, args.solve_ladder_out))
    return report_sweeps.page_command(argv, __doc__, "the sweep file of level-ice runs", make, options)
