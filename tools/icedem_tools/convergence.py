"""Convergence study of the contact solve: do the loads stop depending on the
solver, and at what cost?

    scripts/convergence [--seeds N] [--jobs N] [--icedem PATH] [--out DIR]
                        [--models M ...] [--settings S ...] [--no-brute]
                        [--set KEY=VALUE ...] [--baseline-icedem PATH] [--report-only]

The study is a sweep file, sweeps/studies/convergence.toml: the four paper
models on short fields (scenarios/bench/*_short.toml) are its scenarios, the
candidate solver settings and the references its variants, the tolerances its
[study] table. The references: the converged solve (tolerance 1e-3, a cap of
160 sweeps: 4x the cap of the paper-cost candidates) at dt/2 (two substeps)
for rigid floes and at dt for breakable floes (their joints are calibrated for
a 0.02 s Bullet step, docs/model/convergence.md), and Bullet's own solver at
1000 contact sweeps. This script runs the sweep as `scripts/sweep run` does
(GNU parallel, one directory per run, finished runs reused) and reports; the
runs can as well be made by `scripts/sweep run` or `scripts/sweep slurm` on
that file and reported here with --report-only.

Per model and setting, over the seeds: the mean surge load, the 99th
percentile of the surge series over the analysis window, the mean of the
seeds' maxima with its 95 % confidence interval, the Gumbel location of the
maxima (fit by moments), breaks per run with a 95 % interval, the CPU time
per run (icedem's cpu_time_s) and its ratio to the "paper" setting (10 Bullet
sweeps) of the same session. A setting is within tolerance when its mean is
within 5 %, its p99 and mean of maxima within 10 % of the reference, and its
breaks per run inside the reference's 95 % interval.

Runs are kept in DIR/runs with --out DIR, else in sweeps/convergence (where
`scripts/sweep run` puts them; not committed). --set adds a scenario key to
every run (give it its own --out). Writes DIR/convergence.md and .png (with
--out) or bench/results/convergence-<date>.{md,png}.
"""
import argparse
import datetime
import os
import sys
import tomllib

import numpy as np

from . import aggregate as agg, execute, results, runner, spec
from . import pareto as pareto_plot
from .spec import ROOT

STUDY_FILE = os.path.join(ROOT, "sweeps", "studies", "convergence.toml")
with open(STUDY_FILE, "rb") as _f:
    STUDY = tomllib.load(_f)["study"]
BASELINE, REFERENCE, BRUTE = STUDY["baseline"], STUDY["reference"], STUDY["brute"]
REFERENCES = (REFERENCE, BRUTE)  # the variants the candidates are judged against
MEAN_TOLERANCE, PEAK_TOLERANCE = STUDY["mean_tolerance"], STUDY["peak_tolerance"]


def window_loads(summary, t_end=None):
    """Mean, 99th percentile and max of the surge load over the run's analysis
    window, or over the part of it before t_end (s)."""
    run = results.load_run(os.path.join(summary["run_dir"], runner.RUN_FILES["h5"]))
    t, surge = run["/load/time"], run["/load/surge"]
    end = summary["window_end_s"] if t_end is None else min(t_end, summary["window_end_s"])
    w = (t >= summary["window_start_s"]) & (t <= end)
    if not w.any():
        return float("nan"), float("nan"), float("nan")
    return float(surge[w].mean()), float(np.percentile(surge[w], 99)), float(surge[w].max())


def half_width(values):
    """Half-width of the 95 % confidence interval of the mean (Student's t)."""
    return agg.mean_ci(values)[1]


def ensemble(summaries, t_end=None):
    ok = [s for s in summaries if s.get("status") == "complete" and s.get("mean_fx_N") is not None]
    if not ok:
        return None
    loads = np.array([window_loads(s, t_end) for s in ok])
    mean, p99, peak = loads[:, 0], loads[:, 1], loads[:, 2]
    breaks = np.array([s["breaks"] for s in ok], dtype=float)
    return {"n": len(ok), "failed": len(summaries) - len(ok),
            "message": next((str(s.get("message", "")) for s in summaries if s not in ok), ""),
            "mean": mean.mean(), "mean_hw": half_width(mean),
            "p99": p99.mean(), "max": peak.mean(), "max_hw": half_width(peak),
            "gumbel_u": agg.gumbel_fit(peak)[0], "breaks": breaks.mean(),
            "breaks_hw": half_width(breaks) if breaks.any() else 0.0,
            "cpu": np.mean([s["cpu_time_s"] for s in ok]),
            "rtf": np.mean([s["sim_time_s"] / s["cpu_time_s"] for s in ok]),
            "sweeps": np.mean([s["solver"]["iterations_mean"] for s in ok]),
            "capped": np.mean([s["solver"]["capped_window_fraction"] for s in ok])}


