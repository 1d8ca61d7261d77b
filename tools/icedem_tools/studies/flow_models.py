"""The flow models over seeds: the paper's small floes (f_ii 0.5, f_is 0.2) in still water and under the
OpenFOAM flow (field and probe modes), 10 seeds each (sweeps/flow_models.toml), against the analytic
potential flow, icedem's default, which is the paper grid's own runs of that configuration
(sweeps/paper_grid.toml). Made from the committed records of both:

    scripts/flow_models [--report docs/coupling/flow_models_seeds.md]

writes the page's table (each model's mean and max with their 95 % intervals, each change against the
analytic flow paired seed by seed by the project's one rule, stats/verdict.py, and the family's
multiplicity statement) and fills the spans of README.md and docs/model/coupling.md that name a model's
change ("flow | MODEL | mean" or "max": the change with its interval and verdict; "flow | MODEL | mean N"
or "max N": the mean over seeds with its half-width; "flow | solve": the solve every record was made
with)."""
import argparse
import os
import sys

from ..runs import output_guard, spec
from ..runs.spec import ROOT
from ..reports import spans
from ..reports.flow_table import about, facts, multiplicity, resolver, table

FLOW_SWEEP = os.path.join(ROOT, "sweeps", "flow_models.toml")
PAGES = [os.path.join(ROOT, "README.md"), os.path.join(ROOT, "docs", "model", "coupling.md")]
BEGIN, END = "<!-- flow models table: scripts/flow_models writes below -->", "<!-- end of the flow models table -->"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--report", help="the page (default docs/coupling/flow_models_seeds.md)")
    ap.add_argument("--pages", nargs="*", help="the pages whose spans to fill (default README.md, docs/model/coupling.md)")
    a = ap.parse_args(argv)
    try:
        f = facts(FLOW_SWEEP)
    except spec.SweepError as e:
        sys.exit(f"scripts/flow_models: {e}")
    path = a.report or os.path.join(ROOT, "docs", "coupling", "flow_models_seeds.md")
    pages = PAGES if a.pages is None else a.pages
    output_guard.guard([("--report", path, output_guard.FILE)], [FLOW_SWEEP])
    block = "\n".join([BEGIN, "", "Made by `scripts/flow_models` from the committed records of "
                       f"`{os.path.relpath(FLOW_SWEEP, ROOT)}` and of the paper grid's small_rigid runs at f_ii 0.5, "
                       "f_is 0.2. " + about(f), ""] + table(f) + ["", multiplicity(f), "", END])
    page = open(path).read() if os.path.isfile(path) else "# The flow models over seeds\n"
    output_guard.write_text(path, spans.replace_block(page, block, BEGIN, END))
    print(f"wrote {path}")
    for p in pages:
        text = open(p).read()
        try:
            filled = spans.fill(text, resolver(f), only="flow |")
        except spans.UnknownKey as e:
            sys.exit(f"scripts/flow_models: {p}: {e}")
        if filled != text:
            output_guard.write_text(p, filled)
            print(f"wrote {p}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
