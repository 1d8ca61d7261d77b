#!/usr/bin/python3
"""The contact solve's own error on a full run, free of the trajectory's chaos.

    bench/contact/run_errors.py SCENARIO OUTDIR [--set KEY=VALUE ...] [--every 1.0] [--peaks 20]
                                [--icedem build/dem/icedem] [--tools build/bench/contact/contact_problems]

Two runs of the same scenario differ in their loads for two reasons: the solve's error in
each step, and the chaos of a pack, which grows any difference (a round-off, another
tolerance, another step) into another trajectory. Comparing runs at two tolerances mixes
the two, and five seeds resolve a difference of maxima only to 13-41 %. This script
measures the first alone: it runs the scenario once (OUTDIR/run.h5), runs it again (the
runs are deterministic) writing the contact problems of sampled steps (every `--every`
seconds of the analysis window, and the `--peaks` steps of the largest surge load), then
solves every island that touches the structure or holds joints again to a merit of about
1e-10 (contact_problems errors) and compares, step by step, the load on the structure and
the joints' loads the run's solve gave with the tight ones. The same trajectory, so the
difference is the solve's and nothing else.

Writes OUTDIR/errors.csv (every island and answer) and OUTDIR/report.md; prints the
report. Checkpoints are off in both runs (a checkpoint rebuilds the world, and a rebuilt
lattice world departs from an unbroken run in its last bits).
"""
import argparse
import glob
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
from icedem_tools.runs import results  # noqa: E402


