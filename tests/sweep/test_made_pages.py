#!/usr/bin/python3
"""docs/model/load_budget.md is what scripts/budget makes from the committed records: its tables, its
figure's data and every number of its prose (the spans of tools/icedem_tools/reports/spans.py). The
page is made again into a temporary file, from the records alone, and compared (its date and the run
directory it names aside); a span naming nothing the tool makes is refused. docs/model/tank_maxima.md,
which scripts/tank_maxima makes whole from the paper grid's records, the same; so the paper report's
convergence and flow-model sections, and the flow models' page with the numbers of README.md's and
coupling.md's prose (scripts/flow_models); and the moored cone's stiffness study in docs/model/mooring.md
(scripts/mooring_stiffness), and docs/model/level_ice.md (scripts/level_ice_report)."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import ROOT, check, finish  # noqa: E402
from icedem_tools.reports import spans  # noqa: E402

page = os.path.join(ROOT, "docs", "model", "load_budget.md")
made = open(page).read()
check(len(spans.keys(made)) > 50, f"the page's prose has its numbers in spans ({len(spans.keys(made))})")


def undated(text):
    return re.sub(r"Made \d{4}-\d\d-\d\d by `scripts/budget` from (\d+) of (\d+) runs of `([^`]*)` in `[^`]*`",
                  r"Made by `scripts/budget` from \1 of \2 runs of `\3`", text)


with tempfile.TemporaryDirectory() as d:
    out, figure = os.path.join(d, "load_budget.md"), os.path.join(d, "load_budget.png")
    shutil.copy(page, out)
    budget = os.path.join(ROOT, "scripts", "budget")
    p = subprocess.run([budget, "--out", os.path.join(d, "no_runs"), "--report", out, "--figure", figure],
                       capture_output=True, text=True)
    check(p.returncode == 0 and undated(open(out).read()) == undated(made),
          "the page is what scripts/budget makes from the committed records")
    open(out, "w").write(made.replace("<!-- = large_rigid | added mass | max -->",
                                      "<!-- = large_rigid | added mass | maxx -->", 1))
    p = subprocess.run([budget, "--out", os.path.join(d, "no_runs"), "--report", out, "--figure", figure],
                       capture_output=True, text=True)
    check(p.returncode != 0 and "large_rigid | added mass | maxx" in p.stderr,
          f"a span naming nothing the tool makes is refused: {p.stderr.strip()[-120:]}")

with tempfile.TemporaryDirectory() as d:
    page = os.path.join(ROOT, "docs", "model", "tank_maxima.md")
    out = os.path.join(d, "tank_maxima.md")
    p = subprocess.run([os.path.join(ROOT, "scripts", "tank_maxima"), "--report", out,
                        "--figure", os.path.join(d, "tank_maxima.png")], capture_output=True, text=True)
    check(p.returncode == 0 and open(out).read() == open(page).read(),
          "docs/model/tank_maxima.md is what scripts/tank_maxima makes from the paper grid's records")

# the paper report's convergence section (scripts/report, from the grid's, the convergence sweep's and
# its supplements' records), each change labelled with the two steps it compares
from icedem_tools.runs import spec  # noqa: E402
from icedem_tools.reports.report_sweeps import convergence_section  # noqa: E402
from icedem_tools.reports.report_tables import run_records, supplement_rows  # noqa: E402
_, grid = spec.load(os.path.join(ROOT, "sweeps", "paper_grid.toml"))
records = run_records(grid, os.path.join(ROOT, "sweeps", "paper_grid"))
supplements = [(f, *supplement_rows(f)) for f in (os.path.join(ROOT, "sweeps", "paper_tolerance.toml"),
                                                   os.path.join(ROOT, "sweeps", "paper_tolerance_rest.toml"))]
section = convergence_section(os.path.join(ROOT, "sweeps", "paper_convergence.toml"), records, supplements=supplements)
report = open(os.path.join(ROOT, "docs", "paper_reproduction", "report.md")).read().split("\n")
at = report.index("## Convergence of the grid's loads")
check(report[at:at + len(section)] == section,
      "the paper report's convergence section is what scripts/report makes from the records")
check(any("dt_half (0.01 s against 0.01 s)" in line for line in section),
      "the 0.15 m lattices' dt_half is labelled as the step it is: 0.01 s against the grid's 0.01 s")

# the flow models over seeds (scripts/flow_models, from the flow sweep's and the grid's records): its page,
# the numbers of README.md's and coupling.md's prose, and the paper report's section of the same table
with tempfile.TemporaryDirectory() as d:
    page = os.path.join(ROOT, "docs", "coupling", "flow_models_seeds.md")
    prose = [os.path.join(ROOT, "README.md"), os.path.join(ROOT, "docs", "model", "coupling.md")]
    out = os.path.join(d, "flow_models_seeds.md")
    shutil.copy(page, out)
    copies = [os.path.join(d, f"{i}_{os.path.basename(x)}") for i, x in enumerate(prose)]
    for x, c in zip(prose, copies):
        shutil.copy(x, c)
    p = subprocess.run([os.path.join(ROOT, "scripts", "flow_models"), "--report", out, "--pages", *copies],
                       capture_output=True, text=True)
    check(p.returncode == 0 and open(out).read() == open(page).read(),
          "docs/coupling/flow_models_seeds.md is what scripts/flow_models makes from the records")
    for x, c in zip(prose, copies):
        check(len([k for k in spans.keys(open(x).read()) if k.startswith("flow |")]) >= 6
              and open(c).read() == open(x).read(),
              f"{os.path.relpath(x, ROOT)}: the flow models' numbers in its prose are what scripts/flow_models makes")
# the moored cone's stiffness study (scripts/mooring_stiffness, from its records and the grid's): the table
# and every number of docs/model/mooring.md's prose about it
with tempfile.TemporaryDirectory() as d:
    page = os.path.join(ROOT, "docs", "model", "mooring.md")
    out = os.path.join(d, "mooring.md")
    shutil.copy(page, out)
    p = subprocess.run([os.path.join(ROOT, "scripts", "mooring_stiffness"), "--report", out,
                        "--figure", os.path.join(d, "mooring_stiffness.png")], capture_output=True, text=True)
    check(p.returncode == 0 and open(out).read() == open(page).read()
          and len([k for k in spans.keys(open(page).read()) if k.startswith("mooring |")]) >= 8,
          f"docs/model/mooring.md's study is what scripts/mooring_stiffness makes from the records {p.stderr[-200:]}")
# the level tows against ISO 19906 and Ralston (scripts/level_ice_report, from the level-ice sweeps' records, the
# lattice's and the analytic sheet's with its halved step, crushing law, tighter solve, crushing against the sheet's
# edge, ladder of solves and thickness and speed
# (their runs looked for in an empty directory: the records alone), and the build's `icedem cone-load`):
# docs/model/level_ice.md whole
with tempfile.TemporaryDirectory() as d:
    out = os.path.join(d, "level_ice.md")
    p = subprocess.run([os.path.join(ROOT, "scripts", "level_ice_report"),
                        os.path.join(ROOT, "sweeps", "studies", "level_ice.toml"), "--report", out,
                        "--analytic", os.path.join(ROOT, "sweeps", "studies", "level_ice_analytic.toml"),
                        "--analytic-out", os.path.join(d, "no_runs"),
                        "--step", os.path.join(ROOT, "sweeps", "studies", "level_ice_analytic_step.toml"),
                        "--step-out", os.path.join(d, "no_runs"),
                        "--crushing", os.path.join(ROOT, "sweeps", "studies", "level_ice_analytic_crushing.toml"),
                        "--crushing-out", os.path.join(d, "no_runs"),
                        "--solve", os.path.join(ROOT, "sweeps", "studies", "level_ice_analytic_solve.toml"),
                        "--solve-out", os.path.join(d, "no_runs"),
                        "--sheet-crushing",
                        os.path.join(ROOT, "sweeps", "studies", "level_ice_analytic_sheet_crushing.toml"),
                        "--sheet-crushing-out", os.path.join(d, "no_runs"),
                        "--solve-ladder",
                        os.path.join(ROOT, "sweeps", "studies", "level_ice_analytic_solve_ladder.toml"),
                        "--solve-ladder-out", os.path.join(d, "no_runs"),
                        "--thickness-speed", os.path.join(ROOT, "sweeps", "studies", "level_ice_thickness_speed.toml"),
                        "--thickness-speed-out", os.path.join(d, "no_runs")],
                       capture_output=True, text=True)
    check(p.returncode == 0 and open(out).read() == open(os.path.join(ROOT, "docs", "model", "level_ice.md")).read(),
          f"docs/model/level_ice.md is what scripts/level_ice_report makes from the records {p.stderr[-200:]}")
from icedem_tools.reports.report_sweeps import flow_section  # noqa: E402
section = flow_section(os.path.join(ROOT, "sweeps", "flow_models.toml"), None)
at = report.index("## Flow models over seeds")
check(report[at:at + len(section)] == section,
      "the paper report's flow models section is what scripts/report makes from the records")
finish()
