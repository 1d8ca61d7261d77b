#!/usr/bin/python3
"""Runs killed with SIGKILL and resumed end bit for bit as the uninterrupted run.

Usage: test_resume.py ICEDEM SOURCE_DIR WORK_DIR

Runs stopped by SIGTERM or Ctrl-C go on to their next checkpoint (output.stop_grace) and
resume from it bit for bit too; a second signal stops them at once.

The short tow (40 s) with a checkpoint every 5 s: run once uninterrupted; then killed with
SIGKILL once it has written its checkpoint at t = 5, 15 and 25 s, resumed with
`icedem resume`, and every dataset and the /stats attributes compared, bit for bit. A kill
during a checkpoint write is reproduced by what it leaves on the disk: a torn temporary
checkpoint and a torn output file. Then a run of breakable floes killed between two groups
of breaks, one of rigid floes that split (their pieces are bodies made mid-run), one of level ice cut by
closed forms (and crushing against its edge), a moored structure, one under the crushing contact law and floes
left behind. `icedem info` and refusals are checked on the way, and checkpoints changed or damaged after they were
written are refused.
"""
import json
import os
import signal
import subprocess
import sys
import time

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_files import checkpoint_time, contents  # noqa: E402

icedem, src, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
os.chdir(work)
os.environ["HDF5_USE_FILE_LOCKING"] = "FALSE"  # read checkpoints beside the writer
scenario = os.path.join(src, "scenarios/examples/short_tow.toml")
every = ["--set", "output.checkpoint_interval=5"]
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def run(*args, expect=0):
    p = subprocess.run([icedem, *args], capture_output=True, text=True)
    if p.returncode != expect:
        print(p.stdout, p.stderr)
    return p


