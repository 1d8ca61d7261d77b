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
maxima (fit by moments), breaks and floes broken per run, the CPU time per run
(icedem's cpu_time_s) and its ratio to the "paper" setting (10 Bullet sweeps) of
the same session. A setting is judged against the reference by the project's one
rule (stats.verdict.judge): within tolerance ("yes") when the whole 95 % interval of
its paired change is within 5 % for the mean and 10 % for the p99 and the mean of
maxima, and its floes break as often as the reference's.

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


from ..sweeps import aggregate as agg, execute
from ..runs import output_guard, spec
from ..stats import pareto as pareto_plot
from ..stats import verdict
from ..stats.intervals import gumbel_fit
from ..runs.spec import ROOT

STUDY_FILE = os.path.join(ROOT, "sweeps", "studies", "convergence.toml")
with open(STUDY_FILE, "rb") as _f:
    STUDY = tomllib.load(_f)["study"]
BASELINE, REFERENCE, BRUTE = STUDY["baseline"], STUDY["reference"], STUDY["brute"]
REFERENCES = (REFERENCE, BRUTE)  # the variants the candidates are judged against
MEAN_TOLERANCE, PEAK_TOLERANCE = STUDY["mean_tolerance"], STUDY["peak_tolerance"]


TOLERANCE = {"mean": MEAN_TOLERANCE, "p99": PEAK_TOLERANCE, "max": PEAK_TOLERANCE}


def ensemble(summaries, t_end=None):
    """A setting's finished runs over the seeds (aggregate.ensemble): the window's mean, p99 and
    max (before t_end, s, if given), breaks and floes broken per run, and the Gumbel location of
    the maxima."""
    def per_run(s):
        mean, p99, peak = agg.window_loads(s, t_end)
        return {"mean": mean, "p99": p99, "max": peak, "breaks": s["breaks"],
                "floes_broken": agg.fracture_figures(s)[1]}
    e = agg.ensemble(summaries, per_run)
    if e:
        e["gumbel_u"] = gumbel_fit(e["runs"]["max"])[0]
    return e


def judge(e, ref):
    """The setting against the reference by the project's one rule (stats.verdict.judge): the mean
    within MEAN_TOLERANCE, p99 and mean of maxima within PEAK_TOLERANCE, each paired change's
    whole 95 % interval; floes broken as often (stats.verdict.breaks_agree).
    Returns (changes {name: (change, (lo, hi) or None, verdict)}, floes agree, overall)."""
    changes, floes_ok, overall, _ = verdict.judge(e, ref, TOLERANCE)
    return changes, floes_ok, overall


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
    output_guard.guard([("--out", out, output_guard.DIRECTORY), ("the runs' directory", runs_dir, output_guard.DIRECTORY)])
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
                  f"{ref['mean'][0]:.2f} ± {ref['mean'][1]:.2f} N, p99 {ref['p99'][0]:.2f} N, mean of maxima "
                  f"{ref['max'][0]:.2f} ± {ref['max'][1]:.2f} N (95 %), breaks per run {ref['breaks'][0]:.1f} ± "
                  f"{ref['breaks'][1]:.1f}; {ref['cpu']:.0f} s CPU per run, {100 * ref['capped']:.1f} % of its "
                  f"window's steps capped.", "",
                  "| setting | seeds | mean N | change | p99 N | change | max N (95 %) | change | Gumbel u N | "
                  "breaks/run | floes broken/run | sweeps/step | capped | CPU s/run | CPU / paper | within |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        pareto[title] = []
        for n in names:
            e = ens[n]
            if e is None:
                lines.append(f"| {n} | 0 | no finished run |||||||||||||")
                continue
            changes, floes_ok, overall = judge(e, ref)
            ratio = e["cpu"] / base["cpu"]
            failed = f" ({e['failed']} failed)" if e["failed"] else ""
            change = lambda k: verdict.change_text(changes[k]) if k in changes else ""  # noqa: E731
            lines.append(f"| {n} | {e['n']}{failed} | {e['mean'][0]:.2f} | {change('mean')} | {e['p99'][0]:.2f} | "
                         f"{change('p99')} | {e['max'][0]:.2f} ± {e['max'][1]:.2f} | {change('max')} | "
                         f"{e['gumbel_u']:.2f} | {e['breaks'][0]:.1f} ± {e['breaks'][1]:.1f} | "
                         f"{e['floes_broken'][0]:.1f}{'' if floes_ok else ' (not as often)'} | "
                         f"{e['sweeps']:.1f} | {100 * e['capped']:.0f} % | {e['cpu']:.1f} | {ratio:.2f} | {overall} |")
            if n not in REFERENCES:
                err = {k: changes[k][0] if k in changes else float("nan") for k in TOLERANCE}
                pareto[title].append((n, ratio, err, overall == "yes"))
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
              f"the converged reference, paired seed by seed with the half-width of their 95 % interval; 'within' "
              f"(the project's one rule, stats.verdict.judge) is yes when the whole interval of the mean's change is "
              f"within {100 * MEAN_TOLERANCE:.0f} % and of the p99's and mean of maxima's within "
              f"{100 * PEAK_TOLERANCE:.0f} %, and floes break as often as in the reference (the exact test of two "
              f"Poisson rates at 5 %); no when one is beyond or they do not; undecided when the seeds cannot tell. "
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
