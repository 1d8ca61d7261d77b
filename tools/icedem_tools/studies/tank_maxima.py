"""Like with like: the tank's single largest load of a run against the distribution of the runs' maxima.

    scripts/tank_maxima [--records DIR] [--report PATH] [--figure PNG]

The tank gives one number per condition, the largest surge load of its run; the paper report compares
it with the mean over seeds of each run's maximum, which is not the same quantity. This reads the
paper grid's committed records (docs/paper_reproduction/records: every finished run's summary) and,
per model and friction, sets the tank's value against the runs' maxima: the share of runs whose
maximum reaches it with its Clopper-Pearson 95 % interval, the Gumbel type I fit of the maxima (moment
fit, stats.intervals.gumbel_fit) with the probability it gives of reaching the tank's value, and the largest
of the runs. The tank's values: about 150 N for the 0.6 m floes (the paper's Fig. 12 and its text);
for the 0.3 m floes the paper gives no number, and 75 N is an inference (150 N / 2, the ratio of the
floe sizes), labelled so. A probability plot of the maxima on Gumbel paper at the paper's reference
friction (f_ii 0.5, f_is 0.2 and 0.3 pooled) draws the tank's value across it.

After a low-pass filter: a load cell and its carriage have a bandwidth, and the tank's number has
passed through it; the runs' record (the load over each 0.02 s step, 50 Hz, so nothing above 25 Hz)
has not. The grid's records keep each run's maximum, not its series, so the filtered comparison is
made on the budget's runs, which keep theirs (sweeps/load_budget, scripts/budget):

    scripts/tank_maxima --filter-runs sweeps/load_budget

reads each run's load series of the default, of f_is 0.3 and of added mass, filters it as
`stats.lowpass_hz` does (2nd-order Butterworth, forward and backward: zero phase, the gain squared,
dem/output/statistics.cpp) at 10 and 5 Hz, takes the maximum over the run's own analysis window and
keeps the maxima in docs/model/tank_maxima_records/filtered_maxima.json; the report is made from that
file alone. 25 Hz is the record's own Nyquist frequency: the unfiltered maximum stands for it.
"""
import argparse
import glob
import json
import math
import os
import re
import sys

import numpy as np

from ..sweeps import aggregate as agg
from ..stats.intervals import gumbel_fit, share_text
from ..runs import output_guard
from ..runs.spec import ROOT

# the tank's largest load of one run, N, and what it rests on
TANK = {
    "small_rigid": (75.0, "inferred: 150 N / 2 (the paper gives no number for the 0.3 m floes)"),
    "large_rigid": (150.0, "the tank's 0.6 m floes (the paper's Fig. 12)"),
    "large_breakable_015": (150.0, "the tank's 0.6 m floes (the paper's Fig. 12)"),
    "large_breakable_020": (150.0, "the tank's 0.6 m floes (the paper's Fig. 12)"),
}
REFERENCE = [(0.5, 0.2), (0.5, 0.3)]  # the paper's reference friction, and its neighbour pooled
CUTOFFS_HZ = agg.LOWPASS_HZ  # the filters tried (0: the record as it is, band-limited at 25 Hz)
# the budget's variants whose runs are filtered: the reference friction (default and f_is 0.3,
# pooled as above) and added mass; and, for whether a filtered maximum is converged, the default and
# added mass at half the step and with the solve tightened tenfold (the 0.6 m rigid floes)
FILTERED_VARIANTS = {"default": "reference", "f_is_0.3": "reference", "added_mass": "added mass",
                     "dt_half": "f_is 0.2, dt/2", "solve_tenfold": "f_is 0.2, solve tenfold",
                     "added_mass_dt_half": "added mass, dt/2", "added_mass_solve_tenfold": "added mass, solve tenfold"}
GROUPS = ["reference", "added mass", "f_is 0.2, dt/2", "f_is 0.2, solve tenfold", "added mass, dt/2",
          "added mass, solve tenfold"]
FILTERED_RECORDS = os.path.join(ROOT, "docs", "model", "tank_maxima_records", "filtered_maxima.json")


def filtered_maxima(run_h5, summary):
    """{cutoff Hz (0: none): the maximum surge load over the run's analysis window, N}."""
    import h5py
    with h5py.File(run_h5, "r") as f:
        t = f["load/time"][()]
        x = f["load/surge"][()]
    dt = (t[-1] - t[0]) / (len(t) - 1)
    slack = 1e-6 * dt
    inside = (t >= summary["window_start_s"] - slack) & (t <= summary["window_end_s"] + slack)
    return {"0": float(x[inside].max()), **agg.lowpass_maxima(t, x, inside)}


