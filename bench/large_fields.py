#!/usr/bin/python3
"""Cost against field size: the paper's small-floe scenario with its channel made longer, the
structure and its disturbed ice the same. Prints CPU time per step against total and awake
floes, the ratio to the paper's 24 m field, peak memory and output size, and writes the table
to bench/results/large-fields-<date>.md.

    bench/large_fields.py [--icedem BUILD/dem/icedem] [--duration 110] [--lengths 24,240,2400]

Runs one after another, so that each has a core of its own; compare the ratios, not the
seconds, across machines or sessions (docs/model/performance.md).
"""
import argparse
import datetime
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(icedem, length, duration, work):
    out = os.path.join(work, f"field_{length}.h5")
    summary = os.path.join(work, f"field_{length}.json")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    subprocess.run([icedem, "run", os.path.join(ROOT, "scenarios/paper/small_floes.toml"), "-q",
                    "--set", f"time.duration={duration}", "--set", f"channel.length={length}",
                    "-o", out, "--summary-json", summary], check=True, stdout=subprocess.DEVNULL)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(summary) as f:
        s = json.load(f)
    size = os.path.getsize(out)
    for name in os.listdir(work):  # keep the disk free for the next, larger run
        os.remove(os.path.join(work, name))
    return {
        "length": length,
        "floes": s["floes"],
        "steps": s["steps"],
        "awake": s["mean_awake"],
        "cpu": (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime),
        "wall": wall,
        "peak_mb": after.ru_maxrss / 1024.0,  # the largest child so far: runs go from small to large
        "mb": size / 1e6,
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--icedem", default=os.path.join(ROOT, "build/dem/icedem"))
    p.add_argument("--duration", type=float, default=110.0)
    p.add_argument("--lengths", default="24,240,2400")
    a = p.parse_args()
    lengths = [float(x) for x in a.lengths.split(",")]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for length in lengths:
            rows.append(run(a.icedem, length, a.duration, work))
            r = rows[-1]
            print(f"  {length:g} m: {r['floes']} floes, {r['cpu']:.1f} s CPU", file=sys.stderr)
    base = rows[0]
    lines = [
        f"Small floes, {a.duration:g} s simulated, channel length varied, runs one after another "
        f"({datetime.date.today()}, {os.uname().nodename}):",
        "",
        "| channel | floes | awake on average | CPU s | CPU ratio | ms CPU per step | "
        "us per step per floe | peak memory MB | output MB | output ratio |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        per_step = 1e3 * r["cpu"] / r["steps"]
        lines.append(f"| {r['length']:g} m | {r['floes']} | {r['awake']:.0f} | {r['cpu']:.1f} | "
                     f"{r['cpu'] / base['cpu']:.2f} | {per_step:.2f} | {1e3 * per_step / r['floes']:.3f} | "
                     f"{r['peak_mb']:.0f} | {r['mb']:.1f} | {r['mb'] / base['mb']:.1f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    results = os.path.join(ROOT, "bench/results")
    os.makedirs(results, exist_ok=True)
    with open(os.path.join(results, f"large-fields-{datetime.date.today():%Y%m%d}.md"), "w") as f:
        f.write("# Cost against field size (bench/large_fields.py)\n\n" + text)


if __name__ == "__main__":
    main()
