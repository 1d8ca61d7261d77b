#!/usr/bin/python3
"""The analytic level tows' section of docs/model/level_ice.md (tools/icedem_tools/studies/level_ice_analytic.py),
on records made here: a configuration's loads are the mean over its starts with Student's interval (mean, p99, max
and the 5 Hz low-passed max, the largest of each over ISO 19906), and how many starts' largest load fell at a step
whose solve reached its cap; leaving the channel behind is judged start by
start against the tow without it (a uniform +10 % moves, by +10.0 %); no finished run says so. A sheet's record
counts the breaks whose zone bore more than twice its breaking load and those of them that broke off no piece, those
a floe's push made, the longest time without a break (to the run's end too) and the breaks at a step whose solve
reached its cap (aggregate.sheet_record), and the sheet table shows them over the starts."""
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
import numpy as np  # noqa: E402
from icedem_tools.sweeps import aggregate, execute  # noqa: E402
from icedem_tools.studies import level_ice_analytic as la  # noqa: E402

SWEEP = """name = "analytic_test"
seeds = 1
[[scenario]]
name = "mu02"
file = "scenarios/level_ice/level_ice_analytic.toml"
[grid]
"structure.start_x" = [5.2, 5.201, 5.202]
"activation.leave_behind" = [0.0, 3.0]
"""

# per start: the tow without leaving behind, and the one leaving at 3 m 10 % higher in every criterion
MEANS = {5.2: 20.0, 5.201: 22.0, 5.202: 24.0}


def record(mean, factor):
    m = mean * factor
    return {"summary": {"mean_fx_N": m, "max_fx_N": 100 * m, "cpu_time_s": 560.0, "sim_time_s": 280.0,
                        "breaks": 500},
            "window": {"p99_fx_N": 3 * m, "max_lowpass_fx_N": {"5": 10 * m, "10": 20 * m},
                       # the largest step handed over at the cap for two starts of three (the mean 24 N start: not)
                       "largest_steps": [{"time_s": 50.0, "surge_N": 100 * m, "iterations": 1000 if mean < 24 else 400,
                                          "handovers": int(mean < 24), "capped": 0}]}}


def design(run):
    return {"friction": 0.2, "total_N": 200.0, "ralston_total_N": 250.0, "characteristic_length_m": 0.379}, None


with tempfile.TemporaryDirectory() as tmp:
    sweep = os.path.join(tmp, "analytic.toml")
    with open(sweep, "w") as f:
        f.write(SWEEP)
    execute.status = lambda run, out: execute.Status(run, "pending")
    text = "\n".join(la.section(sweep, la.configurations(sweep, tmp), design))
    check("No finished run yet" in text, "no finished run: the section says so")

    execute.status = lambda run, out: execute.Status(run, "done")
    la.agg.load_record = lambda run, out: record(MEANS[float(dict(run.grid)[la.START])],
                                                 1.1 if float(dict(run.grid)[la.LEAVE]) == 3.0 else 1.0)
    lines = la.section(sweep, la.configurations(sweep, tmp), design)
    rows = {tuple(c.strip() for c in l.split("|")[1:4]): l for l in lines if l.startswith("| mu02 | 0.2 |")}
    base = rows.get(("mu02", "0.2", "0"))
    # the mean over 20, 22, 24: 22 +- t(0.975, 2) * 2 / sqrt(3) = 4.97
    half = 4.302653 * 2.0 / math.sqrt(3)
    check(base is not None and f"| 3 | 22.0 ± {half:.1f} | 66.0 ± {3 * half:.1f} | 2200.0 ± {100 * half:.1f} | "
          f"220.0 ± {10 * half:.1f} | 2400.0 | 200.0 | 250.0 | 12.00 | 1.20 | 500 | 0.50 | 2/3 |" in base,
          f"the tow's loads over its starts, the largest max and max 5 Hz over ISO: {base}")
    change = [l for l in lines if l.startswith("| mu02 | 3 | max 5 Hz |")]
    check(len(change) == 1 and "+10.0 %" in change[0] and "(moves)" in change[0] and change[0].endswith("| 3 |"),
          f"leaving behind judged start by start, the 5 Hz maximum among the criteria: {change}")
    check(sum(l.startswith("| mu02 | 3 |") for l in lines) == 4, "four criteria judged")
# the overloads of a sheet's breaks: load over breaking load 1.0, 2.5 (2 pieces), 30 (no piece), 1.9, 0.5
breaks = np.zeros(5, dtype=[("time", "f8"), ("crack_distance", "f8"), ("broken_area", "f8"), ("crushed_area", "f8"),
                            ("load", "f8"), ("breaking_load", "f8"), ("pieces", "i4"), ("by_floe", "i4")])