def filter_runs(sweep_dir, records):
    """Filter the budget's finished runs in `sweep_dir` and write their maxima to `records`."""
    out = {}
    for path in sorted(glob.glob(os.path.join(sweep_dir, "*", "*", "base", "seed*", "summary.json"))):
        parts = path.split(os.sep)
        model, variant, seed = parts[-5], parts[-4], parts[-2]
        if model not in TANK or variant not in FILTERED_VARIANTS:
            continue
        with open(path) as f:
            summary = json.load(f)
        run = os.path.join(os.path.dirname(path), "run.h5")
        if summary.get("status") != "complete" or not os.path.exists(run):
            continue
        maxima = filtered_maxima(run, summary)
        # the record's own maximum is the run's: a check that the window is the run's own
        if abs(maxima["0"] - summary["max_fx_N"]) > 1e-9 * max(1.0, abs(summary["max_fx_N"])):
            raise RuntimeError(f"{path}: the window's maximum {maxima['0']} N is not the run's {summary['max_fx_N']} N")
        out.setdefault(model, {}).setdefault(variant, {})[seed] = maxima
    output_guard.write_text(records, json.dumps(out, indent=1, sort_keys=True) + "\n")
    return out


def filtered_table(filtered):
    """The report's section on the filtered maxima, from the records of filter_runs."""
    lines = ["## After a low-pass filter", "",
             "A load cell and carriage pass loads up to their bandwidth; the tank's number has been through "
             "theirs, which the paper does not give. The runs' maxima after the filter `stats.lowpass_hz` applies "
             "(2nd-order Butterworth, zero phase) at 10 and 5 Hz, on the load budget's runs "
             "(docs/model/load_budget.md), which keep their series: at the reference friction (f_ii 0.5, f_is "
             "0.2 and 0.3 pooled, as above) and with the water's added mass (`water.added_mass`, f_is 0.2); for "
             "the 0.6 m rigid floes also at f_is 0.2 with the step halved (2 substeps) and the solve tightened "
             "tenfold, with and without added mass: the rows to read a maximum's convergence from (the reference "
             "rows pool two frictions; compare those with the added-mass rows and with each other). The record "
             "is the load over each 0.02 s step (0.01 s at dt/2), so nothing above its 25 Hz Nyquist frequency is "
             "in it: the unfiltered maximum stands for 25 Hz.", "",
             "| model | runs | filter | maxima: mean, largest N | runs reaching the tank (95 %) |", "|---|---|---|---|---|"]
    for model in TANK:
        groups = {}
        for variant, seeds in filtered.get(model, {}).items():
            groups.setdefault(FILTERED_VARIANTS[variant], []).extend(seeds.values())
        tank, _ = TANK[model]
        for group in GROUPS:
            runs = groups.get(group, [])
            if not runs:
                continue
            for cutoff in ["0"] + [f"{fc:g}" for fc in CUTOFFS_HZ]:
                x = np.array([r[cutoff] for r in runs])
                label = "none (25 Hz)" if cutoff == "0" else f"{cutoff} Hz"
                lines.append(f"| {model}, {group} | {len(x)} | {label} | {x.mean():.1f}, {x.max():.1f} | "
                             f"{share_text(int((x >= tank).sum()), len(x))} |")
    return lines + [""]


def read_maxima(records):
    """{model: {(f_ii, f_is): [run maxima, N]}} from a sweep's records."""
    out = {}
    for path in glob.glob(os.path.join(records, "*", "*", "seed*.json")):
        model, config = path.split(os.sep)[-3:-1]
        m = re.match(r"friction\.ice_ice=([\d.]+),friction\.ice_structure=([\d.]+)$", config)
        if model not in TANK or not m:
            continue
        with open(path) as f:
            s = json.load(f)["summary"]
        if s.get("status") == "complete" and s.get("max_fx_N") is not None:
            out.setdefault(model, {}).setdefault((float(m[1]), float(m[2])), []).append(float(s["max_fx_N"]))
    return out


def gumbel_exceedance(u, beta, x):
    """P(X >= x) for a Gumbel type I of location u and scale beta."""
    return 1.0 - math.exp(-math.exp(-(x - u) / beta)) if beta > 0 else float(x <= u)


