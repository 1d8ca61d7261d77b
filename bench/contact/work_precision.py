#!/usr/bin/python3
"""Work-precision benchmark of the contact methods on a library of problem files.

    bench/contact/work_precision.py DIR... [--methods pgs_square,newton,...] [--tolerances 1e-2,1e-4,1e-6]
        [--max-iterations N] [--timeout S] [--out PREFIX] [--tool build/bench/contact/contact_problems]

For every method, tolerance and problem it runs `contact_problems solve` (one merit for
every method: natural_map_residual, docs/model/contact_problems.md) and records the
merit reached and the CPU time. It prints, per method and tolerance, how many problems
reached the tolerance and the median and total CPU time, and writes PREFIX.csv (every
solve) and PREFIX.png (the share of problems solved against CPU time per problem, one
curve per method and tolerance: a performance profile). A solve that runs past
--timeout seconds counts as not reaching the tolerance.
"""
import argparse
import csv
import glob
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def solve(tool, path, method, tolerance, max_iterations, timeout):
    cmd = [tool, "solve", path, "--method", method, "--tolerance", str(tolerance), "--max-iterations",
           str(max_iterations)]
    try:
        out = subprocess.run(cmd, check=True, capture_output=True, text=True, timeout=timeout).stdout
    except subprocess.TimeoutExpired:
        return None, float(timeout), None
    fields = out.strip().splitlines()[-1].split()
    # problem contacts joints method iters merit cpu_ms
    return float(fields[5]), float(fields[6]) / 1e3, int(fields[4])


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("dirs", nargs="+")
    p.add_argument("--methods", default="pgs_square,pgs_cone,newton,siconos_nsgs,siconos_nsn_ac")
    p.add_argument("--tolerances", default="1e-3,1e-6")
    p.add_argument("--max-iterations", type=int, default=1000)
    p.add_argument("--timeout", type=float, default=60.0)
    p.add_argument("--out", default="work_precision")
    p.add_argument("--tool", default=os.path.join(ROOT, "build", "bench", "contact", "contact_problems"))
    a = p.parse_args()
    files = sorted(f for d in a.dirs for f in glob.glob(os.path.join(d, "*.hdf5")))
    if not files:
        sys.exit("no problem files (*.hdf5) in " + ", ".join(a.dirs))
    methods = a.methods.split(",")
    tolerances = [float(t) for t in a.tolerances.split(",")]
    rows = []
    for path in files:
        for method in methods:
            for tol in tolerances:
                merit, cpu, iters = solve(a.tool, path, method, tol, a.max_iterations, a.timeout)
                rows.append({"problem": os.path.basename(path), "method": method, "tolerance": tol,
                             "merit": merit, "cpu_s": cpu, "iterations": iters,
                             "reached": merit is not None and merit <= tol})
                print(f"{os.path.basename(path):40s} {method:16s} {tol:8.0e} "
                      f"{'timeout' if merit is None else f'{merit:9.2e}'} {cpu:9.4f} s", flush=True)
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)

    print(f"\n{len(files)} problems; CPU per problem")
    print(f"{'method':16s} {'tolerance':>9s} {'reached':>9s} {'median s':>9s} {'total s':>9s}")
    curves = []
    for method in methods:
        for tol in tolerances:
            sel = [r for r in rows if r["method"] == method and r["tolerance"] == tol]
            reached = sorted(r["cpu_s"] for r in sel if r["reached"])
            cpus = sorted(r["cpu_s"] for r in sel)
            median = cpus[len(cpus) // 2]
            print(f"{method:16s} {tol:9.0e} {len(reached):4d}/{len(sel):<4d} {median:9.4f} {sum(cpus):9.3f}")
            curves.append((method, tol, reached, len(sel)))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for method, tol, reached, n in curves:
        if not reached:
            continue
        ys = [(i + 1) / n for i in range(len(reached))]
        ax.step(reached, ys, where="post", label=f"{method}, {tol:.0e}")
    ax.set_xscale("log")
    ax.set_xlabel("CPU time per problem, s")
    ax.set_ylabel("share of problems solved to the tolerance")
    ax.set_ylim(0, 1.02)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    ax.set_title(f"Contact methods on {len(files)} problems (merit: natural-map residual)")
    fig.tight_layout()
    fig.savefig(a.out + ".png", dpi=120)
    print(f"\nwrote {a.out}.csv and {a.out}.png")


if __name__ == "__main__":
    main()