breaks["time"] = [10.0, 20.0, 30.0, 40.0, 50.0]
breaks["load"], breaks["breaking_load"] = [26.0, 65.0, 780.0, 49.4, 13.0], 26.0
breaks["pieces"] = [2, 2, 0, 3, 2]
breaks["by_floe"] = [0, 1, 1, 0, 0]
# the run goes on 25 s past its last break (at 50 s): longer than any gap between breaks (10 s)
run = {"/sheet/breaks": breaks, "/bodies/parent": np.array([-1, -1]), "/load/time": np.array([0.0, 75.0])}
aggregate.pieces.body_areas = lambda run: [0.01, 0.02]
sheet = aggregate.sheet_record(run)
check(sheet["overloaded"] == 2 and sheet["overloaded_no_piece"] == 1 and abs(sheet["largest_overload"] - 30.0) < 1e-9
      and sheet["overload_times_s"] == [20.0, 30.0],
      f"a sheet's overloaded breaks: 2 past twice their breaking load, 1 of them with no piece, the largest 30 x: "
      f"{ {k: sheet[k] for k in ('overloaded', 'overloaded_no_piece', 'largest_overload', 'overload_times_s')} }")
check(sheet["underloaded"] == 1 and abs(sheet["smallest_load_ratio"] - 0.5) < 1e-9,
      f"a sheet's breaks below 0.99 of their breaking load: 1, at 0.5: "
      f"{ {k: sheet[k] for k in ('underloaded', 'smallest_load_ratio')} }")
check(sheet["by_floe"] == 2 and sheet["longest_without_break_s"] == 25.0,
      f"a sheet's breaks by floes: 2; the longest time without one: from the last to the run's end, 25 s: "
      f"{ {k: sheet[k] for k in ('by_floe', 'longest_without_break_s')} }")
run["/load/time"] = np.array([0.0, 55.0])
check(aggregate.sheet_record(run)["longest_without_break_s"] == 10.0,
      "the longest time without a break between two breaks (10 s) where the run ends 5 s after its last")
check(sheet["at_cap"] is None, "no per-step diagnostics, no count of the breaks at the solve's cap")
# steps every 10 s; the steps of 20 s (a floe's break) and 50 s (the cone's) handed an island over at the cap, the
# step of 60 s (no break) left one capped: 1 floe's break and 2 breaks at the cap, 3 of 7 steps
run["/load/time"] = np.arange(7) * 10.0
run["/diagnostics/handovers"] = np.array([0, 0, 1, 0, 0, 2, 0])
run["/diagnostics/solver_capped"] = np.array([0, 0, 0, 0, 0, 0, 1])
cap = aggregate.sheet_record(run)["at_cap"]
check(cap == {"by_floe": 1, "breaks": 2, "steps": float(f"{3 / 7:.4g}")},
      f"the breaks at a step whose solve reached its cap: 1 a floe's, 2 of all, 3 of 7 steps: {cap}")
with_sheet = {"summary": {}, "sheet": dict(sheet, quantiles=[0.25, 0.5, 0.75], crack_distance_m=[0.1, 0.2, 0.3],
                                           piece_diameter_m=[0.1, 0.2, 0.3], area_weighted_diameter_m=0.5)}
other = dict(with_sheet, sheet=dict(with_sheet["sheet"], overloaded=4, overloaded_no_piece=0, largest_overload=3.0,
                                    underloaded=0, smallest_load_ratio=0.995, by_floe=4))
rows = [l for l in la.sheet_table({("mu02", 0.0): {5.2: (None, with_sheet), 5.201: (None, other)}}, (0.4, 0.033))
        if l.startswith("| mu02 |")]
check(len(rows) == 1 and rows[0].endswith("| 3.0 (0.5) | 30.0 | 0.5 (0.50) |")
      and rows[0].startswith("| mu02 | 0 | 2 | ") and rows[0].split(" | ")[4] == "3",
      f"the sheet table: breaks by floes a tow over the starts (2 and 4); overloaded breaks a tow (no piece) over the "
      f"starts, the largest ratio of them; those below their load, the smallest ratio: {rows}")
old = dict(other, sheet={k: v for k, v in other["sheet"].items() if k != "by_floe"})
rows = [l for l in la.sheet_table({("mu02", 0.0): {5.2: (None, with_sheet), 5.201: (None, old)}}, (0.4, 0.033))
        if l.startswith("| mu02 |")]
check(len(rows) == 1 and rows[0].split(" | ")[4] == "n/a",
      f"a start whose record has no breaks by floes: n/a, not the other start's alone: {rows}")
finish()
