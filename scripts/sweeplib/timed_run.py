"""One icedem run in its own directory, timed in CPU seconds and reused when
already finished with the same command (scripts/ladder and scripts/convergence).

CPU time, not wall time, is what the benchmarks compare: on a shared machine
the wall time of one setting drifted by 2x within an hour, the CPU time of a
single-threaded run much less.
"""
import json
import os
import subprocess


def run(icedem, scenario, sets, seed, directory):
    """Run `icedem run scenario --set ... --set seed=N` in `directory` (run.h5,
    summary.json, log.txt, cpu_time_s, command). Returns the summary with
    cpu_time_s and run_dir added, or {"status": "failed", "message": ...}."""
    os.makedirs(directory, exist_ok=True)
    summary, cpu_file = os.path.join(directory, "summary.json"), os.path.join(directory, "cpu_time_s")
    cmd = [icedem, "run", scenario, "-q", "-o", os.path.join(directory, "run.h5"),
           "--summary-json", summary] + [x for s in list(sets) + [f"seed={seed}"] for x in ("--set", s)]
    stamp = os.path.join(directory, "command")
    if all(map(os.path.exists, (summary, stamp, cpu_file))) and open(stamp).read() == " ".join(cmd):
        return dict(json.load(open(summary)), cpu_time_s=float(open(cpu_file).read()), run_dir=directory)
    for stale in (summary, stamp, cpu_file):
        if os.path.exists(stale):
            os.remove(stale)
    with open(os.path.join(directory, "log.txt"), "w") as log:
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0 or not os.path.exists(summary):
        lines = open(os.path.join(directory, "log.txt")).read().strip().splitlines()
        return {"status": "failed",
                "message": next((l for l in lines if l.startswith("error:")), lines[-1] if lines else "")}
    cpu = usage.ru_utime + usage.ru_stime
    with open(cpu_file, "w") as f:
        f.write(f"{cpu:.3f}")
    with open(stamp, "w") as f:
        f.write(" ".join(cmd))
    return dict(json.load(open(summary)), cpu_time_s=cpu, run_dir=directory)
