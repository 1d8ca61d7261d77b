"""Running a sweep's runs: one shell command per run, executed by GNU parallel
on this machine or by a Slurm job array, and the status of every run read back
from its directory (so a rerun skips what is finished, in any order).

A run's directory holds run.h5, summary.json, log.txt (stdout and stderr) and
exit_code, written last. A run is finished when exit_code is 0 and
summary.json exists, or when the sweep keeps records and its record exists
(spec.py: it was finished, perhaps on another machine); failed when exit_code
is not 0 (its error is the last "error" line of log.txt); pending otherwise
(never started, or killed: a rerun resumes it from its checkpoint, run.h5.checkpoint).
"""
import json
import os
import shlex
import subprocess
from dataclasses import dataclass

from ..runs.runner import RUN_FILES, resume_args, run_args
from ..runs.spec import ROOT

DEFAULT_ICEDEM = os.path.join(ROOT, "build", "dem", "icedem")


@dataclass
class Status:
    run: object   # spec.Run
    state: str    # "done", "failed" or "pending"
    error: str = ""
    exit_code: object = None  # icedem's exit code when its run directory holds one, else None


def cone_load(icedem, scenario, sets=()):
    """(`icedem cone-load SCENARIO --set ... --json`: the ISO 19906 and Ralston terms, None) or (None,
    why not): the reports say why rather than dropping their rows."""
    if not icedem or not os.path.isfile(icedem):
        return None, f"no build at {icedem}"
    cmd = [icedem, "cone-load", scenario]
    for s in sets:
        cmd += ["--set", s]
    p = subprocess.run(cmd + ["--json"], capture_output=True, text=True)
    if p.returncode != 0:
        first = (p.stderr.strip().splitlines() or ["no message"])[0]
        return None, f"`{icedem} cone-load --json` failed: {first}"
    return json.loads(p.stdout), None


def command(run, out_dir, icedem):
    """The shell command that runs `run` in its directory and records its exit code. A run that
    was killed (a lost node, a preempted or cancelled job) and left a checkpoint is resumed from
    it, its log appended to; one whose checkpoint cannot be resumed (exit 2: written by another
    version) starts over."""
    d = os.path.join(out_dir, run.path)
    h5, summary, log = RUN_FILES["h5"], RUN_FILES["summary"], RUN_FILES["log"]
    start = shlex.join(run_args(icedem, run.scenario_file, h5, summary, run.sets))
    resume = shlex.join(resume_args(icedem, h5, summary))
    return (f"mkdir -p {shlex.quote(d)} && cd {shlex.quote(d)} && rm -f exit_code {summary} && "
            f"if [ -f {h5}.checkpoint ]; then {resume} >> {log} 2>&1; code=$?; else code=2; rm -f {log}; fi; "
            f"if [ $code -eq 2 ]; then {start} >> {log} 2>&1; code=$?; fi; "
            f"echo $code > exit_code; exit $code")


def finished_here(run, out_dir):
    """True if the run's own directory holds a finished run (not only a kept record)."""
    d = os.path.join(out_dir, run.path)
    try:
        with open(os.path.join(d, "exit_code")) as f:
            return f.read().strip() == "0" and os.path.isfile(os.path.join(d, RUN_FILES["summary"]))
    except FileNotFoundError:
        return False


def status(run, out_dir):
    here = finished_here(run, out_dir)
    if here or (run.record_file and os.path.isfile(run.record_file)):
        return Status(run, "done", exit_code=0 if here else None)
    d = os.path.join(out_dir, run.path)
    try:
        with open(os.path.join(d, "exit_code")) as f:
            code = f.read().strip()
    except FileNotFoundError:
        return Status(run, "pending")
    error = f"exit code {code}"
    try:
        with open(os.path.join(d, "log.txt"), errors="replace") as f:
            lines = [l.strip() for l in f if l.strip()]
        errors = [l for l in lines if "error" in l.lower()]
        if errors or lines:
            error += ": " + (errors[-1] if errors else lines[-1])
    except FileNotFoundError:
        pass
    return Status(run, "failed", error, int(code) if code.lstrip("-").isdigit() else None)


