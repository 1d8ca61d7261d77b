#!/usr/bin/python3
"""The analytic level tows' comparisons in docs/model/level_ice.md, on records made here:
- an ensemble changed in one thing (tools/icedem_tools/studies/level_ice_against.py: the halved step, the
  crushing law) against the tows without leave_behind, matched by scenario: a uniform +10 % is judged to move
  by +10.0 % over the starts both ran, each ensemble's mean with its step and its count of starts;
- the thickness and speed tows (level_ice_thickness_speed.py): a row per run with its loads over ISO's and its
  crack distance and piece size over l_c, and the figure written;
- which model lies closer to ISO 19906 (level_ice_report.closer_to_iso): the smallest |log ratio| wins,
  a factor above as far as the same factor below;
- why the models lie where they do (level_ice_report.why_below_iso): ISO's terms, the cut sheet's breaks and how
  many starts' largest load fell at an overloaded break;
- the 10 s blocks (level_ice_blocks.py): pooled over the starts, not paired (a crushing ensemble of two starts
  against a rigid one of three is the ratio of the pooled means), the halved step against the crushing tows
  of its own name, never against itself;
- the ladder of solves (level_ice_solve_ladder.py): a row per rung with its step, merit and tolerance, who broke
  the sheet and the loads, and the tightest solve at the default's step and merit told against the default (not
  the halved step's, nor another merit's)."""
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
from icedem_tools.runs import spec  # noqa: E402
from icedem_tools.sweeps import execute  # noqa: E402
from icedem_tools.studies import level_ice_against as against, level_ice_analytic as la  # noqa: E402
from icedem_tools.studies import level_ice_blocks, level_ice_report, level_ice_thickness_speed as ts  # noqa: E402
from icedem_tools.studies import level_ice_solve_ladder as ladder  # noqa: E402

BASE = """name = "base"
seeds = 1
[[scenario]]
name = "mu02"
file = "scenarios/level_ice/level_ice_analytic.toml"
[grid]
"structure.start_x" = [5.2, 5.201, 5.202]
"activation.leave_behind" = [0.0]
"""
CRUSHING = """name = "crushing"
seeds = 1
[[scenario]]
name = "mu02_crushing"
file = "scenarios/level_ice/level_ice_analytic.toml"
set = ["contact.model=\\"crushing\\""]
[grid]
"structure.start_x" = [5.2, 5.201]
"""
STEP = """name = "step"
seeds = 1
[[scenario]]
name = "mu02_crushing"
file = "scenarios/level_ice/level_ice_analytic.toml"
set = ["contact.model=\\"crushing\\"", "time.dt=0.01", "solver.merit=\\"impulse\\"", "solver.merit_tolerance=1e-4"]
[grid]
"structure.start_x" = [5.2, 5.201]
"""
THICKNESS_SPEED = """name = "ts"
seeds = 1
[[scenario]]
name = "mu02"
file = "scenarios/level_ice/level_ice_analytic.toml"
[variants]
slow = ["structure.speed=0.035", "time.duration=560.0"]
fast = ["structure.speed=0.14", "time.duration=140.0"]
[grid]
"ice.thickness" = [0.025, 0.041]
"""
LADDER = """name = "ladder"
seeds = 1
[[scenario]]
name = "mu02_crushing"
file = "scenarios/level_ice/level_ice_analytic.toml"
[variants]
"siconos 1e-3" = []
"siconos 1e-5" = ["solver.merit_tolerance=1e-5"]
"impulse 1e-6" = ["solver.merit=\\"impulse\\"", "solver.merit_tolerance=1e-6"]
"dt 0.01 siconos 1e-6" = ["time.dt=0.01", "solver.merit_tolerance=1e-6"]
"siconos 1e-6 cap 5000" = ["solver.merit_tolerance=1e-6", "solver.method_iterations=5000"]
"sheet crushing, siconos 1e-3" = ["contact.crushing_contacts=\\"structure_and_sheet\\""]
"sheet crushing, siconos 1e-5" = ["contact.crushing_contacts=\\"structure_and_sheet\\"", "solver.merit_tolerance=1e-5"]
"""
MEANS = {5.2: 20.0, 5.201: 22.0, 5.202: 24.0}