def model_table(model, configs):
    tank, basis = TANK[model]
    lines = [f"### {model}: the tank's {tank:.0f} N; {basis}", "",
             "| f_ii | f_is | runs | maxima: mean, largest N | runs reaching the tank (95 %) | Gumbel u, β N | "
             "Gumbel P(max ≥ tank) |", "|---|---|---|---|---|---|---|"]
    for (fii, fis), maxima in sorted(configs.items()):
        x = np.array(maxima)
        u, beta = gumbel_fit(x)
        reach = share_text(int((x >= tank).sum()), len(x))
        lines.append(f"| {fii} | {fis} | {len(x)} | {x.mean():.1f}, {x.max():.1f} | {reach} "
                     f"| {u:.1f}, {beta:.1f} | {100 * gumbel_exceedance(u, beta, tank):.1f} % |")
    pooled = np.array([v for k in REFERENCE for v in configs.get(k, [])])
    if len(pooled):
        u, beta = gumbel_fit(pooled)
        lines += ["", f"At the reference friction (f_ii 0.5, f_is 0.2 and 0.3 pooled, {len(pooled)} runs): "
                  f"{share_text(int((pooled >= tank).sum()), len(pooled))} of the runs reach the tank's {tank:.0f} N; the "
                  f"Gumbel fit of their maxima (u {u:.1f} N, β {beta:.1f} N) gives {100 * gumbel_exceedance(u, beta, tank):.1f} % "
                  f"for one run, as the tank's one run per condition; the largest of them is {pooled.max():.1f} N. "
                  "Pooled over two frictions, the maxima are a mixture of two distributions (the steps in the "
                  "probability plot): the fit is a summary, the counts are exact.", ""]
    return lines, pooled


def probability_plot(pooled, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
    fig, axes = plt.subplots(1, len(pooled), figsize=(4 * len(pooled), 3.6), sharey=False)
    for ax, (model, x) in zip(np.atleast_1d(axes), pooled.items()):
        x = np.sort(x)
        n = len(x)
        p = (np.arange(1, n + 1) - 0.44) / (n + 0.12)  # Gringorten's plotting positions
        ax.plot(-np.log(-np.log(p)), x, "o", ms=4, label="run maxima")
        u, beta = gumbel_fit(x)
        y = np.linspace(-1.6, 4.5, 50)
        ax.plot(y, u + beta * y, "-", lw=1, label="Gumbel fit")
        tank, _ = TANK[model]
        ax.axhline(tank, color="C3", ls="--", lw=1, label=f"tank {tank:.0f} N")
        ax.set_title(model, fontsize=9)
        ax.set_xlabel("Gumbel reduced variate -ln(-ln p)")
        ax.set_ylabel("run max surge load, N")
        ax.legend(fontsize=7)
    fig.tight_layout()
    output_guard.save_figure(fig, path, dpi=110)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--records", default=os.path.join(ROOT, "docs", "paper_reproduction", "records"))
    ap.add_argument("--report", default=os.path.join(ROOT, "docs", "model", "tank_maxima.md"))
    ap.add_argument("--figure", help="the probability plot (default: beside the report, tank_maxima.png)")
    ap.add_argument("--filter-runs", metavar="SWEEP_DIR",
                    help="first filter the budget's runs in SWEEP_DIR (sweeps/load_budget) into --filtered")
    ap.add_argument("--filtered", default=FILTERED_RECORDS, help="the filtered maxima's records (JSON)")
    a = ap.parse_args(argv)
    figure = a.figure or os.path.splitext(a.report)[0] + ".png"
    outputs = [("--report", a.report, output_guard.FILE), ("--figure", figure, output_guard.FILE)]
    if a.filter_runs:
        outputs.append(("--filtered", a.filtered, output_guard.FILE))
    output_guard.guard(outputs)
    filtered = None
    if a.filter_runs:
        filtered = filter_runs(a.filter_runs, a.filtered)
    elif os.path.exists(a.filtered):
        with open(a.filtered) as f:
            filtered = json.load(f)
    maxima = read_maxima(a.records)
    if not maxima:
        print(f"tank_maxima: no records of the paper grid in {a.records}", file=sys.stderr)
        return 2
    lines = ["# The tank's largest load against the runs' maxima", "",
             f"Made by `scripts/tank_maxima` from the records in `{os.path.relpath(a.records, ROOT)}` (one per "
             "finished run of the paper grid, sweeps/paper_grid.toml, at the default of their build). The tank "
             "gives one number per condition, the largest load of its one run; the paper report's \"max\" is the "
             "mean over seeds of each run's maximum. Here the tank's number is set against the distribution of "
             "the runs' maxima instead. The shares' intervals are Clopper-Pearson's (95 %); the Gumbel fit is the "
             "moment fit (docs/model/validation_targets.md §7).", "",
             f"![run maxima on Gumbel paper at the reference friction]({os.path.basename(figure)})", ""]
    pooled = {}
    for model in TANK:
        if model in maxima:
            table, pooled[model] = model_table(model, maxima[model])
            lines += table
    if filtered:
        lines += filtered_table(filtered)
    probability_plot({m: x for m, x in pooled.items() if len(x)}, figure)
    text = "\n".join(lines) + "\n"
    print(text)
    output_guard.write_text(a.report, text)
    print(f"wrote {a.report} and {figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
