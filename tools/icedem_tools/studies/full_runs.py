"""The contact solve judged on the paper's full runs: the default against a reference
at a merit 100 times tighter and half the step, over seeds.

    scripts/full_runs [--out DIR] [--report PATH]

The runs are those of the sweep file sweeps/studies/full_runs.toml (its scenarios:
the paper's small rigid floes and both lattices; its variants: "default", the
reference, the previous default, and for the lattices the default before islands with
joints were solved to 1e-4 and the reference's two changes one at a time), made by `scripts/sweep run` into DIR
(default sweeps/full_runs); this script only reads them, so it can report while
the sweep is still running (unfinished runs are counted as pending).

Per scenario and variant, over the finished seeds: the mean surge load over the
analysis window, its 99th percentile, the mean of the seeds' maxima, for lattices
the failure ratio (fracture_figures below), joints and floes broken per run (each
with the half-width of its 95 % confidence interval), the share of the window's
steps whose solve stopped at the cap above tolerance, iterations per step and CPU
time per run. A variant passes against the reference when its mean is within 3 %,
its p99 within 5 %, its mean of maxima within 10 %, its failure ratio within 5 %,
and its floes break as often as the reference's (breaks_agree; the issue's "breaks
per run inside the reference's 95 % interval", with a test that holds for rare
events: stats.verdict.breaks_agree).
Each difference is judged with its confidence interval by the project's one rule
(stats.verdict.change_verdict): "within" the bound when the whole interval is, "beyond" when
the whole interval is outside, "moves" when it excludes no change but straddles the bound,
else "unresolved" (more seeds needed); a variant passes ("yes") when every criterion is within, fails
("no") when one is beyond or its floes break more or less often, else is "undecided".
Writes the tables to the report (default bench/results/full-runs-<date>.md) and
prints them.
"""
import argparse
import datetime
import os
import sys

from ..sweeps import execute
from ..runs import output_guard, spec
from ..sweeps.aggregate import TOP_FLOES, ensemble, fracture_figures, window_loads
from ..stats.verdict import change_text
from ..stats.verdict import judge as verdict_judge
from ..runs.spec import ROOT

STUDY_FILE = os.path.join(ROOT, "sweeps", "studies", "full_runs.toml")
REFERENCE = "reference: apgd 1e-5, dt/2"
# the issue's criteria, and one for how near the ice came to breaking (see fracture_figures)
TOLERANCE = {"mean": 0.03, "p99": 0.05, "max": 0.10, "ratio": 0.05}
NAMES = {"mean": "mean", "p99": "p99", "max": "mean of maxima", "ratio": "failure ratio"}


def per_run(summary):
    """One finished run's numbers: the window's mean, p99 and max, breaks, floes broken, and for
    lattices the failure ratio (aggregate.fracture_figures)."""
    mean, p99, peak = window_loads(summary)
    ratio, floes = fracture_figures(summary)
    return {"mean": mean, "p99": p99, "max": peak, "breaks": summary["breaks"], "floes_broken": floes,
            "ratio": ratio}


def statistics(runs):
    """The finished runs reduced over seeds (aggregate.ensemble); None without one. The failure
    ratio only where every run has one (lattices)."""
    return ensemble(runs, per_run)


def judge(e, ref):
    """The variant against the reference by stats.verdict.judge with the criteria of TOLERANCE:
    (changes, floes break as often, overall "yes" / "no" / "undecided", seeds paired)."""
    return verdict_judge(e, ref, TOLERANCE)


def table(name, variants, found):
    lines = [f"### {name}", "",
             "| variant | seeds | mean N | p99 N | mean of maxima N | failure ratio | breaks/run | floes broken/run "
             "| capped % | iterations/step | CPU s/run |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    stats = {}
    cell = lambda e, k, f: f"{e[k][0]:{f}} ± {e[k][1]:{f}}" if k in e else ""
    for v in variants:
        runs = found.get(v, [])
        e = statistics(runs) if runs else None
        pending = sum(1 for s in runs if s.get("status") == "pending")
        if e is None:
            lines.append(f"| {v} | 0 ({pending} pending) | | | | | | | | | |")
            continue
        stats[v] = e
        lines.append(f"| {v} | {e['n']}{f' ({pending} pending)' if pending else ''} | {cell(e, 'mean', '.2f')} | "
                     f"{cell(e, 'p99', '.1f')} | {cell(e, 'max', '.1f')} | {cell(e, 'ratio', '.3f')} | "
                     f"{cell(e, 'breaks', '.1f')} | {cell(e, 'floes_broken', '.1f')} | {100 * e['capped']:.2f} | {e['sweeps']:.1f} | {e['cpu']:.0f} |")
    lines.append("")
    ref = stats.get(REFERENCE)
    if ref:
        keys = [k for k in TOLERANCE if k in ref]
        lines += ["| against the reference | seeds paired | " + " | ".join(NAMES[k] for k in keys) +
                  " | breaks | passes |", "|---" * (len(keys) + 4) + "|"]
        for v, e in stats.items():
            if v == REFERENCE:
                continue
            out, breaks_ok, overall, paired = judge(e, ref)
            row = [change_text(out[k]) if k in out else "" for k in keys]
            lines.append(f"| {v} | {paired} | " + " | ".join(row) + f" | {'as often' if breaks_ok else 'more or fewer'} "
                         f"| {overall} |")
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
    today = datetime.date.today().isoformat()
    path = a.report or os.path.join(ROOT, "bench", "results", f"full-runs-{today}.md")
    output_guard.guard([("--report", path, output_guard.FILE)], [STUDY_FILE])
    found = {}
    for r in runs:
        found.setdefault(r.scenario, {}).setdefault(r.variant, []).append(dict(execute.summary(r, out), seed=r.seed))
    lines = [f"# The contact solve on full runs, {today}", "",
             f"Runs of `{os.path.relpath(STUDY_FILE, ROOT)}` in `{out}`; the criteria: mean within 3 %, p99 within "
             "5 %, mean of maxima within 10 % of the reference, floes breaking as often as in the reference (the exact "
             "test of two Poisson rates at 5 %: joints break in clusters, a floe at several), and for "
             f"lattices the failure ratio (the mean of the {TOP_FLOES} largest per-floe load / capacity ratios of a "
             "run) within 5 %. ± is the half-width of the 95 % confidence interval over the seeds; a difference is "
             "paired seed by seed over the seeds both runs have (the log ratio, docs/model/estimators.md), its 95 % "
             "interval in brackets; it is *within* its bound when its whole interval is, "
             "*beyond* when its whole interval is outside, *moves* when it excludes no change but straddles the bound, "
             "else *unresolved* by the seeds.", ""]
    for scenario in dict.fromkeys(r.scenario for r in runs):
        variants = list(dict.fromkeys(r.variant for r in runs if r.scenario == scenario))
        lines += table(scenario, variants, found[scenario])
    text = "\n".join(lines)
    print(text)
    output_guard.write_text(path, text + "\n")
    print(f"wrote {path}")
    return 0
