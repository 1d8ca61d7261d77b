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
import os

from . import spec
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
    return report_sweeps.page_command(
        argv, __doc__, "the sweep file: scenarios named <model>+<numerics>, one numerics \"default\"",
        lambda sweep, out, args: page(sweep, out))
