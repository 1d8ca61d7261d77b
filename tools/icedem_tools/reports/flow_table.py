"""The flow models over seeds against the analytic flow, from the records: each model's mean and max
over the seeds with their 95 % intervals, each change against the analytic flow paired seed by seed by
the project's one rule (stats/verdict.py), the family's multiplicity statement, and what the pages'
spans ("flow | ...") name. The paper report's "Flow models over seeds" (report_sweeps.flow_section)
and scripts/flow_models (studies/flow_models.py) print it."""
import json
import os

from ..runs import spec
from ..runs.spec import ROOT
from ..stats import verdict
from ..stats.intervals import mean_ci
from ..sweeps import aggregate as agg
from .report_tables import at_reference

GRID_SWEEP = os.path.join(ROOT, "sweeps", "paper_grid.toml")
MODELS = [("analytic", "analytic potential flow (the default; the paper grid's runs)"),
          ("still_water", "still water"), ("openfoam_field", "OpenFOAM, field mode"),
          ("openfoam_probe", "OpenFOAM, probe mode")]
CRITERIA = [("mean", "mean_fx_N"), ("max", "max_fx_N")]


def summaries(runs):
    """{seed: summary} of the `runs` whose kept records say they finished."""
    out = {}
    for r in runs:
        if r.record_file and os.path.isfile(r.record_file):
            s = json.load(open(r.record_file))["summary"]
            if agg.finished(s):
                out[r.seed] = s
    return out


def solve_of(s):
    """The contact solve a run was made with, as the pages name it."""
    v = s.get("solver", {})
    return f"{v.get('method', 'pgs')} to {v.get('tolerance')}"


def facts(flow_sweep):
    """Each model's runs (the flow sweep's scenarios, the paper grid's small_rigid runs at the reference
    friction for the analytic flow), means and changes against the analytic flow over the seeds both
    ran. Raises spec.SweepError for a sweep file that cannot be read."""
    _, flow_runs = spec.load(flow_sweep)
    _, grid = spec.load(GRID_SWEEP)
    runs = {"analytic": summaries([r for r in grid if r.scenario == "small_rigid" and at_reference(r)])}
    for model, _ in MODELS[1:]:
        runs[model] = summaries([r for r in flow_runs if r.scenario == model])
    ref = runs["analytic"]
    f = {"runs": runs, "means": {}, "changes": {}}
    for model, _ in MODELS:
        for name, key in CRITERIA:
            f["means"][(model, name)] = mean_ci([s[key] for s in runs[model].values()])
        if model == "analytic":
            continue
        seeds = sorted(set(runs[model]) & set(ref))
        for name, key in CRITERIA:
            if len(seeds) < 2:
                continue
            a = [runs[model][x][key] for x in seeds]
            b = [ref[x][key] for x in seeds]
            f["changes"][(model, name)] = verdict.judged_change(a, b)
    f["solves"] = sorted({solve_of(s) for r in runs.values() for s in r.values()})
    return f


def table(f):
    L = ["| flow model | seeds | mean N | max N | mean against the analytic flow | max against it | CPU per run s (as recorded, on its machine's load) |",
         "|---|---|---|---|---|---|---|"]
    for model, label in MODELS:
        r = f["runs"][model]
        cells = []
        for name, _ in CRITERIA:
            c = f["changes"].get((model, name))
            cells.append(verdict.change_text(c[:3]) if c else "")
        cpu = sum(s.get("cpu_time_s", 0) for s in r.values()) / len(r) if r else float("nan")
        m, x = f["means"][(model, "mean")], f["means"][(model, "max")]
        L.append(f"| {label} | {len(r)} | {m[0]:.2f} ± {m[1]:.2f} | {x[0]:.1f} ± {x[1]:.1f} | {cells[0]} | {cells[1]} | "
                 f"{cpu:.0f} |")
    return L


def multiplicity(f):
    return verdict.family_text(f["changes"], lambda k: f"{k[0]} {k[1]}")


def resolver(f):
    def resolve(key):
        parts = [x.strip() for x in key.split("|")]
        if parts[0] != "flow":
            raise KeyError(key)
        if parts[1:] == ["solve"]:
            return "; ".join(f["solves"])
        if parts[1:] == ["multiplicity"]:
            return multiplicity(f)
        model, what = parts[1], parts[2]
        if what.endswith(" N"):
            m, h = f["means"][(model, what[:-2])]
            return f"{m:.{2 if what.startswith('mean') else 1}f} ± {h:.{2 if what.startswith('mean') else 1}f} N"
        c = f["changes"].get((model, what))
        if c is None:
            raise KeyError(key)
        return verdict.change_text(c[:3])
    return resolve


def about(f):
    """The paragraph above the table."""
    return ("± is the half-width of the 95 % interval over the seeds; a change is paired seed by seed with the "
            "analytic flow's run of the same layout (the log ratio, docs/model/estimators.md), its 95 % interval in "
            "brackets; \"moves\" when that interval excludes no change, \"unresolved\" when it does not. Contact "
            f"solve of the records: {'; '.join(f['solves'])}.")
