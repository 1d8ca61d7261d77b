"""Does a sweep's findings move with its numerics? A sweep whose scenarios are <model>+<numerics>
(sweeps/studies/breaking_convergence.toml, sweeps/paper_convergence.toml) judged on its own runs:
per model, what each numerics costs, and every headline number (mean, p99 and mean of maxima of
the load, the failure ratio, breaks per run, the breaks' mechanism shares) at each numerics
against the model's "default", seed by seed, with its 95 % interval and verdict (the paper
report's "Are the findings converged?", tools/icedem_tools/report_convergence.py). Unlike the
report, no other sweep's runs are pooled in: the default is the sweep's own.

    scripts/convergence_check SWEEP.toml [--out DIR] [--report PAGE.md]

--out is the sweep's run directory (default sweeps/<name>); finished runs count, so it can report
while the sweep runs. Without --report the page is printed."""
import argparse
import os

from . import output_guard, spec
from .report_convergence import headline_section
from . import report_sweeps
from .report_sweeps import cost_table


def page(sweep, out):
    """The page's Markdown lines for the sweep file `sweep` with its runs in `out`."""
    name, runs = spec.load(sweep)
    got = report_sweeps.by_model_numerics(runs, out)
    L = [f"# {name}: do its findings move with the numerics?", "",
         f"Runs of `{os.path.relpath(sweep, spec.ROOT)}` finished so far, judged on their own "
         "(`scripts/convergence_check`).", ""]
    if not got:
        return L + ["No finished run of a <model>+<numerics> scenario yet.", ""]
    return L + cost_table(got) + [""] + headline_section(got, pooled=False)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sweep", help="the sweep file: scenarios named <model>+<numerics>, one numerics \"default\"")
    ap.add_argument("--out", help="the sweep's run directory (default: sweeps/<name>)")
    ap.add_argument("--report", help="write the page here (Markdown) instead of printing it")
    args = ap.parse_args(argv)
    sweep = os.path.abspath(args.sweep)
    name, _ = spec.load(sweep)
    out = os.path.abspath(args.out) if args.out else os.path.join(spec.ROOT, "sweeps", name)
    if args.report:
        output_guard.guard([("--report", args.report, output_guard.FILE)], [sweep])
    text = "\n".join(page(sweep, out)) + "\n"
    if not args.report:
        print(text, end="")
        return 0
    output_guard.write_text(args.report, text)
    print(f"wrote {args.report}")
    return 0