def judge(e, ref):
    """Relative errors against the reference and whether they are within tolerance."""
    err = {k: (e[k] - ref[k]) / ref[k] if ref[k] else float("nan") for k in ("mean", "p99", "max")}
    breaks_ok = abs(e["breaks"] - ref["breaks"]) <= max(ref["breaks_hw"], 1e-12) if ref["breaks"] or e["breaks"] else True
    ok = (abs(err["mean"]) <= MEAN_TOLERANCE and abs(err["p99"]) <= PEAK_TOLERANCE
          and abs(err["max"]) <= PEAK_TOLERANCE and breaks_ok)
    return err, breaks_ok, ok


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, help="seeds per setting (default: the sweep file's)")
    ap.add_argument("--jobs", type=int, default=1, help="parallel runs (CPU times stay comparable)")
    ap.add_argument("--icedem", default=execute.DEFAULT_ICEDEM)
    ap.add_argument("--baseline-icedem", help="run the paper setting with this build instead (e.g. the build "
                    "before the contact solver, for the cost ratio against it)")
    ap.add_argument("--out", help="directory of runs and report (default: sweeps/convergence, bench/results)")
    ap.add_argument("--models", nargs="*", help="scenarios of the sweep file (default: all)")
    ap.add_argument("--settings", nargs="*", help="candidate settings, its variants (default: all)")
    ap.add_argument("--no-brute", action="store_true", help="skip the 1000-sweep references")
    ap.add_argument("--set", dest="extra", action="append", default=[], metavar="KEY=VALUE",
                    help="a scenario key set in every run, candidates and references (e.g. a physics "
                         "variant: ice.contact_crushing=true)")
    ap.add_argument("--report-only", action="store_true", help="report on finished runs, start none")
    a = ap.parse_args(argv)
    try:
        name, runs = spec.load(STUDY_FILE, seeds=a.seeds, extra=a.extra)
    except spec.SweepError as e:
        sys.exit(f"scripts/convergence: {e}")
    models = list(dict.fromkeys(r.scenario for r in runs))
    settings = list(dict.fromkeys(r.variant for r in runs if r.variant not in REFERENCES))
    for given, known, what in ((a.models, models, "model"), (a.settings, settings, "setting")):
        for x in given or ():
            if x not in known:
                sys.exit(f"scripts/convergence: unknown {what} '{x}'; known: {', '.join(known)}")
    runs = [r for r in runs if (not a.models or r.scenario in a.models)
            and (r.variant in REFERENCES or not a.settings or r.variant in a.settings)
            and not (a.no_brute and r.variant == BRUTE)]
    if not a.report_only and not os.access(a.icedem, os.X_OK):
        sys.exit(f"scripts/convergence: no icedem executable at {a.icedem} (build it: scripts/setup.sh)")
    out = a.out or os.path.join(ROOT, "bench", "results")
    runs_dir = os.path.join(a.out, "runs") if a.out else os.path.join(ROOT, "sweeps", name)
    # the paper setting run by another build goes to a directory of its own
    baseline_dir = os.path.join(runs_dir, "baseline-build")
    other = [r for r in runs if a.baseline_icedem and r.variant == BASELINE]
    start = datetime.datetime.now(datetime.timezone.utc)
    if not a.report_only:
        execute.run_parallel([r for r in runs if r not in other], runs_dir, os.path.abspath(a.icedem), a.jobs)
        execute.run_parallel(other, baseline_dir, os.path.abspath(a.baseline_icedem or a.icedem), a.jobs)
    wall = (datetime.datetime.now(datetime.timezone.utc) - start).total_seconds()
    found = {(r.scenario, r.variant, r.seed): execute.summary(r, baseline_dir if r in other else runs_dir) for r in runs}
    report(a, runs, {k: v for k, v in found.items() if v.get("status") != "pending"}, out, start, wall)


