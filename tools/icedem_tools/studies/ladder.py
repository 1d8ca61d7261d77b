"""Run time against error: a ladder of solver settings and of the skips, each
run over several seeds on the reference scenarios of scenarios/bench/, against
a high-resolution reference (the smallest step with the most iterations).

    scripts/ladder [--quick] [--seeds N] [--jobs N] [--icedem PATH]
                   [--float-icedem PATH] [--out DIR] [--report-only] [REFERENCE ...]

The ladder is a sweep file, sweeps/studies/ladder.toml: the references are its
scenarios, the rungs its variants, the tolerances its [study] table. This script
runs it like `scripts/sweep run` (GNU parallel, one directory per run, finished
runs reused) and reports; the runs can as well be made by `scripts/sweep run` or
`scripts/sweep slurm` on that file and reported here with --report-only.

For every rung and reference it reports, over the seeds: the ensemble mean of
the mean surge load and of the max surge load, the mean break count, and their
errors relative to the reference ensemble; the CPU time and the realtime
factor of one run (icedem's own cpu_time_s), and the CPU time relative to the
default rung (CPU, not wall time: on a shared machine the wall time drifts by
2x within an hour). The reference's own seed scatter (standard error of its
ensemble mean) is printed beside, so an error below it is noise. Skip rungs
turn one skip off (or, for the activation region, on) and one rung turns every
skip off. With a float-precision build (scripts/bench.sh makes one) the default
rung also runs with it.

A rung is accurate when its mean error is within 5 % and its max error within
10 % (the targets of sweeps/studies/ladder.toml); the recommendation is the fastest accurate rung. The
Pareto front (error against CPU time, per reference) goes to a PNG.

Writes bench/results/ladder-<date>.{md,png} (or DIR/ladder.{md,png}); runs are
kept in DIR/runs, or in sweeps/ladder (where `scripts/sweep run` puts them).
--quick (CI): the first reference, one seed, 25 s of tow, four rungs (the
[study] table's quick_*), its runs in DIR/runs or a temporary directory.
"""
import argparse
import datetime
import math
import os
import sys
import tempfile
import tomllib


from ..sweeps import aggregate as agg, execute
from ..runs import output_guard, spec
from ..stats import pareto as pareto_plot
from ..stats import verdict
from ..runs.spec import ROOT

STUDY_FILE = os.path.join(ROOT, "sweeps", "studies", "ladder.toml")
with open(STUDY_FILE, "rb") as _f:
    STUDY = tomllib.load(_f)["study"]
REFERENCE, DEFAULT = STUDY["reference"], STUDY["default"]
FLOAT = "float precision"
MEAN_TOLERANCE, MAX_TOLERANCE = STUDY["mean_tolerance"], STUDY["max_tolerance"]


TOLERANCE = {"mean": MEAN_TOLERANCE, "max": MAX_TOLERANCE}


