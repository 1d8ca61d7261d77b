#!/usr/bin/python3
"""scripts/convergence_check (tools/icedem_tools/studies/convergence_check.py): a <model>+<numerics>
sweep judged on its own runs: each model's numerics against its own "default" (no other sweep
pooled in), scenarios without a "+" left out; no finished run says so; the page is not
written over the sweep file it reads."""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import ROOT, check, finish  # noqa: E402
from icedem_tools.studies import convergence_check  # noqa: E402


SWEEP = """name = "check_test"
seeds = 5
[[scenario]]
name = "lattice+default"
file = "scenarios/examples/short_tow.toml"
[[scenario]]
name = "lattice+dt_half"
file = "scenarios/examples/short_tow.toml"
set = ["time.substeps=2"]
[[scenario]]
name = "unpaired_name"
file = "scenarios/examples/short_tow.toml"
"""


def summary(mean, peak, breaks):
    return {"mean_fx_N": mean, "max_fx_N": peak, "breaks": breaks, "breaks_by_mechanism": {},
            "cpu_time_s": 100.0, "solver": {"iterations_mean": 150.0}}


with tempfile.TemporaryDirectory() as tmp:
    sweep = os.path.join(tmp, "check.toml")
    with open(sweep, "w") as f:
        f.write(SWEEP)
    # no finished run
    convergence_check.report_sweeps.finished_summaries = lambda runs, out: {}
    text = "\n".join(convergence_check.page(sweep, os.path.join(tmp, "runs")))
    check("No finished run" in text, "no finished run: the page says so")
    # dt/2 doubles every seed's breaks and raises the max by 40 % in every seed
    scatter = {1: 0.8, 2: 1.3, 3: 1.0, 4: 0.9, 5: 1.1}
    runs = {"lattice+default": {s: summary(15 * k, 60 * k, 4) for s, k in scatter.items()},
            "lattice+dt_half": {s: summary(15 * k, 84 * k, 8) for s, k in scatter.items()},
            "unpaired_name": {s: summary(99, 999, 0) for s in scatter}}
    convergence_check.report_sweeps.finished_summaries = lambda r, out: runs
    text = "\n".join(convergence_check.page(sweep, os.path.join(tmp, "runs")))
    check("| lattice | default | 5 | 4.0 |" in text and "| lattice | dt_half | 5 | 8.0 |" in text,
          "the cost table has each numerics of the model, its breaks per run")
    check("unpaired_name" not in text, "a scenario without <model>+<numerics> is left out")
    check("count here too" not in text, "the page does not claim other sweeps' runs")
    rows = [line for line in text.splitlines() if line.startswith("| lattice max load")]
    check(len(rows) == 1 and "**beyond**" in rows[0] and "+40 %" in rows[0],
          f"the max moved by 40 % in every seed is beyond its tolerance: {rows}")
    # against dt/2 as the baseline, the scenario's default is 40 % / 1.4 lower: -29 %
    text = "\n".join(convergence_check.page(sweep, os.path.join(tmp, "runs"), baseline="dt_half"))
    rows = [line for line in text.splitlines() if line.startswith("| lattice max load")]
    check('Baseline: "dt_half"' in text and len(rows) == 1 and "-29 %" in rows[0] and "scenario_default" in rows[0],
          f"--baseline judges the other numerics against it: {rows}")
    text = "\n".join(convergence_check.page(sweep, os.path.join(tmp, "runs"), baseline="dt_tenth"))
    check('No finished run of the baseline numerics "dt_tenth"' in text, "a baseline without runs: the page says so")
    # the guard: the page is not written over the sweep file
    r = subprocess.run([os.path.join(ROOT, "scripts", "convergence_check"), sweep, "--report", sweep],
                       capture_output=True, text=True)
    check(r.returncode == 2 and "--report" in r.stderr, f"--report onto the sweep file is refused: {r.stderr.strip()}")
    with open(sweep) as f:
        check(f.read() == SWEEP, "the sweep file is untouched")

finish()