def killed_at(name, t, scene=scenario, options=every):
    """Start a run, SIGKILL it once its checkpoint has reached t; True if it was killed in time."""
    for p in (name, name + ".checkpoint"):
        if os.path.exists(p):
            os.remove(p)
    proc = subprocess.Popen([icedem, "run", scene, "-q", "-o", name, *options],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    while proc.poll() is None and checkpoint_time(name + ".checkpoint") < t - 1e-9:
        time.sleep(0.002)
    if proc.poll() is not None:
        return False
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    return True


def killed_and_resumed(name, t, scene, options, full, what, kept):
    """Kill a run of `scene` after its checkpoint at t, resume it, and check it ends as `full`."""
    check(killed_at(name, t, scene, options), f"{what} killed after t = {t} s")
    p = run("resume", name, "-q")
    check(p.returncode == 0 and contents(name) == full,
          f"{what} resumed from t = {t} s: every dataset, {kept} and the statistics as uninterrupted")


p = run("run", scenario, "-q", "-o", "full.h5", *every)
check(p.returncode == 0 and not os.path.exists("full.h5.checkpoint"),
      "the uninterrupted run completes and leaves no checkpoint")
full = contents("full.h5")
# checkpointing itself changes nothing for rigid floes: the world rebuilt at each checkpoint
# solves in the same (canonical) order, and the load cell adds in that order too
p = run("run", scenario, "-q", "-o", "no_checkpoints_full.h5", "--set", "output.checkpoint_interval=0")
check(contents("no_checkpoints_full.h5") == full, "a rigid run with checkpoints is bit for bit one without")
p = run("resume", "full.h5", expect=2)
check(p.returncode == 2 and "nothing to resume" in p.stderr, "a complete run is not resumed (exit 2)")
check(contents("full.h5") == full, "... and its file is untouched")

for t in (5.0, 15.0, 25.0):
    name = f"killed_{t:.0f}.h5"
    check(killed_at(name, t), f"killed by SIGKILL after its checkpoint at t = {t} s")
    info = run("info", name).stdout
    check("running" in info and "killed" in info and f"resumable from t = {t:.2f} s" in info,
          f"icedem info: killed, resumable from t = {t} s")
    p = run("resume", name, "-q", "--summary-json", name + ".json")
    check(p.returncode == 0, f"resumed from t = {t} s (exit 0)")
    # the wall time counts every process of the run, as the stage times do: they add up to no
    # more than it (a resumed run's summary once counted only its own process: "other -0.9 s")
    summary = json.load(open(name + ".json"))
    stages = sum(v for k, v in summary["stage_time_s"].items() if k != "bullet")
    check(stages <= summary["wall_time_s"] and summary["cpu_time_s"] > 0,
          f"resumed from t = {t} s: wall time {summary['wall_time_s']:.2f} s covers the stages' {stages:.2f} s")
    same = contents(name) == full
    check(same, f"resumed from t = {t} s: every dataset and the statistics as the uninterrupted run's")
    check(not os.path.exists(name + ".checkpoint"), "the finished run's checkpoint is gone")

# SIGTERM (a Slurm preemption) or Ctrl-C: the run goes on to its next checkpoint when it
# can reach it within output.stop_grace, stops there (exit 143), and resumes from it losing
# nothing, bit for bit; a second signal, or no grace, stops it at once
def signalled(name, t, signals, options):
    """Start a run, send `signals` (0.2 s apart, the first 0.2 s after its checkpoint has
    reached t: mid-interval, not just after a checkpoint); (exit code, the checkpoint's time,
    the time its record ends, stderr)."""
    for p in (name, name + ".checkpoint"):
        if os.path.exists(p):
            os.remove(p)
    proc = subprocess.Popen([icedem, "run", scenario, "-q", "-o", name, *options],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    while proc.poll() is None and checkpoint_time(name + ".checkpoint") < t - 1e-9:
        time.sleep(0.002)
    for sig in signals:
        time.sleep(0.2)
        proc.send_signal(sig)
    _, err = proc.communicate()
    with h5py.File(name, "r") as f:
        ended = float(f["load/time"][-1])
    return proc.returncode, checkpoint_time(name + ".checkpoint"), ended, err


def on_grid(t, interval):
    return abs(t / interval - round(t / interval)) < 1e-6


code, at, ended, err = signalled("term.h5", 15.0, [signal.SIGTERM], every + ["--set", "output.stop_grace=600"])
check(code == 143 and at > 15.0 + 1e-6 and on_grid(at, 5.0) and abs(ended - at) < 1e-9
      and f"going on to the checkpoint at t = {at:.2f} s" in err,
      f"SIGTERM after t = 15 s: went on to its next checkpoint ({at:.2f} s) and stopped there (exit {code})")
p = run("resume", "term.h5", "-q")
check(p.returncode == 0 and contents("term.h5") == full,
      "resumed from the checkpoint it stopped at: every dataset and the statistics as the uninterrupted run")
code, at, ended, err = signalled("term_now.h5", 15.0, [signal.SIGTERM], every + ["--set", "output.stop_grace=0"])
check(code == 143 and at > 15.0 - 1e-6 and at <= ended and "going on" not in err,
      f"no grace: stopped at once (t = {ended:.2f} s; resumable from {at:.2f} s)")
code, at, ended, err = signalled("int_twice.h5", 15.0, [signal.SIGINT, signal.SIGINT],
                                 ["--set", "output.checkpoint_interval=15", "--set", "output.stop_grace=600"])
check(code == 130 and abs(at - 15.0) < 1e-9 and ended < 30.0 - 1e-9 and "going on to the checkpoint at t = 30.00" in err,
      f"Ctrl-C: going on to t = 30 s; a second Ctrl-C stopped it at once (t = {ended:.2f} s)")
p = run("resume", "int_twice.h5", "-q")
check(p.returncode == 0 and contents("int_twice.h5")["load/force"] == contents("no_checkpoints_full.h5")["load/force"],
      "... and it resumes from t = 15 s to the uninterrupted loads")

# a kill during a checkpoint write: the last checkpoint is whole, its temporary file torn, and
# the output itself may be torn too
name = "torn.h5"
check(killed_at(name, 15.0), "killed after its checkpoint at t = 15 s")
with open(name + ".checkpoint.tmp", "wb") as f:
    f.write(open(name + ".checkpoint", "rb").read()[:5000])
with open(name, "r+b") as f:
    f.truncate(3000)
p = run("resume", name, "-q")
check(p.returncode == 0 and contents(name) == full,
      "a torn checkpoint write and a torn output: resumed from the last checkpoint, as the uninterrupted run")

# breakable ice: the 0.20 m lattices of the bench field (55 s) with the default solver, a
# checkpoint every 9.75 s, and ice a third as strong in bending so that it breaks within
# 50 s (at the paper's strength the field's first break is at 89.9 s): joints break at
# 39.3-48.7 s and from 48.9 s on, around the checkpoint at 48.75 s where the run is killed
lattices = os.path.join(src, "scenarios/bench/large_breakable_short.toml")
lattice_options = ["--set", "solver.profile=converged", "--set", "time.duration=55",
                   "--set", "ice.bending_strength=12000", "--set", "output.checkpoint_interval=9.75"]
p = run("run", lattices, "-q", "-o", "lattice_full.h5", *lattice_options)
lattice_full = contents("lattice_full.h5")
with h5py.File("lattice_full.h5", "r") as f:
    breaks = f["fracture/events"]["time"]
    check((breaks < 48.75).any() and (breaks > 48.75).any(),
          f"the lattice run breaks joints before and after t = 48.75 s ({list(np.round(breaks, 2))})")
killed_and_resumed("lattice_killed.h5", 48.75, lattices, lattice_options, lattice_full, "the lattice run",
                   "the breaks")

# rigid floes that split (fracture.mode = "analytic"): the bench field's 0.6 m floes, whose
# splits add bodies to the world and to the output; split at 42-46, 61.8, 64.6-65.7 and
# from 71.3 s on, killed after the checkpoint at 68.25 s: the resumed world makes the pieces
# of the splits before it again, the resumed output holds them and adds those after it
split_options = ["--set", "fracture.mode=analytic", "--set", "solver.profile=converged",
                 "--set", "output.snapshot_interval=1", "--set", "output.checkpoint_interval=9.75"]
p = run("run", lattices, "-q", "-o", "split_full.h5", *split_options)
split_full = contents("split_full.h5")
with h5py.File("split_full.h5", "r") as f:
    splits = f["fracture/events"]["time"]
    pieces = int((f["bodies/parent"][:] >= 0).sum())
    check((splits < 68.25).any() and (splits > 68.25).any() and pieces == 2 * len(splits),
          f"the split run splits floes before and after t = 68.25 s, two pieces each ({list(np.round(splits, 2))}, "
          f"{pieces} pieces)")
killed_and_resumed("split_killed.h5", 68.25, lattices, split_options, split_full, "the split run", "the pieces")

# level ice cut by closed forms (the paper's tow of the analytic sheet, its first 12 s): its breaks cut the
# sheet's prisms and add pieces to the world and the output; killed after the checkpoint at 8 s, the resumed
# world cuts the sheet again as the run did and the resumed output holds its breaks and outlines and adds those
# after it
sheet_scenario = os.path.join(src, "scenarios/level_ice/level_ice_analytic.toml")
sheet_options = ["--set", "time.duration=12", "--set", "stats.window_start_travel=0",
                 "--set", "output.snapshot_interval=1", "--set", "output.checkpoint_interval=4"]
p = run("run", sheet_scenario, "-q", "-o", "sheet_full.h5", *sheet_options)
sheet_full = contents("sheet_full.h5")
with h5py.File("sheet_full.h5", "r") as f:
    cuts = f["sheet/breaks"]["time"]
    outlines = len(f["sheet/outline_end_row"])
    check((cuts < 8).any() and (cuts > 8).any() and outlines == len(cuts) + 1,
          f"the sheet breaks before and after t = 8 s, an outline after each ({list(np.round(cuts, 2))}, "
          f"{outlines} outlines)")
killed_and_resumed("sheet_killed.h5", 8, sheet_scenario, sheet_options, sheet_full, "the analytic sheet's run",
                   "the sheet's breaks")
# ... under the crushing law at the structure and the sheet's edge (contact.crushing_contacts = "structure_and_sheet"):
# the crushed depths of the floes' contacts with the sheet's prisms are kept across checkpoints as the cone's are
sheet_crushing = sheet_options + ["--set", 'contact.model="crushing"',
                                  "--set", 'contact.crushing_contacts="structure_and_sheet"']
p = run("run", sheet_scenario, "-q", "-o", "sheet_crushing_full.h5", *sheet_crushing)
sheet_crushing_full = contents("sheet_crushing_full.h5")
p = run("run", sheet_scenario, "-q", "-o", "sheet_crushing_no_checkpoints.h5", *sheet_crushing,
        "--set", "output.checkpoint_interval=0")
check(contents("sheet_crushing_no_checkpoints.h5") == sheet_crushing_full,
      "a run crushing against the sheet's edge with checkpoints is bit for bit one without")
killed_and_resumed("sheet_crushing_killed.h5", 8, sheet_scenario, sheet_crushing, sheet_crushing_full,
                   "the analytic sheet's run crushing against its edge", "the sheet's breaks")

# a moored structure (structure.motion = "moored"): its pose, velocities, last ice impulse and the
# history of its mooring's load are in the checkpoint; killed in the ice after the checkpoint at 25 s,
# the resumed run ends as the uninterrupted one, its motions, mooring load and summary included
moored_options = every + ["--set", 'structure.motion="moored"']
p = run("run", scenario, "-q", "-o", "moored_full.h5", *moored_options)
moored_full = contents("moored_full.h5")
with h5py.File("moored_full.h5", "r") as f:
    t, x = f["load/time"][:], f["structure/position"][:, 0]
    moving = np.abs(np.diff(f["structure/velocity"][:, 0])).max()
    check(p.returncode == 0 and (f["load/cone_contacts"][:][t > 25.0] > 0).any() and moving > 0,
          "the moored run meets the ice after t = 25 s and the ice moves the structure")
killed_and_resumed("moored_killed.h5", 25.0, scenario, moored_options, moored_full, "the moored run",
                   "the structure's motions and the mooring's load")

# the crushing contact law at the structure (contact.model = "crushing"): its bounds, hand-overs to Newton and each
# crushing manifold's crushed depth (dem/world/crushing_contact.hpp), which is in the checkpoint: the run rebuilds its
# world at each checkpoint, so a build that did not keep it parts from the run without checkpoints (at t = 30 s here);
# killed in the ice after the checkpoint at 25 s, the resumed run ends as the uninterrupted one
crushing_options = every + ["--set", 'contact.model="crushing"']
p = run("run", scenario, "-q", "-o", "crushing_full.h5", *crushing_options)
crushing_full = contents("crushing_full.h5")
p = run("run", scenario, "-q", "-o", "crushing_no_checkpoints.h5", "--set", 'contact.model="crushing"',
        "--set", "output.checkpoint_interval=0")
check(contents("crushing_no_checkpoints.h5") == crushing_full,
      "a crushing run with checkpoints is bit for bit one without (the crushed ice kept across each)")
with h5py.File("crushing_full.h5", "r") as f:
    t = f["load/time"][:]
    check(p.returncode == 0 and (f["load/cone_contacts"][:][(t > 20.0) & (t < 30.0)] > 0).any(),
          "the crushing run is in the ice around t = 25 s")
killed_and_resumed("crushing_killed.h5", 25.0, scenario, crushing_options, crushing_full, "the crushing run",
                   "the crushed ice")

# floes left behind (activation.leave_behind): the short tow started 1 m past its field's end and towed away
# from it, every floe in the world from the start, so that the line 2.5 m behind the cone sweeps the field and
# its floes leave the run a few at a time, before and after the checkpoint at 15 s; the resumed world takes out
# those that had left
left_options = every + ["--set", "structure.start_x=11.0", "--set", "activation.leave_behind=2.5",
                        "--set", "activation.unreached_out_of_world=false", "--set", "output.snapshot_interval=1"]
p = run("run", scenario, "-q", "-o", "left_full.h5", *left_options)
left_full = contents("left_full.h5")
sys.path.insert(0, os.path.join(src, "tools"))
from icedem_tools.runs import results  # noqa: E402
with h5py.File("left_full.h5", "r") as f:
    _, _, awake = results.snapshot_field(f)
    left = (awake == results.LEFT).sum(axis=1)
    times = f["snapshots/time"][:]
    check(p.returncode == 0 and left[times < 15].max() > 0 and left[-1] > left[times < 15].max()
          and left[-1] == awake.shape[1], f"floes leave before and after t = 15 s, every one by the end "
          f"({left[times < 15].max()} by 15 s, {left[-1]} of {awake.shape[1]})")
killed_and_resumed("left_killed.h5", 15.0, scenario, left_options, left_full, "the run leaving floes behind",
                   "the floes that had left")

# an output lost after the kill: its checkpoint alone resumes it
name = "lost.h5"
check(killed_at(name, 25.0), "killed after its checkpoint at t = 25 s")
os.remove(name)
p = run("resume", name, "-q")
check(p.returncode == 0 and contents(name) == full, "the output deleted after the kill: resumed from its checkpoint alone")

# an output torn beyond reading (cut inside HDF5's signature, as a full disk or a lost node can
# leave it): `icedem info` says it is resumable and how, the checkpoint named by itself is read as
# one, `run -o` refuses to start the killed run over (--restart does), and resume rebuilds the
# output from the checkpoint, keeping the torn file aside
name = "torn_signature.h5"
check(killed_at(name, 15.0), "killed after its checkpoint at t = 15 s (to tear its output)")
with open(name, "r+b") as f:
    f.truncate(4)
torn, saved = open(name, "rb").read(), open(name + ".checkpoint", "rb").read()
p = run("info", name)
check(p.returncode == 0 and "torn" in p.stdout and "resumable from t = 15.00 s" in p.stdout
      and f"icedem resume {name}" in p.stdout, f"icedem info on a torn output: resumable (exit {p.returncode})")
p = run("info", name + ".checkpoint")
check(p.returncode == 0 and f"the checkpoint of {name}" in p.stdout and "resumable from t = 15.00 s" in p.stdout,
      f"icedem info on the checkpoint by its own name reads it as one (exit {p.returncode})")
p = run("run", scenario, "-q", "-o", name, *every, expect=2)
check(p.returncode == 2 and "icedem resume" in p.stderr and "--restart" in p.stderr
      and open(name, "rb").read() == torn and open(name + ".checkpoint", "rb").read() == saved,
      f"run -o on the killed run refuses to start it over, naming resume and --restart, touching nothing: "
      f"{p.stderr.strip()[:120]}")
p = run("resume", name, "-q")
check(p.returncode == 0 and contents(name) == full and open(name + ".damaged", "rb").read() == torn,
      "the torn output resumed from its checkpoint: every dataset, the events and the statistics as the "
      "uninterrupted run; the torn file kept as .damaged")
name = "restarted.h5"
check(killed_at(name, 15.0), "killed after its checkpoint at t = 15 s (to start over)")
p = run("run", scenario, "-q", "-o", name, *every, "--restart")
check(p.returncode == 0 and contents(name) == full and not os.path.exists(name + ".checkpoint"),
      "run -o --restart starts the killed run over: as the uninterrupted run, its checkpoint gone")

# a checkpoint changed or damaged after it was written is refused (exit 2), naming what differs,
# and neither it nor the output is touched: an edited scenario (friction 0.5 -> 0.9), a changed
# recorded row, a flipped bit in the world's records, a flipped bit in the file's own structures
name = "tampered.h5"
check(killed_at(name, 15.0), "killed after its checkpoint at t = 15 s (to tamper with)")
pristine = open(name + ".checkpoint", "rb").read()


def meta_scenario(f):
    f["meta"].attrs["scenario"] = f["meta"].attrs["scenario"].replace("ice_ice = 0.5", "ice_ice = 0.9")


def surge_row(f):
    f["load/surge"][100] = f["load/surge"][100] + 28.0


def world_bit(f):
    return f["checkpoint/world/friction_memory"].id.get_offset()


tampers = [("an edited scenario", meta_scenario, None, "/meta"),
           ("a changed recorded row", surge_row, None, "/load"),
           ("a flipped bit in the friction memory", None, world_bit, "/checkpoint/world"),
           ("a flipped bit in the root group's header", None, lambda f: 100, "")]
for what, edit, flip_at, part in tampers:
    with open(name + ".checkpoint", "wb") as f:
        f.write(pristine)
    if edit:
        with h5py.File(name + ".checkpoint", "r+") as f:
            edit(f)
    else:
        with h5py.File(name + ".checkpoint", "r") as f:
            at = flip_at(f)
        data = bytearray(pristine)
        data[at + 8] ^= 0x10
        with open(name + ".checkpoint", "wb") as f:
            f.write(data)
    tampered = open(name + ".checkpoint", "rb").read()
    before = open(name, "rb").read()
    p = run("resume", name, "-q", expect=2)
    check(p.returncode == 2 and (part + " ") in p.stderr + " " and "cannot be resumed" in p.stderr
          and open(name, "rb").read() == before and open(name + ".checkpoint", "rb").read() == tampered,
          f"{what}: resume refuses it (exit {p.returncode}), names {part or 'the damage'}, touches no file: "
          f"{p.stderr.strip()[:160]}")
    p = run("info", name, expect=2)
    check(p.returncode == 2 and "not resumable" in p.stdout, f"{what}: icedem info says it is not resumable (exit 2)")
with open(name + ".checkpoint", "wb") as f:
    f.write(pristine)
p = run("resume", name, "-q")
check(p.returncode == 0 and contents(name) == full, "the checkpoint as written: resumed, as the uninterrupted run")

# a run without checkpoints cannot be resumed, and says why
name = "no_checkpoints.h5"
proc = subprocess.Popen([icedem, "run", scenario, "-q", "-o", name, "--set", "output.checkpoint_interval=0"],
                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
time.sleep(0.5)
proc.send_signal(signal.SIGKILL)
proc.wait()
p = run("resume", name, expect=2)
check(p.returncode == 2 and "no checkpoint" in p.stderr, "no checkpoint: resume refuses (exit 2) and says why")
check("not resumable" in run("info", name).stdout, "icedem info: not resumable")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
