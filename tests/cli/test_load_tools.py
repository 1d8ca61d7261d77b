#!/usr/bin/python3
"""The tank comparison and the load budget report from the committed records alone, as on a fresh
machine: scripts/tank_maxima (docs/paper_reproduction/records) and scripts/budget
(docs/model/load_budget_records, with an empty run directory). Their counts are the records' own:
the paper grid's rigid 0.6 m floes at f_ii 0.5, f_is 0.2 and 0.3 pooled, reach the tank's 150 N in 5
of 20 runs; the budget's default in 1 of 10 and with added mass in 10 of 10.

Usage: test_load_tools.py SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

src, work = sys.argv[1:3]
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
      and "| 10/10 (69-100 %) |" in rows.get("added mass", ""),
      f"budget from its records alone: the default 1 of 10 runs at the tank's value, added mass 10 of 10 "
      f"(exit {p.returncode}) {p.stderr[-200:]}")

print(f"{len(failures)} failed")
sys.exit(1 if failures else 0)
