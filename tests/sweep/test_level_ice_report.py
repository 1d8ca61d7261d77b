#!/usr/bin/python3
"""scripts/level_ice_report (tools/icedem_tools/studies/level_ice_report.py): each finished level-ice run
beside the design loads `icedem cone-load` gives for its own scenario and sets (max over ISO and
over Ralston), the breaking lengths' median against 1.11 l_c; no finished run says so; a missing
build is said, not dropped; the page is not written over the sweep file it reads."""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import ROOT, check, finish  # noqa: E402
from icedem_tools.sweeps import execute  # noqa: E402
from icedem_tools.studies import level_ice_report


SWEEP = """name = "level_test"
seeds = 1
[[scenario]]
name = "mu02"
file = "scenarios/level_ice/level_ice_015.toml"
[[scenario]]
name = "mu03"
file = "scenarios/level_ice/level_ice_015.toml"
set = ["friction.ice_structure=0.3"]
[[scenario]]
name = "mu02_step002"
file = "scenarios/level_ice/level_ice_015.toml"
set = ["time.substeps=1"]
"""


def record(mean, peak, distances, pieces=None, held=None, step=None):
    summary = {"mean_fx_N": mean, "max_fx_N": peak, "breaks": len(distances), "cpu_time_s": 400.0,
               "sim_time_s": 200.0}
    if step is not None:
        summary["bullet_step_s"] = step
    if held is not None:
        summary["held_edge_overloads"] = held
        summary["solver"] = {"capped_window_fraction": 0.25}
        summary["breaks_by_mode"] = {"bending": len(distances) - 1, "compression": 0, "shear": 1}
    rec = {"summary": summary, "window": {"p99_fx_N": 0.8 * peak},
           "fracture_events": [{"distance": d} for d in distances]}
    if pieces is not None:
        rec["pieces"] = pieces
    return rec


PIECES = {"pieces": 12, "area_m2": [0.0225, 0.0225, 0.045], "diameter_m": [0.169, 0.169, 0.239],
          "area_weighted_diameter_m": 0.25, "elements_median": 1.0, "single_element_share": 0.55,
          "element_area_m2": 0.0225}


with tempfile.TemporaryDirectory() as tmp:
    sweep = os.path.join(tmp, "level.toml")
    with open(sweep, "w") as f:
        f.write(SWEEP)
    out = os.path.join(tmp, "runs")
    execute.status = lambda run, out: execute.Status(run, "pending")
    text = "\n".join(level_ice_report.page(sweep, out, "/nonexistent/icedem"))
    check("No finished run yet" in text, "no finished run: the page says so")

    execute.status = lambda run, out: execute.Status(run, "done")
    level_ice_report.agg.load_record = lambda run, out: (
        record(40.0, 120.0, [0.1, 0.2, 0.3, 0.4, 0.5], PIECES, 7) if run.scenario == "mu02"
        else record(50.0, 150.0, [], step=0.005) if run.scenario == "mu03"
        else record(50.0, 150.0, []))
    seen = []

    def design(icedem, run):
        seen.append(run.sets)
        mu = 0.3 if "friction.ice_structure=0.3" in run.sets else 0.2
        return {"friction": mu, "total_N": 150.0 if mu == 0.2 else 200.0, "ralston_total_N": 240.0,
                "characteristic_length_m": 0.4}, None

    level_ice_report.design_loads = design
    text = "\n".join(level_ice_report.page(sweep, out, "unused"))
    check(any("friction.ice_structure=0.3" in s for s in seen), "the design loads are asked at the run's own sets")
    row = [line for line in text.splitlines() if line.startswith("| mu02 | 0.2 |")]
    check(len(row) == 1 and "| 0.2 | 0.01 | 40.0 | 96.0 | 120.0 | 150.0 | 240.0 | 0.80 | 0.50 | 5 | 0.50 | 25.0 % |"
          in row[0],
          f"mu 0.2: the scenario's Bullet step (0.02 s in two substeps), max 120 over ISO 150 is 0.80, over "
          f"Ralston 0.50, CPU at half real time, a quarter of the window's steps capped: {row}")
    row = [line for line in text.splitlines() if line.startswith("| mu02_step002 | 0.2 |")]
    check(len(row) == 1 and row[0].startswith("| mu02_step002 | 0.2 | 0.02 |"),
          f"a run's own time.substeps sets its Bullet step: {row}")
    row = [line for line in text.splitlines() if line.startswith("| mu03 | 0.3 |")]
    check(len(row) == 1 and "| 0.3 |" in row[0] and "| 0.75 |" in row[0], f"mu 0.3 against its own ISO load: {row}")
    check(len(row) == 1 and row[0].startswith("| mu03 | 0.3 | 0.005 |"),
          f"a summary's bullet_step_s is the run's step, before the scenario file's (0.01 s): {row}")
    lengths = [line for line in text.splitlines() if line.startswith("| mu02 | 5 |")]
    check(len(lengths) == 1 and "| 0.300 | 0.200-0.400 | 0.68 | 7 | bending 4, shear 1 |" in lengths[0],
          f"breaking lengths: median 0.3 m against 1.11 x 0.4 m, 7 held-edge overloads, the modes that "
          f"broke: {lengths}")
    check(any(line.startswith("| mu03 | 0 | n/a") and line.endswith("| n/a | n/a |") for line in text.splitlines()),
          "a run without breaks says n/a, and n/a held-edge overloads and modes when its summary has none")
    check(any(line.startswith("| mu03 | 0.3 |") and line.endswith("| n/a |") for line in text.splitlines()),
          "a summary without a solver block says n/a capped")
    piece_row = [line for line in text.splitlines() if line.startswith("| mu02 | 12 |")]
    check(len(piece_row) == 1 and "0.0225 (0.0225-0.0450)" in piece_row[0] and "| 55.0 % |" in piece_row[0],
          f"the pieces' row: 12 pieces, median area and quartiles, 55 % in one-element pieces: {piece_row}")
    check(any(line.startswith("| mu03 | n/a |") for line in text.splitlines()),
          "a record kept before pieces were says n/a")

    level_ice_report.design_loads = lambda icedem, run: (None, "no build at nowhere")
    text = "\n".join(level_ice_report.page(sweep, out, "nowhere"))
    check("no design loads (no build at nowhere)" in text, "a missing build is said")

    r = subprocess.run([os.path.join(ROOT, "scripts", "level_ice_report"), sweep, "--report", sweep],
                       capture_output=True, text=True)
    check(r.returncode == 2 and "--report" in r.stderr, f"--report onto the sweep file is refused: {r.stderr.strip()}")
    with open(sweep) as f:
        check(f.read() == SWEEP, "the sweep file is untouched")

finish()
