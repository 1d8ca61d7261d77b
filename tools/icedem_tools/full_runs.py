"""The contact solve judged on the paper's full runs: the default against a reference
at a merit 100 times tighter and half the step, over seeds.

    scripts/full_runs [--out DIR] [--report PATH]

The runs are those of the sweep file sweeps/studies/full_runs.toml (its scenarios:
the paper's small rigid floes and both lattices; its variants: "default", the
reference, and the previous default), made by `scripts/sweep run` into DIR
(default sweeps/full_runs); this script only reads them, so it can report while
the sweep is still running (unfinished runs are counted as pending).

Per scenario and variant, over the finished seeds: the mean surge load over the
analysis window, its 99th percentile, the mean of the seeds' maxima (each with
the half-width of its 95 % confidence interval), breaks per run, the share of the
window's steps whose solve stopped at the cap above tolerance, iterations per
step and CPU time per run. A variant passes against the reference when its mean
is within 3 %, its p99 within 5 %, its mean of maxima within 10 %, and its breaks
per run inside the reference's 95 % interval (the criteria a default must meet; the
confidence intervals say how much of a difference the seeds can resolve).
Writes the tables to the report (default bench/results/full-runs-<date>.md) and
prints them.
"""
import argparse
import datetime
import os
import sys

from . import execute, spec
from .convergence import ensemble
from .spec import ROOT

STUDY_FILE = os.path.join(ROOT, "sweeps", "studies", "full_runs.toml")
REFERENCE = "reference: apgd 1e-5, dt/2"
TOLERANCE = {"mean": 0.03, "p99": 0.05, "max": 0.10}


def judge(e, ref):
    """Relative errors against the reference, whether the breaks lie in its interval, and
    whether every criterion holds."""
    err = {k: (e[k] - ref[k]) / ref[k] if ref[k] else float("nan") for k in TOLERANCE}
    if ref["breaks"] or e["breaks"]:
        breaks_ok = abs(e["breaks"] - ref["breaks"]) <= (ref["breaks_hw"] if ref["n"] > 1 else 0.0)
    else:
        breaks_ok = True
    ok = all(abs(err[k]) <= TOLERANCE[k] for k in TOLERANCE) and breaks_ok
    return err, breaks_ok, ok


def table(name, variants, found):
    lines = [f"### {name}", "",
             "| variant | seeds | mean N | p99 N | mean of maxima N | breaks/run | capped % | iterations/step "
             "| CPU s/run |", "|---|---|---|---|---|---|---|---|---|"]
    stats = {}
    for v in variants:
        runs = found.get(v, [])
        e = ensemble(runs) if runs else None
        pending = sum(1 for s in runs if s.get("status") == "pending")
        if e is None:
            lines.append(f"| {v} | 0 ({pending} pending) | | | | | | | |")
            continue
        stats[v] = e
        lines.append(f"| {v} | {e['n']}{f' ({pending} pending)' if pending else ''} | {e['mean']:.2f} ± "
                     f"{e['mean_hw']:.2f} | {e['p99']:.1f} | {e['max']:.1f} ± {e['max_hw']:.1f} | "
                     f"{e['breaks']:.1f} ± {e['breaks_hw']:.1f} | {100 * e['capped']:.2f} | {e['sweeps']:.1f} | "
                     f"{e['cpu']:.0f} |")
    lines.append("")
    ref = stats.get(REFERENCE)
    if ref:
        lines += ["| against the reference | mean | p99 | mean of maxima | breaks | passes |", "|---|---|---|---|---|---|"]
        for v, e in stats.items():
            if v == REFERENCE:
                continue
            err, breaks_ok, ok = judge(e, ref)
            lines.append(f"| {v} | {100 * err['mean']:+.1f} % | {100 * err['p99']:+.1f} % | {100 * err['max']:+.1f} % | "
                         f"{'in' if breaks_ok else 'outside'} the interval | {'yes' if ok else 'no'} |")
        lines.append("")
    return lines


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", help="the sweep's run directory (default: sweeps/full_runs)")
    ap.add_argument("--report", help="markdown report (default: bench/results/full-runs-<date>.md)")
    a = ap.parse_args(argv)
    try:
        name, runs = spec.load(STUDY_FILE)
    except spec.SweepError as e:
        sys.exit(f"scripts/full_runs: {e}")
    out = a.out or os.path.join(ROOT, "sweeps", name)
    found = {}
    for r in runs:
        found.setdefault(r.scenario, {}).setdefault(r.variant, []).append(execute.summary(r, out))
    variants = list(dict.fromkeys(r.variant for r in runs))
    today = datetime.date.today().isoformat()
    lines = [f"# The contact solve on full runs, {today}", "",
             f"Runs of `{os.path.relpath(STUDY_FILE, ROOT)}` in `{out}`; the criteria: mean within 3 %, p99 within "
             "5 %, mean of maxima within 10 % of the reference, breaks per run inside its 95 % interval. "
             "± is the half-width of the 95 % confidence interval over the seeds.", ""]
    for scenario in dict.fromkeys(r.scenario for r in runs):
        lines += table(scenario, variants, found[scenario])
    text = "\n".join(lines)
    print(text)
    path = a.report or os.path.join(ROOT, "bench", "results", f"full-runs-{today}.md")
    with open(path, "w") as f:
        f.write(text + "\n")
    print(f"wrote {path}")
    return 0
