#!/usr/bin/python3
"""The paper's small-floe run (scripts/run.sh's scenario, the default) killed by SIGKILL after
its checkpoints at 60, 150 and 240 s, resumed, compared dataset by dataset with the
uninterrupted run (the four runs at once: about 9 minutes on two cores).

Usage: test_resume_paper.py ICEDEM SOURCE_DIR WORK_DIR
"""
import os
import signal
import subprocess
import sys
import time

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_files import checkpoint_time, contents  # noqa: E402

os.environ["HDF5_USE_FILE_LOCKING"] = "FALSE"
icedem, src, work = sys.argv[1:4]
scen = os.path.join(src, "scenarios/paper/small_floes.toml")
os.makedirs(work, exist_ok=True)
os.chdir(work)

for p in os.listdir("."):
    if p.endswith((".h5", ".checkpoint", ".tmp")):
        os.remove(p)
full = subprocess.Popen([icedem, "run", scen, "-q", "-o", "full.h5"], stdout=subprocess.DEVNULL)
t0 = time.time()
procs = {T: subprocess.Popen([icedem, "run", scen, "-q", "-o", f"k{T}.h5"], stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL) for T in (60, 150, 240)}
pending = dict(procs)
resumes = {}
while pending:
    for T, p in list(pending.items()):
        if checkpoint_time(f"k{T}.h5.checkpoint") >= T - 1e-9:
            p.send_signal(signal.SIGKILL); p.wait()
            print(f"killed k{T} after its checkpoint at t = {checkpoint_time(f'k{T}.h5.checkpoint'):.2f} s ({time.time() - t0:.0f} s wall)", flush=True)
            del pending[T]
            resumes[T] = subprocess.Popen([icedem, "resume", f"k{T}.h5", "-q"], stdout=subprocess.DEVNULL,
                                          stderr=subprocess.PIPE, text=True)
        elif p.poll() is not None:
            print(f"k{T} ended before its kill (exit {p.returncode})"); del pending[T]
    time.sleep(0.2)
full.wait()
for T, r in resumes.items():
    _, err = r.communicate()
    print(f"resumed k{T}: exit {r.returncode}", err.strip()[:200], flush=True)
ref = contents("full.h5")
ok = full.returncode == 0 and set(resumes) == {60, 150, 240}
for T in (60, 150, 240):
    same = contents(f"k{T}.h5") == ref
    print(f"killed after t = {T} s and resumed: every dataset and /stats bit for bit as the uninterrupted run: {same}")
    ok = ok and same and resumes[T].returncode == 0
with h5py.File("full.h5") as f:
    print("uninterrupted: mean", f["stats"].attrs.get("mean_fx_N"), "max", f["stats"].attrs.get("max_fx_N"))
sys.exit(0 if ok else 1)