def record(mean, step=0.02, capped=None):
    s = {"mean_fx_N": mean, "max_fx_N": 100 * mean, "cpu_time_s": 560.0, "sim_time_s": 280.0, "breaks": 500,
         "bullet_step_s": step}
    if capped is not None:
        s["solver"] = {"capped_window_fraction": capped}
    return {"summary": s, "window": {"p99_fx_N": 3 * mean, "max_lowpass_fx_N": {"5": 10 * mean, "10": 20 * mean}},
            "sheet": {"quantiles": [0.25, 0.5, 0.75], "crack_distance_m": [0.2, 0.3, 0.4],
                      "area_weighted_diameter_m": 0.6, "piece_diameter_m": [0.1, 0.2, 0.3], "breaks": 500,
                      "pieces": 400}}


def design(run):
    h = spec.run_value(run, "ice.thickness") or 0.033
    return {"friction": 0.2, "total_N": 200.0 * h / 0.033, "ralston_total_N": 250.0,
            "characteristic_length_m": 0.3 * (h / 0.033) ** 0.75}, None


with tempfile.TemporaryDirectory() as tmp:
    files = {}
    for name, text in (("base", BASE), ("crushing", CRUSHING), ("step", STEP), ("ts", THICKNESS_SPEED),
                       ("ladder", LADDER)):
        files[name] = os.path.join(tmp, name + ".toml")
        with open(files[name], "w") as f:
            f.write(text)
    execute.status = lambda run, out: execute.Status(run, "pending")
    text = "\n".join(against.section([la.configurations(files["base"], tmp)], files["crushing"],
                                     la.configurations(files["crushing"], tmp), against.CRUSHING,
                                     lambda n: n.removesuffix("_crushing")))
    check("No finished run yet" in text, "no finished run: the comparison says so")

    execute.status = lambda run, out: execute.Status(run, "done")

    def load(run, out):
        start = float(dict(run.grid).get(la.START, 5.2))
        if run.scenario == "mu02_crushing":
            return record(1.1 * MEANS[start], step=0.02, capped=0.05)
        if run.scenario == "mu02" and la.START in dict(run.grid):
            return record(MEANS[start])
        return record(10.0 * (spec.run_value(run, "ice.thickness") / 0.025) * (2.0 if "0.14" in str(run.sets) else 1.0))
    la.agg.load_record = load
    ts.agg.load_record = load

    lines = against.section([la.configurations(files["base"], tmp)], files["crushing"],
                            la.configurations(files["crushing"], tmp), against.CRUSHING,
                            lambda n: n.removesuffix("_crushing"))
    rows = [l for l in lines if l.startswith("| mu02_crushing | mu02 | mean |")]
    half = 4.302653 * 2.0 / math.sqrt(3)
    check(len(rows) == 1 and f"| 0.02 | siconos 0.001 | 22.0 ± {half:.1f} (3) | 0.02 | siconos 0.001 | 23.1 ± " in rows[0]
          and "+10.0 %" in rows[0] and "(moves)" in rows[0] and rows[0].endswith("| 2 |"),
          f"each ensemble's mean with its step and starts, the change over the two starts both ran: {rows}")
    check(sum(l.startswith("| mu02_crushing | mu02 |") for l in lines) == 4, "four criteria compared")
    check(any("5.0 % of their analysis windows' steps stopped at the solve's iteration cap" in l for l in lines),
          "the changed tows' capped steps are told")

    figure = os.path.join(tmp, "ts.png")

    def with_blocks(run, out):  # four blocks whose maxima are 2, 2.4, 1.6 and 2 times the mean: their mean 2 x
        rec = load(run, out)
        m = rec["summary"]["mean_fx_N"]
        rec["window"]["blocks"] = {"block_s": 10.0, "mean_fx_N": [m] * 4, "max_fx_N": [2 * m, 2.4 * m, 1.6 * m, 2 * m],
                                   "max_lowpass_fx_N": {"5": [m] * 4}}
        return rec
    ts.agg.load_record = with_blocks
    lines = ts.section(files["ts"], tmp, design, figure)
    rows = [l for l in lines if l.startswith("| mu02 | 0.2 |")]
    # h = 0.041 at 0.14 m/s: mean 10 * 0.041 / 0.025 * 2 = 32.8 N; ISO 200 * 0.041 / 0.033 = 248.5 N
    fast_thick = [l for l in rows if l.startswith("| mu02 | 0.2 | 0.140 | 0.041 |")]
    iso = 200.0 * 0.041 / 0.033
    lc = 0.3 * (0.041 / 0.033) ** 0.75
    check(len(rows) == 4 and len(fast_thick) == 1
          and "| 32.8 | 98.4 | 3280.0 | 328.0 | 65.6 ± " in fast_thick[0]
          and f"| {iso:.1f} | 250.0 | {32.8 / iso:.2f} | {328.0 / iso:.2f} | {65.6 / iso:.2f} | 500 | "
          f"{lc:.3f} | {0.3 / lc:.2f} | {0.6 / lc:.2f} | 0.50 |" in fast_thick[0],
          f"a row per run, its loads (its blocks' mean maximum) over ISO's and its crack and pieces over l_c: "
          f"{fast_thick}")
    check(os.path.isfile(figure) and os.path.getsize(figure) > 10000 and any("ts.png" in l for l in lines),
          "the figure is written and shown")
    check("Contact law: crushing (contact.model)." in lines,
          "the runs' contact law is said (none --set: the scenario file's, crushing)")

    # the blocks: every run's the same pattern (lag-1 correlation cos 1.3 = 0.27) scaled by its start's mean, the
    # crushing tows' by 1.1, the halved step's by 0.8 of that
    def blocks(mean, n=24):
        w = [1 + 0.2 * math.sin(1.3 * k) for k in range(n)]
        return {"block_s": 10.0, "mean_fx_N": [mean * x for x in w], "max_fx_N": [3 * mean * x for x in w],
                "max_lowpass_fx_N": {"5": [2 * mean * x for x in w]}}

    def load_blocks(run, out):
        rec = load(run, out)
        start = float(dict(run.grid).get(la.START, 5.2))
        halved = "time.dt=0.01" in run.sets
        factor = (1.1 if run.scenario == "mu02_crushing" else 1.0) * (0.8 if halved else 1.0)
        rec["window"]["blocks"] = blocks(factor * MEANS[start])
        rec["summary"]["bullet_step_s"] = 0.01 if halved else 0.02
        return rec
    la.agg.load_record = load_blocks
    configs = {k: la.configurations(files[k], tmp) for k in ("base", "crushing", "step")}
    lines = level_ice_blocks.section([(files[k], configs[k]) for k in ("base", "crushing", "step")],
                                     [(files["crushing"], lambda n: n.removesuffix("_crushing")),
                                      (files["step"], lambda n: n)], design)
    table = [l for l in lines if l.startswith("| mu02")]
    # pooled: rigid over starts 20, 22, 24 (mean 22), crushing 1.1 x over 20, 22 (mean 23.1): +5.0 %, not +10 %
    crushing = [l for l in table if l.startswith("| mu02_crushing | mu02 | block mean |")]
    check(len(crushing) == 1 and "| +5.0 % (" in crushing[0] and crushing[0].endswith("| 72 / 48 |"),
          f"the crushing tows' block mean against the rigid ones', pooled over their starts: {crushing}")
    step = [l for l in table if l.startswith("| mu02_crushing | mu02_crushing |")]
    check(len(step) == 3 and all(l.endswith("| 48 / 48 |") and "| -20.0 % (" in l for l in step),
          f"the halved step against the crushing tows of its name, each criterion -20 %: {step}")
    # the step's tows say how they were solved: the sweep's merit and its tolerance
    lines = against.section([configs["base"], configs["crushing"]], files["step"], configs["step"], against.STEP,
                            lambda n: n)
    mean = [l for l in lines if l.startswith("| mu02_crushing | mu02_crushing | mean |")]
    check(len(mean) == 1 and "| 0.02 | siconos 0.001 | " in mean[0] and "| 0.01 | impulse 0.0001 | " in mean[0],
          f"each side's step and solve: {mean}")
    rows = [l for l in table if ".toml |" in l]
    w = sum(1 + 0.2 * math.sin(1.3 * k) for k in range(24)) / 24  # the pattern's mean
    check(len(rows) == 3 and "| step.toml | crushing | 0.01 | 2 | 48 |" in rows[2]
          and f"| {3 * 22.0 * w:.1f} ± " in rows[0]
          and f"| 200.0 | {3 * 22.0 * w / 200:.2f} | {2 * 22.0 * w / 200:.2f} |" in rows[0],
          f"a row an ensemble: its law, step, starts, blocks, the block maxima over ISO's: {rows}")

    lattice = [("r12", 0.2, {"mean": 0.5, "max": 0.7}), ("r20", 0.2, {"mean": 0.4, "max": 0.9})]
    lines = level_ice_report.closer_to_iso(lattice, [("rigid", {(0.2, "mean"): 1.9, (0.2, "max"): 3.0}),
                                                     ("crushing", {(0.2, "mean"): 0.6, (0.2, "max"): 1.05})])
    mean = [l for l in lines if l.startswith("| 0.2 | mean |")]
    mx = [l for l in lines if l.startswith("| 0.2 | max |")]
    # mean: |log 0.6| = 0.51 < |log 1.9| = 0.64, |log 0.5| = 0.69; max: |log 1.05| = 0.05 is the smallest
    check(mean == ["| 0.2 | mean | r12 0.50, r20 0.40 | 1.90 | 0.60 | cut sheet, crushing |"],
          f"a factor below is as far as the same factor above: {mean}")
    lines = level_ice_report.closer_to_iso(lattice, [("rigid", {(0.2, "max"): 3.0})])
    check([l for l in lines if l.startswith("| 0.2 | max |")] == ["| 0.2 | max | r12 0.70, r20 0.90 | 3.00 | "
                                                                "lattice r20 |"], "the lattice's closest run named")
    check(mx and mx[0].endswith("| cut sheet, crushing |"), f"the closest of all: {mx}")
    lines = level_ice_report.closer_to_iso(lattice, [("rigid", {(0.2, "mean"): 1.9, (0.2, "max"): 3.0})])
    # mean: |log 1.9| = 0.64 < |log 0.5| = 0.69, the cut sheet; max: |log 0.9| = 0.11, the lattice
    check("Of the 2 criteria and frictions compared, the closest: cut sheet, rigid 1, the lattice 1." in lines,
          f"the closest counted: {lines[-2]}")

    # why: ISO's terms, the cut sheet's breaks (a metre of tow, crack over l_c, the zone's force), the ratios inside
    # the lattice's range
    iso = {0.2: {"friction": 0.2, "total_N": 200.0, "breaking_N": 150.0, "crack_width_m": 2.0,
                  "characteristic_length_m": 0.4}}
    rec = record(20.0)
    rec["fracture_events"] = [{"floe": -1, "touching_structure": 1, "structure_force": f} for f in (30.0, 50.0, 70.0)]
    rec["fracture_events"] += [{"floe": 3, "touching_structure": 1, "structure_force": 900.0},  # a piece's split
                               {"floe": -1, "touching_structure": 0, "structure_force": 0.0}]  # a floe's patch
    # the start 5.2's largest load 0.08 s after a break that bore past twice its breaking load, 5.201's 0.5 s after
    # and 5.2's largest step ran to the solve's cap
    late = dict(rec, window=dict(rec["window"], largest_steps=[{"time_s": 50.0, "capped": 1}]),
                sheet=dict(rec["sheet"], overload_times_s=[49.92]))
    early = dict(late, window=dict(rec["window"], largest_steps=[{"time_s": 50.0}]),
                 sheet=dict(rec["sheet"], overload_times_s=[49.5]))
    la.agg.load_record = lambda run, out: late if float(dict(run.grid)[la.START]) == 5.2 else early
    breaking = level_ice_report.sheet_breaking(la.configurations(files["crushing"], tmp), lambda run: (iso[0.2], None))
    check(breaking[0.2][3] == (1, 2), f"1 of 2 starts' largest load within 0.1 s of an overloaded break: {breaking}")
    check(breaking[0.2][4] == (1, 2), f"1 of 2 starts' largest load at a step capped: {breaking}")
    # 500 breaks over 0.07 m/s x 280 s = 19.6 m; crack 0.3 m over l_c 0.4 m; the median of the cone's zones 50 N
    check(list(breaking) == [0.2] and abs(breaking[0.2][0] - 500 / 19.6) < 1e-9 and abs(breaking[0.2][1] - 0.75)
          < 1e-12 and breaking[0.2][2] == 50.0,
          f"the sheet's breaks a metre, crack over l_c, the zone's force: {breaking}")
    lines = level_ice_report.why_below_iso(iso, lattice, [("crushing", {(0.2, "mean"): 0.45, (0.2, "max"): 1.2})],
                                           {"crushing": breaking})
    text = " ".join(lines)
    check("200.0 N: 150.0 N the breaking term" in text and "2.00 m wide, and 50.0 N pushing" in text
          and "broke 26 times a metre of tow, its cracks 0.75 l_c" in text and "median of 50.0 N" in text
          and "0.33 of ISO's breaking term" in text and "is 4.8 times that force" in text
          and "Of its 2 starts, 1 had their largest load within 0.1 s of a break whose zone bore more than 2 times "
              "its breaking load (a floe's push on the sheet's edge within one step" in text
          and "1 of the crushing cut sheet's 2 starts had their largest load at a step whose solve ran to its cap" in text,
          f"ISO's terms and the sheet's breaks told from the records: {text}")
    uncapped = {0.2: breaking[0.2][:4] + ((0, 2),)}
    quiet = " ".join(level_ice_report.why_below_iso(iso, lattice, [("crushing", {(0.2, "mean"): 0.45,
                                                                                (0.2, "max"): 1.2})],
                                                    {"crushing": uncapped}))
    check("ran to its cap" not in quiet, f"no locked starts, no word of them: {quiet}")
    # mean 0.45 lies in the lattice's 0.40-0.50, max 1.2 above its 0.70-0.90
    check("Of the 2 ratios of the cut sheet's ensembles compared, 1 lie within the range" in text
          and ": crushing mean;" in text, f"the ratios within the lattice's spread counted: {text}")

    # the ladder: the default breaks by the cone (2 of 100 by floes), each tighter rung by floes more (by the
    # tolerance's exponent: 1e-5 40, 1e-6 60), its mean 10 % lower and half its window's steps capped; with the
    # sheet's edge crushing too, 1 and 3 of 100
    def rung(run, out):
        tol = float(spec.run_value(run, "solver.merit_tolerance"))
        sheet = spec.run_value(run, "contact.crushing_contacts") == "structure_and_sheet"
        floes = ({1e-3: 1, 1e-5: 3} if sheet else {1e-3: 2, 1e-5: 40, 1e-6: 60})[tol]
        rec = record(30.0 if tol == 1e-3 else 27.0, step=float(spec.run_value(run, "time.dt")),
                     capped=0.01 if tol == 1e-3 else 0.5)
        rec["summary"]["solver"]["iterations_mean"] = 300.0
        rec["summary"]["sim_time_s"] = 45.0
        rec["sheet"].update(breaks=100, by_floe=floes, underloaded=floes // 4, smallest_load_ratio=0.5,
                            longest_without_break_s=2.0 + floes / 4,
                            at_cap={"by_floe": floes // 2, "breaks": floes, "steps": 0.01 if tol == 1e-3 else 0.5})
        return rec
    ladder.agg.load_record = rung
    execute.status = lambda run, out: execute.Status(run, "pending")
    check("No finished run yet." in ladder.section(files["ladder"], tmp, design),
          "no finished rung: the section says so")
    execute.status = lambda run, out: execute.Status(run, "done")
    lines = ladder.section(files["ladder"], tmp, design)
    rows = [l for l in lines if l.startswith("| mu02_crushing |")]
    check(len(rows) == 7 and rows[0] == "| mu02_crushing | 0.2 | 0.02 | siconos | 0.001 | 1000 | ipm | structure | "
          "100 | 2 (2 %) | 0 (0.50) | "
          "2.5 | 30.0 | 90.0 | 300.0 | 1.0 % | 1 of 2 | 300 | 0.08 |"
          and rows[3].startswith("| mu02_crushing | 0.2 | 0.01 | siconos | 1e-06 | 1000 | ipm | structure | 100 | "
                                 "60 (60 %) | 15 (0.50) |")
          and rows[4].startswith("| mu02_crushing | 0.2 | 0.02 | siconos | 1e-06 | 5000 | ipm | structure |")
          and rows[6].startswith("| mu02_crushing | 0.2 | 0.02 | siconos | 1e-05 | 1000 | ipm | structure and sheet | "
                                 "100 | 3 (3 %) |"),
          f"a row per rung: step, merit, tolerance, cap, hand-over, crushing, breaks by floes, below their load, the "
          f"loads: {rows}")
    told = [l for l in lines
            if l.startswith("The default solve against the tightest at its step, merit, cap, hand-over and crushing: ")]
    check(len(told) == 1 and "mu02_crushing (mu 0.2): from siconos 0.001 to siconos 1e-05 at 0.02 s, the breaks by "
          "floes go from 2 of 100 to 40 of 100" in told[0] and "from 2.5 s to 12.0 s" in told[0]
          and "(-10.0 %, one start each)" in told[0]
          and "50 % of the tightest's steps reached the solve's cap, and 20 of its 40 breaks by floes" in told[0]
          and "mu02_crushing (mu 0.2), crushing at structure and sheet: from siconos 0.001 to siconos 1e-05 at 0.02 s, "
              "the breaks by floes go from 1 of 100 to 3 of 100" in told[0],
          f"the tightest at the default's step, merit, cap and crushing (not the halved step's 1e-6, nor the impulse "
          f"merit's, nor the higher cap's; the sheet's crushing against its own default): {told}")
finish()
