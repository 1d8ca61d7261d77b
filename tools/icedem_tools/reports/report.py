"""The paper-comparison report of a friction sweep: a Markdown file
that sets the sweep's results beside the seed paper's findings, says where they
disagree, and shows the figures of scripts/sweep_figures.py. Run
`scripts/sweep aggregate` and `scripts/sweep_figures.py` first (or
`scripts/reproduce_paper`, which runs the whole chain).

    scripts/report SWEEP.toml [--out DIR] [--report FILE] [--figures DIR] [--command TEXT]

Scenario names it looks for (as in sweeps/paper_grid.toml): small_rigid,
large_rigid, large_breakable_015, large_breakable_020; missing ones are
reported as n/a. Default report: OUT/report.md; figures: OUT/figures.
"""
import argparse
import math
import os
import sys

from ..sweeps import aggregate as agg, execute
from ..runs import output_guard, spec
from .paper_findings import changed_findings, disagreement_section, filled_causes, findings, side_by_side
from .report_breakage import margin_section, mechanism_section
from .report_fracture_models import fracture_models_section
from .report_sweeps import before_section, convergence_section, flow_section, supplement_section
from .report_tables import ci, fmt, num, read_rows, run_records, run_summaries, supplement_rows

# Figures in the paper's order, with the paper's figure numbers.
FIGURES = (
    ("loads_vs_fis", "Average and max surge load against f_is, one line per f_ii (paper Figs. 8, 12, 16)"),
    ("history", "Surge load time histories at f_ii = 0.5, first seed (paper Figs. 9, 13, 17)"),
    ("spectrum", "Ensemble load spectra at f_ii = 0.5 (the paper's peak interval; not a paper figure)"),
    ("topview", "Floes and cone from above: start, largest load, end (paper Figs. 4, 11, 14, 18)"),
    ("frontview", "Front view of floe trajectories near the cone (paper Fig. 10)"),
)


def joblog_span(out):
    """(busy wall span s, summed job time s, jobs) of the GNU parallel job log: the wall
    time during which the engine ran jobs, over every logged session."""
    path = os.path.join(out, "joblog.txt")
    if not os.path.isfile(path):
        return None
    spans = []
    with open(path) as f:
        for line in f:
            parts = line.split("\t")
            if len(parts) < 7 or parts[0] == "Seq":
                continue
            try:
                start, dur = float(parts[2]), float(parts[3])
            except ValueError:
                continue
            spans.append((start, start + dur))
    if not spans:
        return None
    spans.sort()
    busy, cur_s, cur_e = 0.0, spans[0][0], spans[0][1]
    for s, e in spans[1:]:
        if s > cur_e:
            busy += cur_e - cur_s
            cur_s, cur_e = s, e
        else:
            cur_e = max(cur_e, e)
    busy += cur_e - cur_s
    return busy, sum(e - s for s, e in spans), len(spans)

