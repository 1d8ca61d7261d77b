#!/usr/bin/python3
"""The scripts' one output guard (tools/icedem_tools/runs/output_guard.py), as the program's
(tests/unit/test_output_guard.cpp): a table of outputs it must refuse and allow, its writes whole or
not at all, and scripts/layout_from_photo end to end (its overlay defaults to OUTPUT with .png, which
may be the photo itself).

Usage: test_script_outputs.py SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

src, work = sys.argv[1:3]
sys.path.insert(0, os.path.join(src, "tools"))
from icedem_tools.runs import output_guard as og  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
os.chdir(work)
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


def refusal(outputs, inputs=()):
    """The guard's refusal of `outputs`, "" if it lets them through."""
    try:
        og.guard(outputs, inputs)
    except og.Refused as e:
        return str(e)
    return ""


open("scenario.toml", "w").write("seed = 1\n")
open("notes.csv", "w").write("x\n")
os.symlink("scenario.toml", "alias.toml")
os.makedirs("figures")
with h5py.File("run.h5", "w") as f:
    f.create_group("meta")
with h5py.File("old_views.h5", "w") as f:
    f["joint_topology"] = np.zeros((1, 4), dtype=np.int64)
open("a_file", "w").write("")

F, D, V = og.FILE, og.DIRECTORY, og.VIEWS
table = [
    # (outputs, inputs, a word the refusal must hold, or None: let through)
    ([("-o", "", F)], [], "give a name"),
    ([("-o", "scenario.toml", F)], ["scenario.toml"], "input of this command"),
    ([("-o", "alias.toml", F)], ["scenario.toml"], "input of this command"),          # one file, two names
    ([("-o", "./x/../scenario.toml", F)], ["scenario.toml"], "input of this command"),
    ([("-o", "out.csv", F), ("--overlay", "out.csv", F)], [], "writes the same file"),
    ([("-o", "figures", F)], [], "a directory, where a file goes"),
    ([("--out", "a_file", D)], [], "a file, where a directory goes"),
    ([("-o", "run.h5", F)], [], "HDF5"),
    ([("views", "run.h5", V)], [], "HDF5"),                                           # a run's output
    ([("-o", "/dev/null", F)], [], "not a regular file"),
    ([("views", "old_views.h5", V)], [], None),                                       # an earlier view
    ([("-o", "notes.csv", F)], ["scenario.toml"], None),                              # an earlier text output
    ([("-o", "new/deeper/out.csv", F)], [], None),                                    # made on the way
    ([("--out", "figures", D), ("--out", "new_dir", D)], [], None),
    ([("--out", "figures", D), ("the runs' directory", "figures", D)], [], None),   # one directory, two uses
    ([("--out", "figures", D), ("--report", "figures", F)], [], "the same file"),
    ([("--report", None, F)], [], None),                                              # not asked for
]
for outputs, inputs, word in table:
    why = refusal(outputs, inputs)
    if word is None:
        check(why == "", f"{outputs} let through ({why or 'no refusal'})")
    else:
        check(word in why, f"{outputs} refused: {why}")

# a write is whole or not at all: a failed one leaves the earlier file as it was
og.write_text("notes.csv", "y\n")
check(open("notes.csv").read() == "y\n", "write_text replaces the file whole")
os.chmod("notes.csv", 0o640)
og.write_text("notes.csv", "z\n")
og.write_text("fresh.csv", "z\n")
umask = os.umask(0)
os.umask(umask)
check(os.stat("notes.csv").st_mode & 0o777 == 0o640 and os.stat("fresh.csv").st_mode & 0o777 == 0o666 & ~umask,
      "a replaced file keeps its mode, a new one has the umask's (not mkstemp's private 0600)")
try:
    og.write_text("a_file/inside.csv", "z\n")  # its directory is a file: the write fails
    check(False, "a write that cannot be made raises WriteFailed")
except og.WriteFailed as e:
    check("a_file" in str(e), f"a write that cannot be made raises WriteFailed: {e}")
check(not [n for n in os.listdir(".") if n.endswith(".tmp")], "no temporary file left behind")

# scripts/layout_from_photo end to end: every refusal exit 2, before any work, the photo untouched
photo = os.path.join(work, "photo.png")
shutil.copy(os.path.join(src, "docs", "photo_layout", "squares_30cm_60pc_overlay.jpg"), "photo.jpg")
from skimage import io  # noqa: E402 (Debian's python3-skimage)
io.imsave(photo, io.imread("photo.jpg"), check_contrast=False)
before = open(photo, "rb").read()
tool = os.path.join(src, "scripts", "layout_from_photo")
for args, what in [(["-o", "photo.csv"], "the overlay defaults to OUTPUT with .png: the photo"),
                   (["-o", "layout.csv", "--overlay", "photo.png"], "--overlay names the photo"),
                   (["-o", "run.h5"], "-o names a run's HDF5 output"),
                   (["-o", "figures"], "-o names a directory")]:
    p = subprocess.run([tool, "photo.png", *args, "--metres-per-pixel", "0.004"], capture_output=True, text=True)
    check(p.returncode == 2 and "error:" in p.stderr and open(photo, "rb").read() == before,
          f"layout_from_photo: {what}: exit {p.returncode}, the photo untouched: {p.stderr.strip()[:120]}")

# and a photo of floes goes through: the layout and its overlay written whole
p = subprocess.run([os.path.join(src, "scripts", "photo_layout_validation.py"), "--example", "floes.jpg"],
                   capture_output=True, text=True)
p = subprocess.run([tool, "floes.jpg", "-o", "floes.csv", "--metres-per-pixel", "0.004"], capture_output=True, text=True)
rows = [line for line in open("floes.csv") if line[:1].isdigit() or line[:1] == "-"] if p.returncode == 0 else []
check(p.returncode == 0 and len(rows) > 40 and os.path.getsize("floes.png") > 0,
      f"layout_from_photo on a photo of 50 floes: exit {p.returncode}, {len(rows)} floes, its overlay floes.png")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