def ensemble(summaries):
    """A rung's runs over the seeds (aggregate.ensemble: mean and max surge load, breaks per
    run, cost), or {"failed", "message"} if one of them did not finish."""
    ok = [s for s in summaries if agg.finished(s)]
    if len(ok) < len(summaries):
        bad = [s for s in summaries if s not in ok]
        return {"failed": len(bad), "message": str(bad[0].get("message", ""))}
    return agg.ensemble(summaries, lambda s: {"mean": s["mean_fx_N"], "max": s["max_fx_N"], "breaks": s["breaks"]})


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("references", nargs="*", help="reference scenarios (default: all; --quick: the first)")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--seeds", type=int, help="seeds per rung (default: the sweep file's)")
    ap.add_argument("--jobs", type=int, default=1, help="parallel runs (CPU times stay comparable)")
    ap.add_argument("--icedem", default=execute.DEFAULT_ICEDEM)
    ap.add_argument("--float-icedem", default=os.path.join(ROOT, "build-float", "dem", "icedem"),
                    help="a float-precision build (scripts/bench.sh makes one); skipped if absent")
    ap.add_argument("--out")
    ap.add_argument("--report-only", action="store_true", help="report on finished runs, start none")
    a = ap.parse_args(argv)
    try:
        name, runs = spec.load(STUDY_FILE, seeds=1 if a.quick else a.seeds,
                               extra=STUDY["quick_set"] if a.quick else ())
    except spec.SweepError as e:
        sys.exit(f"scripts/ladder: {e}")
    known = list(dict.fromkeys(r.scenario for r in runs))
    a.references = a.references or (STUDY["quick_scenarios"] if a.quick else known)
    unknown = [r for r in a.references if r not in known]
    if unknown:
        sys.exit(f"scripts/ladder: unknown reference {', '.join(unknown)}; known: {', '.join(known)}")
    runs = [r for r in runs if r.scenario in a.references
            and (not a.quick or r.variant in STUDY["quick_variants"] + [REFERENCE])]
    if not a.report_only and not os.access(a.icedem, os.X_OK):
        sys.exit(f"scripts/ladder: no icedem executable at {a.icedem} (build it: scripts/setup.sh)")
    runs_dir = (os.path.join(a.out, "runs") if a.out else tempfile.mkdtemp(prefix="icedem-ladder-") if a.quick
                else os.path.join(ROOT, "sweeps", name))
    float_dir = os.path.join(runs_dir, "float")
    output_guard.guard([("--out", a.out, output_guard.DIRECTORY), ("the runs' directory", runs_dir, output_guard.DIRECTORY)])
    float_runs = [r for r in runs if r.variant == DEFAULT] if not a.quick and os.access(a.float_icedem, os.X_OK) else []
    seeds = sorted({r.seed for r in runs})
    start = datetime.datetime.now(datetime.timezone.utc)
    if not a.report_only:
        execute.run_parallel(runs, runs_dir, os.path.abspath(a.icedem), a.jobs)
        execute.run_parallel(float_runs, float_dir, os.path.abspath(a.float_icedem), a.jobs)
    wall = (datetime.datetime.now(datetime.timezone.utc) - start).total_seconds()
    results = {(r.scenario, r.variant, r.seed): execute.summary(r, runs_dir) for r in runs}
    results.update({(r.scenario, FLOAT, r.seed): execute.summary(r, float_dir) for r in float_runs})
    sets = {(r.scenario, r.variant): r.sets[:-1] for r in runs}
    files = {r.scenario: os.path.relpath(r.scenario_file, ROOT) for r in runs}

    lines, pareto, failures = [], {}, 0
    for ref in a.references:
        names = list(dict.fromkeys(n for (r, n, _) in results if r == ref))
        ens = {n: ensemble([results[(ref, n, s)] for s in seeds]) for n in names}
        r0, d0 = ens[REFERENCE], ens.get(DEFAULT)
        if not r0 or r0.get("failed") or not d0 or d0.get("failed"):
            lines += [f"## {ref}", "", f"reference or default failed: {(r0 or {}).get('message', '')} {d0}", ""]
            failures += 1
            continue
        spread = "" if math.isnan(r0["mean"][1]) else f" ± {r0['mean'][1]:.2f} (95 %)"
        lines += [f"## {ref} ({files[ref]}, {len(seeds)} seed{'s' * (len(seeds) > 1)})", "",
                  f"Reference ({', '.join(sets[(ref, REFERENCE)]) or 'as the file is'}): mean surge "
                  f"{r0['mean'][0]:.2f}{spread} N, max {r0['max'][0]:.2f} N, breaks "
                  f"{r0['breaks'][0]:.1f}, {r0['cpu']:.1f} s CPU per run.", "",
                  "| rung | mean N | change of mean | max N | change of max | breaks | CPU s/run | x real time (CPU) | "
                  "time / default | accurate |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        pareto[ref] = []
        for n in names:
            e = ens[n]
            if e.get("failed"):
                lines.append(f"| {n} | failed ({e['failed']} of {len(seeds)}): {e['message'][:120]} |||||||||")
                continue
            changes, _, overall, _ = verdict.judge(e, r0, TOLERANCE)
            em, ex = changes["mean"][0], changes["max"][0]
            def cell(k):
                return verdict.change_text(changes[k])
            lines.append(f"| {n} | {e['mean'][0]:.2f} | {cell('mean')} | {e['max'][0]:.2f} | {cell('max')} | "
                         f"{e['breaks'][0]:.1f} | {e['cpu']:.1f} | {e['rtf']:.1f} | {e['cpu'] / d0['cpu']:.2f} | "
                         f"{overall} |")
            if n != REFERENCE:
                pareto[ref].append((n, e["cpu"] / d0["cpu"], abs(em), abs(ex), overall == "yes", e["rtf"]))
        accurate = sorted([p for p in pareto[ref] if p[4] and not p[0].startswith(("skip off", "every"))],
                          key=lambda p: p[1])
        lines.append("")
        if accurate:
            best = accurate[0]
            lines.append(f"Recommended (fastest rung within {100 * MEAN_TOLERANCE:.0f} % mean and "
                         f"{100 * MAX_TOLERANCE:.0f} % max): **{best[0]}**, {best[1]:.2f} of the default's "
                         f"time, {best[5]:.1f}x real time on this short scenario.")
        else:
            lines.append("No rung is within the tolerances.")
        every = next((p for p in pareto[ref] if p[0] == "every skip off"), None)
        if every:
            lines.append(f"All skips together: {every[1]:.2f} times the default's run time with them off "
                         f"(the default is {every[1]:.1f}x faster); errors with them off: mean "
                         f"{100 * every[2]:.1f} %, max {100 * every[3]:.1f} %.")
        lines.append("")

    cpu_total = sum(r.get("cpu_time_s", 0.0) for r in results.values())
    header = [f"# Run time against error, {start:%Y-%m-%d %H:%M} UTC", "",
              f"Command: `scripts/ladder{' --quick' if a.quick else ''}"
              f"{'' if a.quick or a.seeds is None else f' --seeds {a.seeds}'}{' --out DIR' if a.out else ''} "
              f"{' '.join(a.references)}`: {len(results)} runs, {cpu_total / 3600:.2f} CPU hours in all (this "
              f"invocation {wall:.0f} s wall; finished runs are reused). Changes are "
              f"relative to the reference, paired seed by seed, with the half-width of their 95 % interval (none "
              f"for one seed); 'accurate' (the project's one rule, stats.verdict.judge) is yes when the whole interval "
              f"is within {100 * MEAN_TOLERANCE:.0f} % (mean) and {100 * MAX_TOLERANCE:.0f} % (max), no when one "
              f"is beyond, else undecided.", ""]
    text = "\n".join(header + lines)
    print(text)
    out_dir = a.out or (runs_dir if a.quick else os.path.join(ROOT, "bench", "results"))
    os.makedirs(out_dir, exist_ok=True)
    stem = "ladder" if a.out or a.quick else f"ladder-{start:%Y%m%d}"
    with open(os.path.join(out_dir, stem + ".md"), "w") as f:
        f.write(text + f"\n\n![Pareto front]({stem}.png)\n")
    pareto_plot.plot({ref: [(n, t, max(em / MEAN_TOLERANCE, ex / MAX_TOLERANCE), ok) for n, t, em, ex, ok, _ in points]
                      for ref, points in pareto.items()}, os.path.join(out_dir, stem + ".png"),
                     "CPU time / default", "error / tolerance (worse of mean and max)",
                     f"tolerance ({100 * MEAN_TOLERANCE:.0f} % mean, {100 * MAX_TOLERANCE:.0f} % max)")
    print(f"wrote {os.path.join(out_dir, stem + '.md')} and .png")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