def summary(run, out_dir):
    """The summary of a run finished in its directory, with run_dir (its directory) added; else
    {"status": "failed" or "pending", "message": why}."""
    if not finished_here(run, out_dir):
        st = status(run, out_dir)
        return {"status": "failed" if st.state == "failed" else "pending", "message": st.error or "not run here yet"}
    d = os.path.join(out_dir, run.path)
    from ..runs.results import load_summary  # numpy and h5py: not needed to run a sweep
    return dict(load_summary(os.path.join(d, RUN_FILES["summary"])), run_dir=d)


def run_here(runs, out_dir, icedem, jobs=0):
    """Make sure the runs' own directories hold them (their HDF5 files, for figures), running
    again with GNU parallel those known only by a kept record: runs are deterministic, so the
    rerun writes the same results."""
    missing = [r for r in runs if not finished_here(r, out_dir)]
    if missing:
        run_parallel_all(missing, out_dir, icedem, jobs)
    return [r for r in runs if finished_here(r, out_dir)]


def write_jobs(runs, out_dir, icedem, path):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        for r in runs:
            f.write(command(r, out_dir, icedem) + "\n")


def run_parallel(runs, out_dir, icedem, jobs=0):
    """Run every unfinished run with GNU parallel (jobs 0: one per core). Returns the statuses."""
    run_parallel_all([r for r in runs if status(r, out_dir).state != "done"], out_dir, icedem, jobs)
    return [status(r, out_dir) for r in runs]


def run_parallel_all(todo, out_dir, icedem, jobs=0):
    """Run the given runs with GNU parallel, finished or not."""
    if todo:
        # one list per invocation: a second one (figures rerunning a run) must not rewrite
        # the list a running sweep's GNU parallel is still reading
        jobs_file = os.path.join(out_dir, f"jobs-{os.getpid()}.txt")
        write_jobs(todo, out_dir, icedem, jobs_file)
        cmd = ["parallel", "--will-cite", "--jobs", str(jobs) if jobs > 0 else "100%",
               # "+": append, so the log keeps every session of a resumed sweep
               "--joblog", "+" + os.path.join(out_dir, "joblog.txt"), "--arg-file", jobs_file]
        # parallel's exit code counts failed jobs; the statuses below report them one by one
        subprocess.run(cmd, check=False)


def slurm_script(runs, out_dir, icedem, name):
    """Write a Slurm job-array script for the unfinished runs; returns (script path, task count)."""
    todo = [r for r in runs if status(r, out_dir).state != "done"]
    sdir = os.path.join(out_dir, "slurm")
    jobs_file = os.path.join(sdir, "jobs.txt")
    write_jobs(todo, out_dir, icedem, jobs_file)
    script = os.path.join(sdir, "array.sh")
    with open(script, "w") as f:
        f.write(f"""#!/bin/bash
# icedem sweep "{name}": {len(todo)} runs, one per array task (scripts/sweep slurm)
#SBATCH --job-name=icedem-{name}
#SBATCH --array=0-{max(len(todo) - 1, 0)}
#SBATCH --cpus-per-task=1
#SBATCH --output={sdir}/task-%a.out
#SBATCH --open-mode=append
# a preempted or failed node's task goes back in the queue, and resumes its run from the
# checkpoint it left (at SIGTERM icedem goes on to its next checkpoint if it can reach it
# within output.stop_grace, else stops at once: the checkpoint is then at most
# output.checkpoint_interval behind)
#SBATCH --requeue
line=$(sed -n "$((SLURM_ARRAY_TASK_ID + 1))p" {shlex.quote(jobs_file)})
exec bash -c "$line"
""")
    return script, len(todo)


def submit_slurm(script, wait=True):
    """sbatch the array script; with wait, block until every task ends (exit code: the highest)."""
    cmd = ["sbatch"] + (["--wait"] if wait else []) + [script]
    return subprocess.run(cmd, check=False).returncode
