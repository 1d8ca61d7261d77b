"""The one way the tools run icedem: `run_args` is its command line, `execute` runs it once in
a directory and says what happened (exit code, log, summary, CPU and wall time). Many runs go
through a sweep (execute.py: GNU parallel or Slurm over the same command line); the ladder, the
convergence study and the stress suite are sweeps too (sweeps/studies/).

CPU time, not wall time, is what the benchmarks compare: on a shared machine the wall time of
one setting drifted by 2x within an hour, the CPU time of a single-threaded run much less. It is
the CPU time of icedem and of the processes it waited for (OpenFOAM, the coupling partner).
"""
import dataclasses
import json
import os
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))  # tools/icedem_tools/runs/
DEFAULT_ICEDEM = os.path.join(ROOT, "build", "dem", "icedem")


@dataclasses.dataclass
class Run:
    command: list        # the command line
    returncode: int      # icedem's exit code (docs/user/commands.md)
    log: str             # what it printed (stdout and stderr)
    cpu_time_s: float    # user + system of icedem and its children
    wall_time_s: float
    summary: dict        # the summary JSON, or None if none was written
    h5: str              # the HDF5 output path

    @property
    def ok(self):
        return self.returncode == 0 and self.summary is not None

    @property
    def error(self):
        """icedem's error line, else the last line of its log."""
        lines = self.log.strip().splitlines()
        return next((line for line in lines if line.startswith("error:")), lines[-1] if lines else "")


def sets_args(sets):
    """["--set", "a=1", "--set", "b=2"] for sets ["a=1", "b=2"]."""
    return [x for s in sets for x in ("--set", s)]


# A run's directory holds these, as a sweep's runs do (execute.py): one layout for every tool
RUN_FILES = {"h5": "run.h5", "summary": "summary.json", "log": "log.txt"}


def run_args(icedem, scenario, h5, summary, sets=()):
    """The argv of `icedem run SCENARIO -q -o H5 --summary-json SUMMARY --restart --set ...`: every
    tool (this runner, a sweep's job list) runs icedem with it. --restart: a tool starts a run over
    on purpose (a sweep's job resumes a killed run first, and starts over only one that cannot be)."""
    return [icedem, "run", scenario, "-q", "-o", h5, "--summary-json", summary, "--restart"] + sets_args(sets)


def resume_args(icedem, h5, summary):
    """The argv of `icedem resume H5 -q --summary-json SUMMARY`: a killed run continued from its
    checkpoint (H5.checkpoint)."""
    return [icedem, "resume", h5, "-q", "--summary-json", summary]


def execute(scenario, directory, sets=(), icedem=DEFAULT_ICEDEM, env=None, args=()):
    """Runs `icedem run scenario -q -o DIR/run.h5 --summary-json DIR/summary.json --set ...` (and
    `args`) in `directory`, its output in DIR/log.txt; never raises for a failed run."""
    os.makedirs(directory, exist_ok=True)
    h5, summary = (os.path.join(directory, RUN_FILES[k]) for k in ("h5", "summary"))
    if os.path.exists(summary):
        os.remove(summary)  # a summary left from an earlier run must not pass for this one's
    cmd = run_args(icedem, scenario, h5, summary, sets) + list(args)
    log_path = os.path.join(directory, RUN_FILES["log"])
    start = time.monotonic()
    with open(log_path, "w") as log:
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
        _, status, usage = os.wait4(proc.pid, 0)  # wait4: the CPU time of the run and its children
        proc.returncode = os.waitstatus_to_exitcode(status)  # reaped: Popen must not wait again
    wall = time.monotonic() - start
    with open(log_path) as f:
        text = f.read()
    data = None
    if os.path.exists(summary):
        with open(summary) as f:
            data = json.load(f)
    return Run(cmd, proc.returncode, text, usage.ru_utime + usage.ru_stime, wall, data, h5)
