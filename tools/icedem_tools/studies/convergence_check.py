"""Does a sweep's findings move with its numerics? A sweep whose scenarios are <model>+<numerics>
(sweeps/studies/breaking_convergence.toml, sweeps/paper_convergence.toml) judged on its own runs:
per model, what each numerics costs, and every headline number (mean, p99 and mean of maxima of
the load, the failure ratio, breaks per run, the breaks' mechanism shares) at each numerics
against the model's "default", seed by seed, with its 95 % interval and verdict (the paper
report's "Are the findings converged?", tools/icedem_tools/reports/report_convergence.py). Unlike the
report, no other sweep's runs are pooled in: the default is the sweep's own.

    scripts/convergence_check SWEEP.toml [--out DIR] [--report PAGE.md] [--baseline NUMERICS]

--out is the sweep's run directory (default sweeps/<name>); finished runs count, so it can report
while the sweep runs. Without --report the page is printed. --baseline judges every numerics
against another one than "default" (does dt/4 still move from dt/2?); the scenario's own default
is then listed as "scenario_default"."""
import os

from ..runs import spec
from ..reports.report_convergence import headline_section
from ..reports import report_sweeps
from ..reports.report_sweeps import cost_table


def rebased(got, baseline):
    """`got` with the numerics `baseline` in the place of "default", which the tables judge every
    other numerics against, and the scenario's own default renamed "scenario_default"."""
    def name(numerics):
        return "default" if numerics == baseline else "scenario_default" if numerics == "default" else numerics
    return {(model, name(numerics)): v for (model, numerics), v in got.items()}


def page(sweep, out, baseline="default"):
    """The page's Markdown lines for the sweep file `sweep` with its runs in `out`, each numerics
    against `baseline`."""
    name, runs = spec.load(sweep)
    got = report_sweeps.by_model_numerics(runs, out)
    L = [f"# {name}: do its findings move with the numerics?", "",
         f"Runs of `{os.path.relpath(sweep, spec.ROOT)}` finished so far, judged on their own "
         "(`scripts/convergence_check`).", ""]
    if baseline != "default":
        if not any(n == baseline for _, n in got):
            return L + [f"No finished run of the baseline numerics \"{baseline}\" yet.", ""]
        got = rebased(got, baseline)
        judged = {model for model, numerics in got if numerics == "default"}  # the models with the baseline
        got = {k: v for k, v in got.items() if k[0] in judged}
        L += [f"**Baseline: \"{baseline}\".** In the tables below \"default\" stands for the numerics "
              f"\"{baseline}\", and every other numerics is judged against it; the scenarios' own "
              "default is \"scenario_default\".", ""]
    if not got:
        return L + ["No finished run of a <model>+<numerics> scenario yet.", ""]
    return L + cost_table(got) + [""] + headline_section(got, pooled=False)


def main(argv=None):
    return report_sweeps.page_command(
        argv, __doc__, "the sweep file: scenarios named <model>+<numerics>, one numerics \"default\"",
        lambda sweep, out, args: page(sweep, out, args.baseline),
        lambda ap: ap.add_argument("--baseline", default="default",
                                   help="the numerics every other is judged against (default: \"default\")"))
