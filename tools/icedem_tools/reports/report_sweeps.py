"""The report's sections on other sweeps beside the grid: the flow models over seeds, the
convergence of the grid's loads, supplements, and the same grid run with an earlier build
(tools/icedem_tools/reports/report.py)."""
import argparse
import collections
import math
import os

from ..sweeps import aggregate as agg, execute
from ..runs import output_guard, spec
from . import flow_table
from .report_convergence import headline_section
from .report_tables import at_reference, ci, fmt, num, ratio_to_first, read_rows, supplement_rows, sweep_about


def run_numbers(record):
    """A run's summary with its record's window quantiles (p99_fx_N) added: the numbers the
    report judges per run."""
    return {**record["summary"], **record.get("window", {})}


def finished_summaries(runs, out):
    """{scenario: {seed: run_numbers}} of a sweep's finished runs (here or by their records)."""
    found = collections.defaultdict(dict)
    for r in runs:
        if execute.status(r, out).state == "done":
            found[r.scenario][r.seed] = run_numbers(agg.load_record(r, out))
    return found


def supplement_section(sweep_file, name, runs, out, rows):
    """The configurations of another aggregated sweep (its supplement_rows), with their max
    against the first one's. Configurations named <model>+<numerics> are judged against the
    grid's own runs seed by seed in "Are the findings converged?" (report_convergence.py), so
    they get no second, unpaired comparison here."""
    if rows is None:
        return [f"## Supplement: sweep `{name}`", "", f"Not aggregated yet (`scripts/sweep aggregate {sweep_file}`).", ""]
    done = sum(1 for r in runs if execute.status(r, out).state == "done")
    L = [f"## Supplement: sweep `{name}`", "", sweep_about(sweep_file), "",
         f"{done} of {len(runs)} runs finished. Ratios: against the first configuration.", "",
         "| configuration | seeds | mean N | max N | mean ratio | max ratio | run time per run s |",
         "|---|---|---|---|---|---|---|"]
    for r in rows:
        per = num(r, "run_wall_time_s")
        n = int(float(r["seeds"])) if r.get("seeds") else 0
        L.append(f"| {r['configuration']} | {r['seeds']} | {ci(r, 'mean_fx_N')} | {ci(r, 'max_fx_N')} | "
                 f"{ratio_to_first(rows, r, 'mean_fx_N')} | {ratio_to_first(rows, r, 'max_fx_N')} | "
                 f"{fmt(per / n if per is not None and n else None, '', 0)} |")
    if any("+" in r["scenario"] for r in rows):
        L += ["", "Its `<model>+<numerics>` runs are set beside the grid's runs of the same seeds in "
              "\"Are the findings converged?\"."]
    return L + [""]


def before_section(rows, before_out, note):
    """Every configuration against the same sweep run with an earlier build (its output
    directory): mean and max load before and now, their ratio, and whether the change is
    within the seeds' scatter (the two 95 % half-widths combined)."""
    if not os.path.isfile(os.path.join(before_out, "results.csv")):
        return ["## Against an earlier build", "", f"No results.csv in `{before_out}`.", ""]
    before = {r["configuration"]: r for r in read_rows(before_out)}
    L = ["## Against an earlier build", "", note, "",
         f"The earlier runs: `{os.path.relpath(before_out, spec.ROOT)}`. A change is within the seed "
         "scatter when it is smaller than the two 95 % half-widths combined (root of the sum of squares).", "",
         "| configuration | seeds before / now | mean N before → now | ratio | within scatter | "
         "max N before → now | ratio | within scatter |", "|---|---|---|---|---|---|---|---|"]
    ratios = {}

    def change(a, b, key):
        """(table cells "before → now | ratio | within scatter", the ratio or None)"""
        x, y = num(a, key), num(b, key)
        if x is None or y is None or x == 0:
            return "n/a | n/a | n/a", None
        h = math.hypot(num(a, key + "_ci95") or 0.0, num(b, key + "_ci95") or 0.0)
        return f"{x:.1f} → {y:.1f} | {y / x:.2f} | {'yes' if abs(y - x) <= h else '**no**'}", y / x

    for r in rows:
        b = before.get(r["configuration"])
        if b is None:
            continue
        cells = []
        for key, column in (("mean", "mean_fx_N"), ("max", "max_fx_N")):
            text, ratio = change(b, r, column)
            cells.append(text)
            if ratio is not None:
                ratios.setdefault((r["scenario"], key), []).append(ratio)
        L.append(f"| {r['configuration']} | {b['seeds']} / {r['seeds']} | {cells[0]} | {cells[1]} |")
    L.append("")
    for scen in dict.fromkeys(r["scenario"] for r in rows):
        parts = [f"{key} {sum(v) / len(v):.2f}" for key in ("mean", "max")
                 if (v := ratios.get((scen, key)))]
        if parts:
            L.append(f"- {scen}: now / before, averaged over its configurations: " + ", ".join(parts) + ".")
    return L + [""]