def report(a, runs, found, out, start, wall):
    """The tables, the Pareto plot; `found` holds the summaries of the finished and failed runs."""
    lines, pareto = [], {}
    models = list(dict.fromkeys(r.scenario for r in runs))
    files = {r.scenario: os.path.relpath(r.scenario_file, ROOT) for r in runs}
    sets = {(r.scenario, r.variant): [x for x in r.sets[:-1] if x not in a.extra] for r in runs}
    seeds = sorted({r.seed for r in runs})
    views = [(m, m, None) for m in models]
    for m in models:
        for title, t_end in STUDY.get("windows", {}).get(m, {}).items():
            views.append((m, f"{m}, {title}", t_end))
    for m, title, t_end in views:
        names = list(dict.fromkeys(r.variant for r in runs if r.scenario == m))
        ens = {n: ensemble([found[(m, n, s)] for s in seeds if (m, n, s) in found], t_end) for n in names}
        ref, base = ens.get(REFERENCE), ens.get(BASELINE)
        lines += [f"## {title} (`{files[m]}`)", ""]
        if ref is None or base is None:
            lines += ["Reference or paper setting has no finished run yet.", ""]
            continue
        lines += [f"Reference ({', '.join(sets[(m, REFERENCE)])}), {ref['n']} seeds: mean "
                  f"{ref['mean']:.2f} ± {ref['mean_hw']:.2f} N, p99 {ref['p99']:.2f} N, mean of maxima "
                  f"{ref['max']:.2f} ± {ref['max_hw']:.2f} N (95 %), breaks per run {ref['breaks']:.1f} ± "
                  f"{ref['breaks_hw']:.1f}; {ref['cpu']:.0f} s CPU per run, {100 * ref['capped']:.1f} % of its "
                  f"window's steps capped.", "",
                  "| setting | seeds | mean N | err | p99 N | err | max N (95 %) | err | Gumbel u N | breaks/run | "
                  "sweeps/step | capped | CPU s/run | CPU / paper | within |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        pareto[title] = []
        for n in names:
            e = ens[n]
            if e is None:
                lines.append(f"| {n} | 0 | no finished run |||||||||||||")
                continue
            err, breaks_ok, ok = judge(e, ref)
            ratio = e["cpu"] / base["cpu"]
            failed = f" ({e['failed']} failed)" if e["failed"] else ""
            lines.append(f"| {n} | {e['n']}{failed} | {e['mean']:.2f} | "
                         f"{100 * err['mean']:+.1f} % | {e['p99']:.2f} | {100 * err['p99']:+.1f} % | "
                         f"{e['max']:.2f} ± {e['max_hw']:.2f} | {100 * err['max']:+.1f} % | {e['gumbel_u']:.2f} | "
                         f"{e['breaks']:.1f} ± {e['breaks_hw']:.1f}{'' if breaks_ok else ' (out)'} | "
                         f"{e['sweeps']:.1f} | {100 * e['capped']:.0f} % | {e['cpu']:.1f} | {ratio:.2f} | "
                         f"{'yes' if ok else 'no'} |")
            if n not in REFERENCES:
                pareto[title].append((n, ratio, err, ok))
        good = sorted((p for p in pareto[title] if p[3]), key=lambda p: p[1])
        lines += ["", f"Cheapest setting within tolerance: **{good[0][0]}**, {good[0][1]:.2f} times the paper "
                      f"setting's CPU time." if good else "No candidate is within tolerance.", ""]
    cpu_total = sum(r.get("cpu_time_s", 0.0) for r in found.values())
    header = [f"# Convergence of the contact solve, {start:%Y-%m-%d %H:%M} UTC", "",
              f"Command: `scripts/convergence{f' --seeds {a.seeds}' if a.seeds else ''}{' --out DIR' if a.out else ''}"
              f"{' --no-brute' if a.no_brute else ''}{''.join(' --set ' + x for x in a.extra)}"
              f"{' --baseline-icedem BUILD' if a.baseline_icedem else ''}"
              f"{' --models ' + ' '.join(a.models) if a.models else ''}"
              f"{' --settings ' + ' '.join(repr(x) for x in a.settings) if a.settings else ''}`; "
              f"{len(found)} runs reported, {cpu_total / 3600:.2f} CPU "
              f"hours in all (finished runs are reused; this invocation {wall:.0f} s wall). Errors are relative to "
              f"the converged reference; 'within' is mean within {100 * MEAN_TOLERANCE:.0f} %, p99 and mean of "
              f"maxima within {100 * PEAK_TOLERANCE:.0f} %, breaks per run inside the reference's 95 % interval. "
              f"± are 95 % half-widths over the seeds. CPU times are icedem's per run, comparable within one "
              f"session.", ""]
    text = "\n".join(header + lines)
    print(text)
    stem = "convergence" if a.out else f"convergence-{start:%Y%m%d}"
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, stem + ".md"), "w") as f:
        f.write(text + f"\n\n![Pareto front]({stem}.png)\n")
    pareto_plot.plot({m: [(n, t, max(abs(err["mean"]) / MEAN_TOLERANCE, abs(err["p99"]) / PEAK_TOLERANCE,
                                      abs(err["max"]) / PEAK_TOLERANCE), ok) for n, t, err, ok in points]
                      for m, points in pareto.items()}, os.path.join(out, stem + ".png"),
                     "CPU time / paper setting", "error / tolerance (worst of mean, p99, max)",
                     cost_line=(2.0, "2x the paper's cost"))
    print(f"wrote {os.path.join(out, stem + '.md')} and .png")


if __name__ == "__main__":
    sys.exit(main())
