#!/usr/bin/python3
"""The tank comparison and the load budget report from the committed records alone, as on a fresh
machine: scripts/tank_maxima (docs/paper_reproduction/records) and scripts/budget
(docs/model/load_budget_records, with an empty run directory). Their counts are the records' own:
the paper grid's rigid 0.6 m floes at f_ii 0.5, f_is 0.2 and 0.3 pooled, reach the tank's 150 N in 5
of 20 runs; the budget's default in 1 of 10 and with added mass in 10 of 10. The filtered maxima
(scripts/tank_maxima --filter-runs) filter a run's load as icedem's own stats.lowpass_hz does: the
short tow's maximum after the 5 Hz filter is the one icedem reports with that key, to round-off, and
so is the one a sweep's record keeps (aggregate.make_record) for the budget's "max at 5 Hz".

Usage: test_load_tools.py SOURCE_DIR WORK_DIR ICEDEM
"""
import json
import os
import shutil
import subprocess
import sys

src, work, icedem = sys.argv[1:4]
sys.path.insert(0, os.path.join(src, "tools"))
from icedem_tools.studies import tank_maxima  # noqa: E402
shutil.rmtree(work, ignore_errors=True)
os.makedirs(os.path.join(work, "no_runs"))
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


page = os.path.join(work, "tank_maxima.md")
p = subprocess.run([os.path.join(src, "scripts", "tank_maxima"), "--report", page], capture_output=True, text=True)
text = open(page).read() if p.returncode == 0 else ""
rigid = text[text.find("### large_rigid"):text.find("### large_breakable_015")]
check(p.returncode == 0 and "5/20 (9-49 %) of the runs reach the tank's 150 N" in rigid
      and os.path.getsize(os.path.join(work, "tank_maxima.png")) > 0,
      f"tank_maxima from the grid's records: the rigid floes reach 150 N in 5 of 20 runs (exit {p.returncode})")
check("inferred" in text and "75 N" in text, "the small floes' 75 N is labelled an inference")

page = os.path.join(work, "load_budget.md")
p = subprocess.run([os.path.join(src, "scripts", "budget"), "--out", os.path.join(work, "no_runs"), "--report", page],
                   capture_output=True, text=True)
text = open(page).read() if p.returncode == 0 else ""
rigid = text[text.find("### large_rigid"):]
rigid = rigid[:rigid.find("\n### ", 1)] if "\n### " in rigid[1:] else rigid  # its own section only
rows = {line.split("|")[1].strip(): line for line in rigid.splitlines() if line.startswith("|")}
check(p.returncode == 0 and "| 1/10 (0-45 %) |" in rows.get("default", "")
      and "| 10/10 (69-100 %) |" in rows.get("added mass", "") and "| max at 5 Hz N |" in rigid
      and os.path.getsize(os.path.join(work, "load_budget.png")) > 0,
      f"budget from its records alone: the default 1 of 10 runs at the tank's value, added mass 10 of 10 "
      f"(exit {p.returncode}) {p.stderr[-200:]}")

# the filter: the short tow run as it is and with icedem's own 5 Hz low-pass of its statistics
run_dir = os.path.join(work, "sweep", "large_rigid", "default", "base", "seed1")
os.makedirs(run_dir)
tow = os.path.join(src, "scenarios", "examples", "short_tow.toml")
for name, extra in (("run", []), ("filtered", ["--set", "stats.lowpass_hz=5"])):
    subprocess.run([icedem, "run", tow, "-q", "-o", os.path.join(run_dir, name + ".h5"), "--summary-json",
                    os.path.join(run_dir, "summary.json" if name == "run" else "filtered.json"),
                    "--set", "output.snapshot_interval=0"] + extra, check=True)
os.remove(os.path.join(run_dir, "filtered.h5"))
with open(os.path.join(run_dir, "summary.json")) as f:
    plain = json.load(f)
with open(os.path.join(run_dir, "filtered.json")) as f:
    by_icedem = json.load(f)["max_fx_N"]
ours = tank_maxima.filtered_maxima(os.path.join(run_dir, "run.h5"), plain)
# 1e-9: the same filter, the same padding, the same window; only the order of round-off differs
check(abs(ours["5"] - by_icedem) <= 1e-9 * abs(by_icedem) and ours["0"] == plain["max_fx_N"],
      f"the 5 Hz maximum is icedem's: {ours['5']!r} N against {by_icedem!r} N (unfiltered {ours['0']} N)")
# a sweep's record keeps the same filtered maximum (what scripts/budget's "max at 5 Hz" column reads)
from icedem_tools.sweeps import aggregate  # noqa: E402
kept = aggregate.make_record(run_dir)["window"]["max_lowpass_fx_N"]
check(abs(kept["5"] - by_icedem) <= 1e-9 * abs(by_icedem),
      f"the record's 5 Hz maximum is icedem's: {kept['5']!r} N against {by_icedem!r} N")
# its 10 s blocks: the window's whole blocks from its start, each block's mean and maximum as read off the
# run's load by time (half a sample either side of a block's edge); the record rounds to 6 digits
import h5py  # noqa: E402
blocks = aggregate.make_record(run_dir)["window"]["blocks"]
with h5py.File(os.path.join(run_dir, "run.h5"), "r") as f:
    t, x = f["/load/time"][:], f["/load/surge"][:]
start, end, dt = plain["window_start_s"], plain["window_end_s"], t[1] - t[0]
whole = int((end - start + dt / 2) // 10.0)
expect = []
for k in range(whole):
    sel = (t >= start + 10.0 * k - dt / 2) & (t < start + 10.0 * (k + 1) - dt / 2)
    expect.append((x[sel].mean(), x[sel].max()))
got = list(zip(blocks["mean_fx_N"], blocks["max_fx_N"])) if blocks else []
check(whole >= 2 and len(got) == whole
      and all(abs(a - c) <= 1e-5 * abs(c) and abs(b - d) <= 1e-5 * abs(d)
              for (a, b), (c, d) in zip(got, expect))
      and max(blocks["max_lowpass_fx_N"]["5"]) <= by_icedem * (1 + 1e-5),
      f"the record's 10 s blocks are the window's whole blocks by time: {len(got)} of {whole}, "
      f"means {blocks and blocks['mean_fx_N']} against {[round(m, 3) for m, _ in expect]}")
records = os.path.join(work, "filtered.json")
page = os.path.join(work, "tank_maxima_filtered.md")
p = subprocess.run([os.path.join(src, "scripts", "tank_maxima"), "--filter-runs", os.path.join(work, "sweep"),
                    "--filtered", records, "--report", page], capture_output=True, text=True)
with open(records) as f:
    kept = json.load(f) if p.returncode == 0 else {}
check(p.returncode == 0 and kept.get("large_rigid", {}).get("default", {}).get("seed1") == ours
      and "| large_rigid, reference | 1 | 5 Hz |" in open(page).read(),
      f"--filter-runs keeps each run's filtered maxima and the report shows them (exit {p.returncode}) {p.stderr[-300:]}")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