def configuration_table(rows):
    L = ["## Every configuration", "",
         "Gumbel u and β: the moment fit of the seed maxima (docs/model/validation_targets.md §7); the expected max of an "
         "N-times longer record is u + β ln N. CoV: the coefficient of variation of the seed maxima; "
         "n(±10 %): the seeds a mean of maxima within ±10 % at 95 % needs, (1.96 CoV / 0.1)².", "",
         "| configuration | seeds | mean N | max N | Gumbel u, β N | CoV of max | n(±10 %) | peak interval s "
         "| spectral peak s | breaks (bending) |",
         "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        u, beta = num(r, "max_fx_gumbel_u_N"), num(r, "max_fx_gumbel_beta_N")
        cov = num(r, "max_fx_cov")
        need = math.ceil((1.96 * cov / 0.1) ** 2) if cov is not None else None
        L.append(f"| {r['configuration']} | {r['seeds']} | {ci(r, 'mean_fx_N')} | {ci(r, 'max_fx_N')} | "
                 f"{fmt(u)}, {fmt(beta)} | {fmt(cov, '', 2)} | {need if need is not None else 'n/a'} | "
                 f"{fmt(num(r, 'peak_interval_s'), '', 2)} | "
                 f"{fmt(num(r, 'spectral_peak_period_s'), '', 2)} | {r.get('breaks_bending', '0')} |")
    return L + [""]

def run_time_section(summaries, out, total_runs):
    L = ["## Run time", "", "| scenario | runs | wall time per run s | CPU time per run s | real-time factor | "
         "share of the grid's CPU |", "|---|---|---|---|---|---|"]
    total = sum(x.get("wall_time_s") or 0 for v in summaries.values() for _, x in v)
    total_cpu = sum(x.get("cpu_time_s") or 0 for v in summaries.values() for _, x in v)
    done = sum(len(v) for v in summaries.values())
    for s, v in summaries.items():
        w = [x.get("wall_time_s") or 0 for _, x in v]
        c = [x.get("cpu_time_s") or 0 for _, x in v]
        rtf = [x.get("realtime_factor") or 0 for _, x in v]
        share = f"{100 * sum(c) / total_cpu:.0f} %" if total_cpu else "n/a"
        L.append(f"| {s} | {len(v)} | {sum(w) / len(w):.0f} | {sum(c) / len(c):.0f} | {sum(rtf) / len(rtf):.1f} | "
                 f"{share} |")
    L += ["", f"The finished runs took {total / 3600:.2f} h of wall time and {total_cpu / 3600:.2f} h of CPU time "
          "(each run on one core; wall time grows when the machine is shared, CPU time does not)."]
    if done:
        # the measure: the whole grid on a 2-core machine of its own (CPU time over 2 cores)
        L.append(f"On 2 cores with nothing else running, the whole grid takes about "
                 f"{total_cpu * total_runs / done / 2 / 3600:.1f} h of wall time (its CPU time over 2 cores"
                 + ("" if done == total_runs else f", scaled from the {done} runs finished") + ").")
    span = joblog_span(out)
    if span and done and span[2] < done:
        # a later, partial run of the sweep (a rerun of a few of its runs) replaced the log: it says
        # nothing of how these runs shared the machine
        L.append(f"GNU parallel's job log holds {span[2]} jobs, fewer than the {done} runs finished: it is "
                 "of a later partial run of the sweep, so how many of these ran at once is not known here.")
    elif span and done:
        busy, summed, n = span
        # the log also holds jobs that were stopped or whose runs were deleted and rerun:
        # they ran beside the others, so they count for how many ran at once
        L.append(f"GNU parallel's job log holds {n} jobs (stopped and rerun ones included): "
                 f"{summed / 3600:.2f} h of run time in "
                 f"{busy / 3600:.2f} h of wall time, {summed / busy:.2f} runs at once on average on this "
                 f"{os.cpu_count()}-core machine. At that rate the whole grid takes about "
                 f"{total * total_runs / done / (summed / busy) / 3600:.1f} h of wall time.")
    return L + [""]

def figure_section(runs, out, figs, report):
    rel = os.path.relpath(figs, os.path.dirname(report))
    present = set(os.listdir(figs)) if os.path.isdir(figs) else set()
    L = ["## Figures", ""]
    for kind, caption in FIGURES:
        files = [f"{kind}_{s}.png" for s in dict.fromkeys(r.scenario for r in runs) if f"{kind}_{s}.png" in present]
        if files:
            L += [f"### {caption}", ""]
            for fn in files:
                L += [f"![{fn}]({rel}/{fn})", ""]
    views = [os.path.relpath(os.path.join(out, r.path, "run.xdmf"), spec.ROOT) for r in runs
             if os.path.isfile(os.path.join(out, r.path, "run.xdmf"))]
    if views:
        L += ["### Snapshots in ParaView", "",
              "The runs of the top views, every snapshot (floes and elements as prisms in the tank frame, "
              "floe id and awake flag per body), for ParaView's XDMF reader (not committed: they sit beside "
              "the runs):", ""] + [f"- `{v}`" for v in views] + [""]
    return L

def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sweep")
    ap.add_argument("--out", help="the sweep's output directory (default sweeps/<name>)")
    ap.add_argument("--report", help="the Markdown file (default OUT/report.md)")
    ap.add_argument("--figures", help="where sweep_figures.py put the PNGs (default OUT/figures)")
    ap.add_argument("--command", help="the command that made the report, quoted at its top")
    ap.add_argument("--supplement", action="append", default=[],
                    help="another aggregated sweep (e.g. sweeps/paper_resolution.toml) whose "
                         "configurations get a table of their own; repeatable")
    ap.add_argument("--before", help="the output directory of the same sweep run with an earlier "
                                     "build: a section compares every configuration with it")
    ap.add_argument("--before-note", default="", help="what changed since the earlier build")
    ap.add_argument("--before-label", default="icedem before",
                    help="the column heading of the earlier build's findings")
    ap.add_argument("--label", default="icedem", help="the column heading of this sweep's findings")
    ap.add_argument("--flow", help="a sweep of the small floes under other flow models (e.g. "
                                   "sweeps/flow_models.toml), compared with this grid's small_rigid runs")
    ap.add_argument("--convergence", help="a sweep of the grid's models with other numerics (e.g. "
                                          "sweeps/paper_convergence.toml), compared seed by seed")
    ap.add_argument("--fracture-models", help="the sweep of the analytic fracture model on the larger floes "
                                              "(sweeps/paper_fracture_models.toml), compared with the grid's rigid "
                                              "floes and lattices, the tank and ISO 19906")
    ap.add_argument("--fracture-models-convergence",
                    help="the analytic model at other numerics (sweeps/paper_fracture_models_convergence.toml)")
    ap.add_argument("--icedem", help="the build whose `cone-load` gives the ISO 19906 load (default build/dem/icedem)")
    args = ap.parse_args(argv)
    name, runs = spec.load(args.sweep)
    out = os.path.abspath(args.out or os.path.join(spec.ROOT, "sweeps", name))
    rows = read_rows(out)
    report = os.path.abspath(args.report or os.path.join(out, "report.md"))
    figs = os.path.abspath(args.figures or os.path.join(out, "figures"))
    sweep_rel = os.path.relpath(os.path.abspath(args.sweep), spec.ROOT)
    # before any work: the report is never the sweep file, a supplement, nor a run's HDF5 file
    output_guard.guard([("--report", report, output_guard.FILE)], [args.sweep, *args.supplement])
    records = run_records(runs, out)
    summaries = run_summaries(records)
    done = sum(len(v) for v in summaries.values())
    seeds = sorted({r.seed for r in runs})

    L = [f"# icedem against the seed paper: sweep `{name}`", "",
         "Made with " + (f"`{args.command}`" if args.command else
                         f"`scripts/sweep run {sweep_rel}`, `scripts/sweep aggregate {sweep_rel}`, "
                         f"`scripts/sweep_figures.py {sweep_rel}` and `scripts/report {sweep_rel}`") + ".", "",
         f"{done} of {len(runs)} runs finished, {len({r.config for r in runs})} configurations, "
         f"seeds {seeds[0]}-{seeds[-1]}" + ("" if done == len(runs) else
                                             " (**the grid is not complete**: configurations average "
                                             "over the seeds finished, see the seeds column)") + ". "
         "Loads are the surge load (the component resisting the tow, N) over each run's analysis "
         "window, given as the mean over seeds ± the half-width of the 95 % confidence interval "
         "(Student's t).", ""]
    failed = [st for st in (execute.status(r, out) for r in runs) if st.state == "failed"]
    if failed:
        # a failed run is reported, never silently dropped: its configuration averages the other seeds
        L += [f"**{len(failed)} run(s) failed**, left out of the averages:", ""]
        L += [f"- `{st.run.path}`: {st.error}" for st in failed] + [""]
    supplements = [(f, *supplement_rows(f)) for f in args.supplement]  # read once, cited twice
    causes = filled_causes(supplements)
    modes = agg.break_names([x for v in summaries.values() for _, x in v], "breaks_by_mode")
    now = findings(rows, summaries, modes)
    before_rows = None
    if args.before:
        before_out = os.path.abspath(args.before)
        if os.path.isfile(os.path.join(before_out, "results.csv")):
            before_rows = read_rows(before_out)
    before = findings(before_rows, None, modes) if before_rows else None
    table, disagreements = side_by_side(now, before, args.before_label, args.label)
    L += table + [""] + changed_findings(now, before, args.before_label, args.label)
    L += disagreement_section(disagreements, causes, summaries)
    L += mechanism_section(records, figs, report) + margin_section(records, figs, report)
    if args.flow:
        L += flow_section(os.path.abspath(args.flow), rows)
    if args.convergence:
        L += convergence_section(os.path.abspath(args.convergence), records, supplements=supplements)
    if args.fracture_models:
        icedem = args.icedem or os.path.join(spec.ROOT, "build", "dem", "icedem")
        conv = args.fracture_models_convergence
        L += fracture_models_section(os.path.abspath(args.fracture_models), records, figs, report, icedem,
                                     os.path.abspath(conv) if conv else None)
    for sup in supplements:
        L += supplement_section(*sup)
    if args.before:
        L += before_section(rows, os.path.abspath(args.before), args.before_note)
    L += configuration_table(rows) + run_time_section(summaries, out, len(runs))
    L += figure_section(runs, out, figs, report)
    output_guard.write_text(report, "\n".join(L) + "\n")
    print(f"wrote {report}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
