#!/usr/bin/python3
"""scripts/movie end to end on the short tow: one frame per snapshot (or every Nth), frames that
change as the structure moves, the joints' path with breakable floes, a moored cone's lines, the analytic level
sheet; a run without snapshots and
a movie over the run's own file are refused (exit 2) and leave nothing.

Usage: test_movie.py SOURCE_DIR WORK_DIR ICEDEM
"""
import os
import shutil
import subprocess
import sys

import numpy as np
from PIL import Image

src, work, icedem = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
movie = os.path.join(src, "scripts", "movie")
tow = os.path.join(src, "scenarios", "examples", "short_tow.toml")
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def run(name, *sets):
    out = os.path.join(work, name + ".h5")
    args = [icedem, "run", tow, "-q", "-o", out]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, capture_output=True)
    return out


def frames(path):
    im = Image.open(path)
    out = []
    for k in range(im.n_frames):
        im.seek(k)
        out.append(np.asarray(im.convert("RGB"), dtype=float))
    return out


# the short tow: 40 s, a snapshot every 2 s (21 with the one at t = 0)
rigid = run("rigid", "output.snapshot_interval=2")
p = subprocess.run([movie, rigid], capture_output=True, text=True)
gif = os.path.join(work, "rigid.gif")
shots = frames(gif) if p.returncode == 0 and os.path.exists(gif) else []
check(len(shots) == 21, f"one frame per snapshot: {len(shots)} of 21 (exit {p.returncode}) {p.stderr[-300:]}")
# the structure moves 2.8 m and the floes with it: the first and last frames differ in many pixels
if shots:
    changed = float(np.mean(np.abs(shots[0] - shots[-1]).sum(axis=2) > 30))
    check(changed > 0.02, f"the frames change over the run: {100 * changed:.1f} % of the pixels")
p = subprocess.run([movie, rigid, "--every", "5", "-o", os.path.join(work, "every5.gif")], capture_output=True, text=True)
check(p.returncode == 0 and len(frames(os.path.join(work, "every5.gif"))) == 5, "--every 5: frames 0, 5, 10, 15, 20")

# breakable floes (2 x 2 elements of 0.15 m) of weak ice (3 kPa in bending: about a hundred breaks):
# no crack is drawn at t = 0, and the broken joints are, in red, at the end
lattice = run("lattice", "output.snapshot_interval=10", "fracture.mode=on", "fracture.element_size=0.15",
              "ice.bending_strength=3000")
p = subprocess.run([movie, lattice], capture_output=True, text=True)
shots = frames(os.path.join(work, "lattice.gif")) if p.returncode == 0 else []


def red(image):  # pixels of the cracks' colour in the views (left of the load panel, whose cursor is red too)
    views = image[:, : int(0.6 * image.shape[1])]
    return int(((views[..., 0] > 200) & (views[..., 1] < 60) & (views[..., 2] < 60)).sum())


check(len(shots) == 5 and red(shots[0]) == 0 and red(shots[-1]) > 50,
      f"a run of breakable floes: its cracks drawn once broken (red pixels first {red(shots[0]) if shots else '-'}, "
      f"last {red(shots[-1]) if shots else '-'}; exit {p.returncode}) {p.stderr[-300:]}")

# the cone moored by four catenary lines: its lines drawn in orange (matplotlib's C1), anchors to fairleads,
# in the top and side views of every frame; a towed run's frames have none of that colour
moored = os.path.join(work, "moored.h5")
subprocess.run([icedem, "run", os.path.join(src, "scenarios", "moored", "small_floes_moored.toml"), "-q", "-o", moored,
                "--set", "time.duration=2", "--set", 'mooring.model="catenary"', "--set", "output.snapshot_interval=1"],
               check=True, capture_output=True)
p = subprocess.run([movie, moored, "--span", "5"], capture_output=True, text=True)
shots = frames(os.path.join(work, "moored.gif")) if p.returncode == 0 else []


def orange(image):  # C1, (255, 127, 14), in the views
    views = image[:, : int(0.6 * image.shape[1])]
    return int(((views[..., 0] > 200) & (np.abs(views[..., 1] - 127) < 40) & (views[..., 2] < 70)).sum())


check(len(shots) == 3 and min(orange(x) for x in shots) > 100 and orange(frames(gif)[0]) == 0,
      f"a moored run's lines are drawn (orange pixels {[orange(x) for x in shots]}, towed "
      f"{orange(frames(gif)[0]) if os.path.exists(gif) else '-'}; exit {p.returncode}) {p.stderr[-300:]}")

# level ice cut by closed forms: the held sheet drawn in pale grey (0.85) in every frame as it stood then (its first
# 8 s, a snapshot every 2 s, breaks from 2.7 s on: about 30,000 such pixels); a run of floes has a few hundred (edges)
sheet = os.path.join(work, "sheet.h5")
subprocess.run([icedem, "run", os.path.join(src, "scenarios", "level_ice", "level_ice_analytic.toml"), "-q", "-o", sheet,
                "--set", "time.duration=8", "--set", "output.snapshot_interval=2"], check=True, capture_output=True)
p = subprocess.run([movie, sheet], capture_output=True, text=True)
shots = frames(os.path.join(work, "sheet.gif")) if p.returncode == 0 else []


def pale(image):  # the sheet's grey, (217, 217, 217), in the views
    views = image[:, : int(0.6 * image.shape[1])]
    return int((np.abs(views - 217).max(axis=2) < 4).sum())


check(len(shots) == 5 and min(pale(x) for x in shots) > 10000 and pale(frames(gif)[0]) < 2000,
      f"the analytic sheet is drawn (pale pixels {[pale(x) for x in shots]}, floes' run "
      f"{pale(frames(gif)[0]) if os.path.exists(gif) else '-'}; exit {p.returncode}) {p.stderr[-300:]}")

# refusals: nothing written
bare = run("bare", "output.snapshot_interval=0")
p = subprocess.run([movie, bare], capture_output=True, text=True)
check(p.returncode == 2 and "snapshot" in p.stderr and not os.path.exists(os.path.join(work, "bare.gif")),
      f"a run without snapshots is refused: exit {p.returncode}, {p.stderr.strip()[:200]}")
before = os.path.getsize(rigid)
p = subprocess.run([movie, rigid, "-o", rigid], capture_output=True, text=True)
check(p.returncode == 2 and os.path.getsize(rigid) == before, f"a movie over the run itself is refused: exit {p.returncode}")

p = subprocess.run([movie, os.path.join(work, "missing.h5")], capture_output=True, text=True)
check(p.returncode == 2 and "no such file" in p.stderr, f"a missing run is named: exit {p.returncode}")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
