"""Parameter sweeps of icedem runs: scenarios x grid of --set overrides x seeds.

    scripts/sweep expand SWEEP.toml               list the runs
    scripts/sweep run SWEEP.toml [--jobs N]       run the unfinished ones with GNU parallel
    scripts/sweep slurm SWEEP.toml [--submit]     write (and submit) a Slurm job array instead
    scripts/sweep status SWEEP.toml               finished, failed and pending runs
    scripts/sweep aggregate SWEEP.toml            per configuration over seeds: OUT/results.{csv,h5}

Common options: --out DIR (default sweeps/<name> in the repository), --icedem
PATH (default build/dem/icedem). The sweep file format is in
tools/icedem_tools/runs/spec.py; examples in sweeps/*.toml. A rerun skips finished
runs; failed runs are rerun and every failure is reported with its error.
Exit code: 0 when every run is finished, 1 when some failed or are pending,
2 for a bad sweep file.
"""
import argparse
import os
import sys

from . import execute
from ..runs import output_guard, spec


def report(statuses):
    done = sum(s.state == "done" for s in statuses)
    failed = [s for s in statuses if s.state == "failed"]
    pending = [s for s in statuses if s.state == "pending"]
    print(f"{len(statuses)} runs: {done} finished, {len(failed)} failed, {len(pending)} pending")
    for s in failed:
        print(f"  FAILED {s.run.path}: {s.error}")
    for s in pending:
        print(f"  pending {s.run.path}")
    return 0 if done == len(statuses) else 1


def main(argv=None):
    try:
        return _main(argv)
    except BrokenPipeError:
        # `scripts/sweep status X | head`: the reader closed the pipe, having what it wanted;
        # point stdout at /dev/null so Python's exit-time flush does not raise again
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1


def _main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("command", choices=["expand", "run", "slurm", "status", "aggregate"])
    ap.add_argument("sweep")
    ap.add_argument("--out")
    ap.add_argument("--icedem", default=execute.DEFAULT_ICEDEM)
    ap.add_argument("--jobs", type=int, default=0, help="parallel jobs (0: one per core)")
    ap.add_argument("--submit", action="store_true", help="slurm: sbatch --wait the array")
    args = ap.parse_args(argv)
    try:
        name, runs = spec.load(args.sweep)
    except spec.SweepError as e:
        print(f"sweep: {e}", file=sys.stderr)
        return 2
    out = os.path.abspath(args.out or os.path.join(spec.ROOT, "sweeps", name))
    output_guard.guard([("--out", out, output_guard.DIRECTORY)], [args.sweep])
    if args.command == "expand":
        for r in runs:
            print(f"{r.path}: {os.path.relpath(r.scenario_file, spec.ROOT)} " + " ".join(f"--set {s}" for s in r.sets))
        print(f"{len(runs)} runs, {len({r.config for r in runs})} configurations")
        return 0
    if args.command in ("run", "slurm") and not os.access(args.icedem, os.X_OK):
        print(f"sweep: no icedem executable at {args.icedem} (build it: scripts/setup.sh)", file=sys.stderr)
        return 2
    if args.command == "run":
        return report(execute.run_parallel(runs, out, os.path.abspath(args.icedem), args.jobs))
    if args.command == "slurm":
        script, n = execute.slurm_script(runs, out, os.path.abspath(args.icedem), name)
        print(f"wrote {script} ({n} unfinished runs)")
        if not args.submit:
            print(f"submit with: sbatch {script}")
            return 0
        if n:
            execute.submit_slurm(script)
        return report([execute.status(r, out) for r in runs])
    if args.command == "aggregate":
        return aggregate(runs, out)
    return report([execute.status(r, out) for r in runs])


def aggregate(runs, out):
    from icedem_tools.sweeps import aggregate as agg  # numpy, scipy, h5py: only needed here
    groups = {}
    missing = 0
    for r in runs:
        scenario, labels, records = groups.setdefault(r.config, (r.scenario, r.labels, []))
        if execute.status(r, out).state == "done":
            records.append(agg.run_record(r, out))
        else:
            missing += 1
    rows, spectra = agg.aggregate(groups)
    os.makedirs(out, exist_ok=True)  # a sweep known only by its kept records has no directory yet
    agg.write_csv(rows, os.path.join(out, "results.csv"))
    agg.write_hdf5(rows, os.path.join(out, "results.h5"), spectra)
    print(f"{'configuration':50s} seeds  mean N (95% CI)   max N (95% CI)    peak s  spectral s")
    for row in rows:
        print(f"{row['configuration']:50s} {row['seeds']:5d}  {row['mean_fx_N']:6.2f} +- {row['mean_fx_N_ci95']:5.2f}"
              f"  {row['max_fx_N']:6.2f} +- {row['max_fx_N_ci95']:5.2f}  {row['peak_interval_s']:6.2f}"
              f"  {row['spectral_peak_period_s']:6.2f}")
    for config, counts in agg.mixed_builds(groups).items():
        print(f"note: {config}: its runs were made by {len(counts)} builds ("
              + ", ".join(f"{b}: {n}" for b, n in sorted(counts.items())) + ")")
    print(f"wrote {out}/results.csv and results.h5" + (f"; {missing} runs not finished were left out" if missing else ""))
    return 0 if missing == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
