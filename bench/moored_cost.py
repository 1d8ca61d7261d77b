#!/usr/bin/python3
"""What a moored structure costs against the towed one: the paper's small-floe run (seed 1) towed, moored
by the linear springs and moored by the four catenary lines, the three started together so that they share
the machine alike. Prints each run's CPU time, its ratio to the towed run's, the contact solve's iterations
a step and the awake bodies, and writes the table to bench/results/moored-cost-<date>.md.

    bench/moored_cost.py [--icedem BUILD/dem/icedem] [--duration 150] [--seed 1]

Compare the ratios, not the seconds, across machines or sessions (docs/model/performance.md).
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RUNS = [("towed", "scenarios/paper/small_floes.toml", []),
        ("moored, linear", "scenarios/moored/small_floes_moored.toml", []),
        ("moored, catenary", "scenarios/moored/small_floes_moored.toml", ['mooring.model="catenary"'])]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--icedem", default=os.path.join(ROOT, "build", "dem", "icedem"))
    ap.add_argument("--duration", type=float, default=150.0, help="s of tow (the ice arrives at about 49 s)")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as work:
        procs = []
        for i, (name, scenario, sets) in enumerate(RUNS):
            args = [a.icedem, "run", os.path.join(ROOT, scenario), "-q", "-o", os.path.join(work, f"{i}.h5"),
                    "--summary-json", os.path.join(work, f"{i}.json"), "--set", f"time.duration={a.duration}",
                    "--set", f"seed={a.seed}", "--set", "output.snapshot_interval=0"]
            for s in sets:
                args += ["--set", s]
            procs.append(subprocess.Popen(args, stdout=subprocess.DEVNULL))
        if any(p.wait() != 0 for p in procs):
            sys.exit("bench/moored_cost.py: a run failed")
        summaries = [json.load(open(os.path.join(work, f"{i}.json"))) for i in range(len(RUNS))]
    towed = summaries[0]["cpu_time_s"]
    lines = [f"# The moored structure's cost against the towed one ({datetime.date.today()})", "",
             f"`bench/moored_cost.py --duration {a.duration:g} --seed {a.seed}`: the paper's small floes, the three runs "
             "started together (CPU time of each icedem process).", "",
             "| run | CPU s | against towed | iterations a step | awake bodies | mean surge N |",
             "|---|---|---|---|---|---|"]
    for (name, _, _), s in zip(RUNS, summaries):
        lines.append(f"| {name} | {s['cpu_time_s']:.1f} | {s['cpu_time_s'] / towed:.2f} | "
                     f"{s['solver']['iterations_mean']:.1f} | {s['mean_awake']:.1f} | {s['mean_fx_N']:.2f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    path = os.path.join(ROOT, "bench", "results", f"moored-cost-{datetime.date.today():%Y%m%d}.md")
    with open(path, "w") as f:
        f.write(text)
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
