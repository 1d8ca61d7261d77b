#!/usr/bin/python3
"""The report's comparison of fracture models (tools/icedem_tools/reports/report_fracture_models.py)
compares the models over the seeds every model with runs finished, the same layouts, at the paper's
Fig. 18 frictions only: a seed one model lacks is left out of every model's numbers (a model
without any run is n/a and leaves the others' seeds alone), other
frictions are not mixed in, and a run without the window's p99 (a record kept before it was)
makes the column n/a rather than a mean over the others; without the ISO 19906 load the
row says why. The hexagonal lattices are set against the squares of their size on the seeds both
finished, seed by seed, and do not narrow the models' seeds."""
import collections
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
from icedem_tools.reports.report_fracture_models import (FII, FIS, MODELS, SHAPES, comparison, iso19906,  # noqa: E402
                                                 shape_comparison, shape_lines)

Run = collections.namedtuple("Run", "seed labels")


def record(mean, peak, breaks=0, cpu=10.0, p99=None):
    # `breaks` breaks: two of one floe, then the others of a second
    events = [{"floe": 3 if k < 2 else 7, "ratio": 1.0 + 0.5 * k} for k in range(breaks)]
    rec = {"summary": {"mean_fx_N": mean, "max_fx_N": peak, "breaks": breaks, "cpu_time_s": cpu},
           "fracture_events": events}
    if p99 is not None:
        rec["window"] = {"p99_fx_N": p99}
    return rec


def runs(fii, fis, seeds, scale, p99=True):
    return [(Run(s, ((FII, fii), (FIS, fis))), record(10 * scale + s, 100 * scale + s, breaks=s,
                                                      p99=(50 * scale + s) if p99 else None)) for s in seeds]


records = {}
for k, (scenario, _) in enumerate(MODELS):
    seeds = [1, 2, 3] if k else [1, 2]  # the rigid floes lack seed 3
    records[scenario] = (runs(0.3, 0.3, seeds, k + 1) + runs(0.7, 0.3, seeds, k + 1, p99=k != 2)
                         + runs(0.3, 0.1, [1, 2, 3, 4], 100))  # another f_is: not the comparison's
got = comparison(records)
common, models = got[0.3]
check(common == [1, 2], f"f_ii 0.3: the seeds every model finished, {common}")
st = models[MODELS[1]]
check(abs(st["mean_fx_N"][0] - 21.5) < 1e-12, f"the analytic model's mean over seeds 1 and 2 only: {st['mean_fx_N']}")
check(abs(st["largest"] - 202) < 1e-12, f"its largest max, seed 3 and f_is 0.1 left out: {st['largest']}")
check(abs(st["breaks"] - 1.5) < 1e-12 and abs(st["cpu"] - 10) < 1e-12, f"breaks and CPU per run: {st}")
check(st["ratio"] is not None and abs(st["ratio"][0] - 1.0) < 1e-12,
      f"the breaks' load ratios over the runs (1, 1, 1.5): median {st['ratio']}")
check(abs(st["floes"] - 1.0) < 1e-12, f"floes broken per run, each once (1 break and 2 of one floe): {st['floes']}")
check(abs(st["p99_fx_N"][0] - 101.5) < 1e-12, f"its p99: {st['p99_fx_N']}")
check(got[0.7][1][MODELS[2]]["p99_fx_N"] is None and got[0.7][1][MODELS[1]]["p99_fx_N"] is not None,
      "records without the window's p99 make the column n/a for that model only")
check(all(v is None for v in comparison({})[0.3][1].values()), "no runs: no numbers")
# a model whose sweep has not started (no run at all) does not empty the others' table
unstarted = {k: v for k, v in records.items() if k != MODELS[-1][0]}
common, models = comparison(unstarted)[0.3]
check(common == [1, 2] and models[MODELS[-1]] is None and models[MODELS[1]] is not None,
      f"a model without runs is n/a and leaves the others' seeds: {common}")
# one with some runs but not those seeds does narrow them: its seeds are a fair comparison's
partial = dict(unstarted)
partial[MODELS[-1][0]] = runs(0.3, 0.3, [2], 9)
common, models = comparison(partial)[0.3]
check(common == [2] and models[MODELS[-1]] is not None, f"a model with runs narrows the seeds to its own: {common}")
# a hexagonal lattice with one seed of the models' three does not narrow the models' seeds
with_shape = dict(records)
hexagon, _, squares = SHAPES[0]
with_shape[hexagon] = [(Run(s, ((FII, 0.3), (FIS, 0.3))), record(v, 10 * v, breaks=b, p99=5 * v))
                       for s, v, b in ((2, 30.0, 40), (3, 35.0, 50))]
common, models = comparison(with_shape)[0.3]
check(common == [1, 2], f"a hexagonal lattice leaves the models' seeds alone: {common}")
got = shape_comparison(with_shape)
check(got[0.7][hexagon] is None and got[0.3][SHAPES[1][0]] is None, "a shape without runs at a friction: None")
seeds, st_hex, st_sq, diffs = got[0.3][hexagon]
# the squares (model k = 2, scale 3) at seed s: mean 30 + s, max 300 + s, breaks s, p99 150 + s
check(seeds == [2, 3], f"the shape against the squares on the seeds both finished: {seeds}")
check(abs(st_sq["mean_fx_N"][0] - 32.5) < 1e-12 and abs(st_hex["mean_fx_N"][0] - 32.5) < 1e-12,
      f"both over seeds 2 and 3 only: {st_sq['mean_fx_N']}, {st_hex['mean_fx_N']}")
# seed by seed: mean 30 - 32 = -2, 35 - 33 = +2 -> 0 +- t(0.975, 1) * 2.83 / sqrt(2) = 12.706 * 2
d, half = diffs["mean_fx_N"]
check(abs(d) < 1e-12 and abs(half - 12.706 * 2) < 0.01, f"the mean's paired difference and interval: {diffs['mean_fx_N']}")
check(abs(diffs["breaks"][0] - 42.5) < 1e-12, f"breaks, (40 - 2 + 50 - 3) / 2: {diffs['breaks']}")
check(abs(diffs["max_fx_N"][0] - (300 + 350 - 302 - 303) / 2) < 1e-12, f"the maxima: {diffs['max_fx_N']}")
lines = "\n".join(shape_lines(with_shape))
check("hexagons - squares | 2 | +0.0 ± 25.4" in lines, f"the table's difference row:\n{lines}")
check(shape_lines(records) == [], "no shape run: no section")
terms, why = iso19906("/nonexistent/icedem")
check(terms is None and "no build at /nonexistent/icedem" in why, f"without a build the ISO row says why: {why}")
terms, why = iso19906("/bin/false")
check(terms is None and "failed" in why, f"a build whose cone-load fails: the row says so: {why}")

finish()