def flow_section(flow_sweep, rows):
    """The flow models over seeds (a sweep of the small floes under other flow models, from its
    records) against the grid's own small-floe runs at f_ii 0.5, f_is 0.2 (the analytic potential flow,
    the default), each change paired seed by seed by the project's one rule (flow_table.py). `rows`
    is not read: the grid's runs come from their records too."""
    f = flow_table.facts(flow_sweep)
    return (["## Flow models over seeds", "", sweep_about(flow_sweep), "", flow_table.about(f), ""] +
            flow_table.table(f) + ["", flow_table.multiplicity(f), ""])


def by_model_numerics(runs, out):
    """{(model, numerics): {seed: run_numbers}} of a sweep's finished runs whose scenarios are
    named <model>+<numerics> (the others left out)."""
    got = {}
    for scenario, by_seed in finished_summaries(runs, out).items():
        model, plus, numerics = scenario.partition("+")
        if plus:
            got.setdefault((model, numerics), {}).update(by_seed)
    return got


def pooled_numerics(got, records, supplements):
    """The convergence sweep's {(model, numerics): {seed: summary}} with the runs of the
    supplements named <model>+<numerics> added, and the grid's own runs at the reference
    friction as each model's default (the same configuration: convergence_section checks that
    they repeat)."""
    pooled = {k: dict(v) for k, v in got.items()}
    for _, _, runs, out, _ in supplements:
        for key, by_seed in by_model_numerics(runs, out).items():
            pooled.setdefault(key, {}).update(by_seed)
    for model in {m for m, _ in pooled}:
        grid = {r.seed: run_numbers(rec) for r, rec in records.get(model, []) if at_reference(r)}
        if grid:
            pooled.setdefault((model, "default"), {}).update(grid)
    return pooled


def cost_table(got):
    """Markdown lines: what each numerics of a <model>+<numerics> sweep costs, per model (its runs,
    breaks per run, solver iterations per step, CPU per run). `got`: {(model, numerics): {seed:
    summary}}."""
    L = ["What each numerics costs (its changes to the findings follow in \"Are the findings converged?\"):", "",
         "| model | numerics | seeds | breaks per run | solver iterations per step | CPU per run s |",
         "|---|---|---|---|---|---|"]
    for model in dict.fromkeys(m for m, _ in got):
        for numerics in [n for m, n in got if m == model]:
            runs_ = got[(model, numerics)]
            br = [x.get("breaks", 0) for x in runs_.values()]
            sw = [(x.get("solver") or {}).get("iterations_mean") for x in runs_.values()]
            sw = [v for v in sw if v is not None]
            cpu = [x.get("cpu_time_s") for x in runs_.values() if x.get("cpu_time_s")]
            L.append(f"| {model} | {numerics} | {len(runs_)} | {sum(br) / len(br):.1f} | "
                     f"{fmt(sum(sw) / len(sw) if sw else None)} | {fmt(sum(cpu) / len(cpu) if cpu else None, '', 0)} |")
    return L