def run(cmd):
    print("  " + " ".join(a if len(a) < 200 else a[:60] + " ..." for a in cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def sample_times(run_file, every, peaks):
    """Times of the steps to export: every `every` s over the analysis window, and the `peaks`
    steps of the largest surge load at least 1 s apart (so one load event counts once)."""
    t, surge = np.asarray(run_file["/load/time"]), np.asarray(run_file["/load/surge"])
    start = float(run_file.stats.get("window_start_s", t[0]))
    in_window = t >= start
    regular = t[in_window][::max(1, int(round(every / np.median(np.diff(t)))))]
    top = []
    for i in np.argsort(-np.where(in_window, surge, -np.inf)):
        if len(top) >= peaks:
            break
        if all(abs(t[i] - t[j]) >= 1.0 for j in top):
            top.append(i)
    return regular, t[top]


def per_step(rows, answer):
    """{time: (load vector N, joint force error N, joint moment error N m)} summed (load) or
    maximised (joints) over the islands of each step, for one answer."""
    out = {}
    for r in rows[rows["answer"] == answer]:
        load, df, dm = out.get(r["time"], (np.zeros(3), 0.0, 0.0))
        out[r["time"]] = (load + [r["load_x"], r["load_y"], r["load_z"]],
                          max(df, r["joint_force_error_n"]), max(dm, r["joint_moment_error_nm"]))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scenario")
    ap.add_argument("outdir")
    ap.add_argument("--set", action="append", default=[], help="a scenario key, as icedem run --set")
    ap.add_argument("--every", type=float, default=1.0, help="s between sampled steps (default 1)")
    ap.add_argument("--peaks", type=int, default=20, help="steps of the largest surge load (default 20)")
    ap.add_argument("--icedem", default=os.path.join(ROOT, "build", "dem", "icedem"))
    ap.add_argument("--tools", default=os.path.join(ROOT, "build", "bench", "contact", "contact_problems"))
    args = ap.parse_args()

    os.makedirs(args.outdir, exist_ok=True)
    sets = [a for s in args.set + ["output.checkpoint_interval=0", "output.snapshot_interval=0"] for a in ("--set", s)]
    first = os.path.join(args.outdir, "run.h5")
    if results.status(first) != "complete":
        run([args.icedem, "run", args.scenario, "-o", first, "-q", *sets])
    run_file = results.load_run(first)
    regular, peak_times = sample_times(run_file, args.every, args.peaks)
    problems = os.path.join(args.outdir, "problems")
    if not glob.glob(os.path.join(problems, "*.hdf5")):
        # a step exports when a time falls in (its end - h, its end]: ask at the middle of
        # the last Bullet step, so that a time's round-off cannot pick the next step
        scen = run_file.scenario["time"]
        half = 0.5 * scen["dt"] / scen.get("substeps", 1)
        times = ",".join(f"{x - half:.6f}" for x in sorted(set(regular) | set(peak_times)))
        run([args.icedem, "run", args.scenario, "-o", os.path.join(args.outdir, "export.h5"), "-q", *sets,
             "--export-problems", problems, "--export-at", times, "--export-min-contacts", "1"])
    csv = os.path.join(args.outdir, "errors.csv")
    if not os.path.exists(csv):
        files = sorted(glob.glob(os.path.join(problems, "*.hdf5")))
        run([args.tools, "errors", *files, "--loaded-only", "--tolerance", "1e-5", "--max-iterations", "10000",
             "--csv", csv + ".tmp"])
        os.replace(csv + ".tmp", csv)
    rows = np.genfromtxt(csv, delimiter=",", names=True, dtype=None, encoding="utf-8")
    report = make_report(args, run_file, rows, peak_times)
    with open(os.path.join(args.outdir, "report.md"), "w") as f:
        f.write(report)
    print(report)


def make_report(args, run_file, rows, peak_times):
    scen = run_file.scenario
    travel = -1.0 if scen["structure"]["speed"] < 0 else 1.0
    tight, ran = per_step(rows, "tight"), per_step(rows, "run")
    times = np.array(sorted(t for t in tight if t in ran))
    surge_tight = np.array([-tight[t][0][0] * travel for t in times])
    surge_run = np.array([-ran[t][0][0] * travel for t in times])
    load_error = np.array([np.linalg.norm(ran[t][0] - tight[t][0]) for t in times])
    # the reported load is the step's mean (it sums the substeps' impulses): compare it there
    mean_surge = float(np.mean(np.abs(np.asarray(run_file["/load/surge"]))))
    is_peak = np.isin(np.round(times, 6), np.round(peak_times, 6))
    lines = [f"# The contact solve's error on a full run: {os.path.basename(args.scenario)}",
             "",
             f"`bench/contact/run_errors.py {' '.join(sys.argv[1:])}`; sets: {', '.join(args.set) or 'none'}.",
             f"{len(times)} sampled steps ({int(is_peak.sum())} of them the largest loads), "
             f"{len(set(rows['problem']))} islands that touch the structure or hold joints, "
             "each solved again to a merit of about 1e-10: the run's answer against that, on the same state.",
             "",
             "| | steps | median | p99 | max |",
             "|---|---|---|---|---|"]

    def stat_row(name, x):
        return f"| {name} | {len(x)} | {np.median(x):.3g} | {np.percentile(x, 99):.3g} | {np.max(x):.3g} |" if len(x) else \
            f"| {name} | 0 | | | |"
    lines.append(stat_row("load error on the structure, N", load_error))
    rel = load_error / np.maximum(np.abs(surge_tight), mean_surge)
    lines.append(stat_row("the same / max(surge, the run's mean surge)", rel))
    peak_rel = np.abs(surge_run[is_peak] - surge_tight[is_peak]) / np.abs(surge_tight[is_peak])
    lines.append(stat_row("surge error at the peaks / the peak", peak_rel))
    joint_rows = rows[(rows["answer"] == "run") & (rows["joint_rows"] > 0)]
    if len(joint_rows):
        ice, fracture = scen["ice"], scen["fracture"]
        L, T = fracture["element_size"], ice["thickness"]
        shear_capacity = L * T * ice["shear_strength"]            # N (eq. 2)
        bending_capacity = L * T * T * ice["bending_strength"] / 6.0  # N m (eq. 3)
        df = np.array([ran[t][1] for t in times]) / shear_capacity
        dm = np.array([ran[t][2] for t in times]) / bending_capacity
        lines.append(stat_row("joint force error / shear capacity (worst row of the step)", df))
        lines.append(stat_row("joint moment error / bending capacity (worst row of the step)", dm))
    merit = rows[rows["answer"] == "tight"]["merit"]
    lines += ["", f"Tight answers: merit median {np.median(merit):.1e}, largest {np.max(merit):.1e}.",
              f"Peaks: surge {np.max(surge_tight[is_peak]) if is_peak.any() else float('nan'):.2f} N tight, "
              f"{np.max(surge_run[is_peak]) if is_peak.any() else float('nan'):.2f} N the run's.", ""]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()
