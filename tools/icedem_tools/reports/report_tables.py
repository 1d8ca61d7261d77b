"""The report's tables: the aggregated rows of a sweep (results.csv) and the records of its
runs, read and formatted for the report (tools/icedem_tools/reports/report.py)."""
import csv
import math
import os

import numpy as np

from ..sweeps import aggregate as agg, execute
from ..runs import spec

FII, FIS = "friction.ice_ice", "friction.ice_structure"


def at_reference(run):
    """Whether a grid run is at the paper's reference friction, f_ii 0.5, f_is 0.2."""
    g = dict(run.grid)
    return g.get(FII) == 0.5 and g.get(FIS) == 0.2
BREAKABLE = ("large_breakable_015", "large_breakable_020")

def read_rows(out):
    with open(os.path.join(out, "results.csv")) as f:
        return list(csv.DictReader(f))

def num(row, key):
    try:
        v = float(row[key])
        return v if math.isfinite(v) else None
    except (TypeError, KeyError, ValueError):
        return None

def fmt(v, unit="", digits=1):
    return "n/a" if v is None else f"{v:.{digits}f}{unit}"

def ci(row, key):
    m, h = num(row, key), num(row, key + "_ci95")
    if m is None:
        return "n/a"
    return f"{m:.1f} ± {h:.1f}" if h is not None else f"{m:.1f}"

def pick(rows, scenario, fii=0.5, fis=0.2):
    """The row of a scenario at the given friction (or its only row); None if absent."""
    cand = [r for r in rows if r["scenario"] == scenario]
    exact = [r for r in cand if (not r.get(FII) or float(r[FII]) == fii) and (not r.get(FIS) or float(r[FIS]) == fis)]
    return (exact or cand or [None])[0]

def grid_mean(rows, scenario, key, **fixed):
    """Mean of `key` over a scenario's rows matching fixed grid values (e.g. fis=0.1)."""
    names = {"fii": FII, "fis": FIS}
    sel = [r for r in rows if r["scenario"] == scenario
           and all(r.get(names[k]) and float(r[names[k]]) == v for k, v in fixed.items())]
    vals = [num(r, key) for r in sel]
    vals = [v for v in vals if v is not None]
    return sum(vals) / len(vals) if vals else None

def grid_values(rows, scenario, key):
    return sorted({float(r[key]) for r in rows if r["scenario"] == scenario and r.get(key)})

def trend(rows, scenario, key, axis):
    """Change of `key` (averaged over the other friction) from the lowest to the highest value
    of `axis`, and whether it rises at every step between."""
    vals = grid_values(rows, scenario, axis)
    if len(vals) < 2:
        return None, None
    name = "fis" if axis == FIS else "fii"
    means = [grid_mean(rows, scenario, key, **{name: v}) for v in vals]
    if any(m is None for m in means):
        return None, None
    return means[-1] - means[0], all(b > a for a, b in zip(means, means[1:]))

def ratio_to_first(rows, r, key):
    """A supplement configuration's value against its first configuration's, formatted."""
    a, b = num(r, key), num(rows[0], key)
    return fmt(a / b if a is not None and b else None, "", 2)

def quantile(values, q):
    """The q-quantile (linear between order statistics), None for no values."""
    return float(np.quantile(values, q)) if len(values) else None

def run_records(runs, out):
    """{scenario: [(run, record dict)]} of the finished runs (tools/icedem_tools/sweeps/aggregate.py)."""
    res = {}
    for r in runs:
        if execute.status(r, out).state == "done":
            res.setdefault(r.scenario, []).append((r, agg.load_record(r, out)))
    return res

def run_summaries(records):
    """{scenario: [(run, summary dict)]} from run_records()."""
    return {s: [(r, rec["summary"]) for r, rec in v] for s, v in records.items()}

def supplement_rows(sweep_file):
    """(name, runs, output directory, results rows or None if not aggregated) of a supplement."""
    name, runs = spec.load(sweep_file)
    out = os.path.join(spec.ROOT, "sweeps", name)
    rows = read_rows(out) if os.path.isfile(os.path.join(out, "results.csv")) else None
    return name, runs, out, rows

def sweep_about(sweep_file):
    """The opening comment of a sweep file, which says what the sweep is for (its command lines left out)."""
    lines = []
    with open(sweep_file) as f:
        for line in f:
            if not line.startswith("#"):
                break  # the opening comment ends at the first key; later comments are on their keys
            if line.startswith("# ") and not line[2:].lstrip().startswith("scripts/"):
                lines.append(line[2:].rstrip())
    return " ".join(lines)
