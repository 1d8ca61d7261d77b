#!/usr/bin/python3
"""A tank photo's floes break, end to end: scripts/layout_from_photo turns the example photo
(scenarios/examples/floes_photo.jpg) into a layout of irregular floes, icedem runs it with
breakable ice (fracture.mode = "on") in square and in hexagonal elements cut at the floes'
outlines, and the HDF5 file holds each floe's elements, their outlines and the breaks.

The ice is made ten times weaker than the paper's so that a 12 s run breaks joints: what is
tested is that the chain works, not how much ice breaks (that is the physics tests' and the
sweeps').

Usage: test_photo_breakable.py SOURCE_DIR WORK_DIR ICEDEM
"""
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

src, work, icedem = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


# the photo to a layout, as the example scenario's header says
p = subprocess.run([os.path.join(src, "scripts", "layout_from_photo"),
                    os.path.join(src, "scenarios", "examples", "floes_photo.jpg"), "-o", "floes.csv",
                    "--floe-size", "0.24", "--metres-per-pixel", "0.004", "--origin", "6.0,0.75"],
                   capture_output=True, text=True)
check(p.returncode == 0, f"layout_from_photo: exit {p.returncode} {p.stderr[-300:]}")
floes = sum(1 for line in open("floes.csv") if line[:1].isdigit()) if p.returncode == 0 else 0
check(floes > 40, f"the photo's floes: {floes}")
scenario = open(os.path.join(src, "scenarios", "examples", "floes_from_photo.toml")).read()
open("photo.toml", "w").write(scenario.replace('file = "floes_from_photo.csv"', 'file = "floes.csv"'))

weak = ["ice.bending_strength=3640", "ice.shear_strength=7280", "ice.compressive_strength=14560"]
for shape in ["square", "hexagon"]:
    out = f"{shape}.h5"
    args = [icedem, "run", "photo.toml", "-q", "-o", out, "--set", 'fracture.mode="on"', "--set",
            f'fracture.element_shape="{shape}"', "--set", "fracture.element_size=0.1", "--set", "time.duration=12",
            "--set", "structure.start_x=5.3", "--set", "output.snapshot_interval=0"]
    for s in weak:
        args += ["--set", s]
    p = subprocess.run(args, capture_output=True, text=True)
    check(p.returncode == 0, f"{shape}: the run: exit {p.returncode} {p.stderr[-300:]}")
    if p.returncode != 0:
        continue
    with h5py.File(out, "r") as h:
        floe_id = h["bodies/floe_id"][()]
        ends = h["bodies/vertex_offset"][()][1:]  # nb + 1 of them: body i's are [offset[i], offset[i + 1])
        vertices = h["bodies/vertices"][()].reshape(-1, 2)
        breaks = len(h["fracture/events"])
    per_floe = np.bincount(floe_id[floe_id >= 0])
    check(len(per_floe) == floes and per_floe.min() >= 1 and per_floe.mean() > 3,
          f"{shape}: every floe is its elements: {len(floe_id)} bodies for {len(per_floe)} floes, "
          f"{per_floe.mean():.1f} a floe")
    # the elements cut at the outlines are not all the one square or hexagon
    counts, areas = [], []
    start = 0
    for body, end in enumerate(ends):
        v = vertices[start:end]
        start = end
        if floe_id[body] < 0:
            continue
        x, z = v[:, 0], v[:, 1]
        counts.append(len(v))
        areas.append(0.5 * abs(np.dot(x, np.roll(z, -1)) - np.dot(z, np.roll(x, -1))))
    areas = np.array(areas)
    cell = 0.1 ** 2 * (1.0 if shape == "square" else np.sqrt(3) / 2)
    check(areas.std() > 0.05 * areas.mean() and len(set(counts)) > 1 and areas.min() > 0,
          f"{shape}: elements of many outlines: areas {areas.min():.5f}-{areas.max():.4f} m^2 "
          f"(a cell {cell:.4f}), {sorted(set(counts))} vertices")
    check(breaks > 0, f"{shape}: joints broke and are in /fracture/events: {breaks}")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