def convergence_section(conv_sweep, records, title="## Convergence of the grid's loads", supplements=()):
    """The grid's numbers against a halved step and a tighter solve (a sweep whose scenarios are
    <model>+<numerics>, e.g. sweeps/paper_convergence.toml), compared seed by seed, and whether
    its default runs repeat the grid's runs of the same seeds; then every headline number's
    change (report_convergence.py), with the supplements' <model>+<numerics> runs added."""
    name, runs, out, _ = supplement_rows(conv_sweep)
    L = [title, "", sweep_about(conv_sweep), ""]
    got = by_model_numerics(runs, out)  # (model, numerics) -> {seed: summary}
    if not got:
        return L + [f"No finished runs yet (`scripts/sweep run {os.path.relpath(conv_sweep, spec.ROOT)}`).", ""]
    # what each numerics costs; what it changes is judged, with intervals, by headline_section
    L += cost_table(got)
    # the default runs are the grid's runs of the same seeds at f_ii 0.5, f_is 0.2: they must agree
    same, differ = 0, []
    for (model, numerics), by_seed in got.items():
        if numerics != "default":
            continue
        for r, rec in records.get(model, []):
            if at_reference(r) and r.seed in by_seed:
                a, b = rec["summary"].get("max_fx_N"), by_seed[r.seed].get("max_fx_N")
                if a == b:
                    same += 1
                else:
                    differ.append(f"{model} seed {r.seed}: {a} against {b} N")
    if same or differ:
        L += ["", f"The default runs repeat the grid's: {same} of {same + len(differ)} runs give the same max load "
              "to the last digit" + (" (**not**: " + "; ".join(differ) + ")" if differ else "") + "."]
    return L + [""] + headline_section(pooled_numerics(got, records, supplements),
                                       steps=compared_steps(runs, records, supplements))


def compared_steps(runs, records, supplements):
    """{(model, numerics): Bullet step s} of the pooled runs (pooled_numerics): the grid's own runs at the
    reference friction give each model's default, the convergence sweep and its supplements the other
    numerics. The report labels each change with the two steps it compares, since a model's scenario
    can take another step than it did when its checks were run."""
    steps = {}
    for r in list(runs) + [r for _, _, rs, _, _ in supplements for r in rs]:
        model, plus, numerics = r.scenario.partition("+")
        if plus:
            steps.setdefault((model, numerics), set()).add(round(spec.bullet_step(r), 9))
    for model, rows in records.items():
        grid = {round(spec.bullet_step(r), 9) for r, _ in rows if at_reference(r)}
        if grid:
            steps[(model, "default")] = grid
    return {k: v.pop() if len(v) == 1 else None for k, v in steps.items()}


def page_command(argv, doc, sweep_help, page, add_options=None):
    """The main of a command that makes a page of one sweep's finished runs (scripts/convergence_check,
    scripts/level_ice_report): SWEEP [--out DIR] [--report PAGE] and the command's own options
    (`add_options(parser)`). `page(sweep, out, args)` gives the page's lines; they are printed, or
    written to --report, never over the sweep file. --out is the sweep's run directory (default
    sweeps/<name>)."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sweep", help=sweep_help)
    ap.add_argument("--out", help="the sweep's run directory (default: sweeps/<name>)")
    ap.add_argument("--report", help="write the page here (Markdown) instead of printing it")
    if add_options:
        add_options(ap)
    args = ap.parse_args(argv)
    sweep = os.path.abspath(args.sweep)
    name, _ = spec.load(sweep)
    out = os.path.abspath(args.out) if args.out else os.path.join(spec.ROOT, "sweeps", name)
    if args.report:
        output_guard.guard([("--report", args.report, output_guard.FILE)], [sweep])
    text = "\n".join(page(sweep, out, args)) + "\n"
    if not args.report:
        print(text, end="")
        return 0
    output_guard.write_text(args.report, text)
    print(f"wrote {args.report}")
    return 0
