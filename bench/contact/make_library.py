#!/usr/bin/python3
"""Regenerate the contact-problem library: real contact problems of real runs,
one FCLIB file per island (docs/model/contact_problems.md).

    bench/contact/make_library.py OUTDIR [--icedem build/dem/icedem] [--only SET ...]

Each set runs one scenario with `icedem run --export-problems` and writes its
files to OUTDIR/SET/. The lattice sets run their scenario twice: once to find the
joint breaks, once more (the runs are deterministic) to write the islands of the
steps that broke joints, the solves whose loads broke them. A set whose directory
already holds files is skipped, so the script resumes where it stopped.

Sets (about 1.5 hours of CPU in all):
  small_jam    the paper's small floes: islands the PGS sweeps stopped at their cap
  wide_jam     the same on a 48 m wide field (9,600 floes), the longest chains
  large_rigid  the paper's 0.6 m rigid floes: capped islands as the pack builds up
               (these three run with the sweeps, solver.method = "pgs")
  locked       the stress suite's jammed field: a pack locked between cone and end wall
  lattice_020  0.6 m floes of 0.20 m elements: steps that broke a joint
  lattice_015  0.6 m floes of 0.15 m elements: steps that broke a joint, among them
               floes pressed under the cone
  hexagon_015  0.6 m floes of 0.15 m hexagons: steps that broke a joint
  level_ice    level ice of 0.15 m elements, its first 40 s: the free sheet with the rubble
               at the cone (hundreds of elements, thousands of joint rows)
The crushing sets: the same scenes with crushing contacts (contact.model = "crushing",
docs/model/crushing.md) and the water's added mass, each contact's normal bounded by its
cap (/icedem/contact_normal_cap); their islands at fixed times, the pack built up (about
40 minutes of CPU in all):
  crushing_small        the paper's small floes, from 60 s on
  crushing_large        the paper's 0.6 m rigid floes, from 100 s on
  crushing_lattice_020  0.6 m floes of 0.20 m elements: steps that broke a joint
  crushing_level_ice    level ice of 0.15 m elements, its first 40 s
"""
import argparse
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def scenario(path):
    return os.path.join(ROOT, "scenarios", path)


# The jams the library is about are those the projected Gauss-Seidel sweeps (the default
# before the accelerated projected gradient) stopped at their cap: the capped sets run
# with the sweeps' settings, whatever the default is now.
SWEEPS = ["--set", "solver.method=pgs", "--set", "solver.position_iterations=160"]

# The crushing contact with the water's added mass: the model issue 67's loads are measured with
CRUSHING = ["--set", "contact.model=crushing", "--set", "water.added_mass=true"]

# name: (scenario, extra icedem arguments, export arguments); the lattice sets'
# export times come from a first run
SETS = {
    "small_jam": ("paper/small_floes.toml", SWEEPS,
                  ["--export-capped", "16", "--export-spacing", "15", "--export-min-contacts", "50"]),
    "wide_jam": ("paper/small_floes.toml",
                 SWEEPS + ["--set", "channel.width=48", "--set", "tank.width=49.2", "--set", "time.duration=150"],
                 ["--export-capped", "6", "--export-spacing", "15", "--export-min-contacts", "300"]),
    "large_rigid": ("paper/large_floes_rigid.toml", SWEEPS,
                    ["--export-capped", "6", "--export-spacing", "30", "--export-min-contacts", "50"]),
    "locked": ("stress/jammed.toml", [],
               ["--export-at", "40,46,50,54,58", "--export-min-contacts", "50"]),
    "lattice_020": ("paper/large_floes_breakable_020.toml", [], None),
    "lattice_015": ("paper/large_floes_breakable_015.toml", [], None),
    "hexagon_015": ("paper/large_floes_hexagon_015.toml", [], None),
    "level_ice": ("level_ice/level_ice_015.toml", ["--set", "time.duration=40"],
                  ["--export-at", "14,22,30,38", "--export-min-contacts", "100"]),
    "crushing_small": ("paper/small_floes.toml", CRUSHING,
                       ["--export-at", "60,90,120,150,180,210,240,270", "--export-min-contacts", "50"]),
    "crushing_large": ("paper/large_floes_rigid.toml", CRUSHING,
                       ["--export-at", "100,130,160,190,220,250,275", "--export-min-contacts", "30"]),
    "crushing_lattice_020": ("paper/large_floes_breakable_020.toml", CRUSHING, None),
    "crushing_level_ice": ("level_ice/level_ice_015.toml", CRUSHING + ["--set", "time.duration=40"],
                           ["--export-at", "14,22,30,38", "--export-min-contacts", "100"]),
}
BREAK_STEPS = 6  # steps with breaks written per lattice set, spread over the run


def run(icedem, scen, extra, out_h5, export_dir=None, export_args=(), name=""):
    cmd = [icedem, "run", scenario(scen), "-o", out_h5, *extra]
    if export_dir:
        cmd += ["--export-problems", export_dir, "--export-name", name, *export_args]
    print("  " + " ".join(cmd), flush=True)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def break_times(h5_path):
    """The times of the steps that broke joints, pressed-under breaks first, then spread over the run."""
    with h5py.File(h5_path, "r") as f:
        events = f["/fracture/events"][()]
        names = dict(item.split(" ", 1) for item in
                     f["/fracture/events"].attrs["mechanism_names"].split(", ")) if len(events) else {}
    if not len(events):
        return []
    pressed = [int(code) for code, n in names.items() if n.strip() == "pressed under"]
    times = np.unique(np.round(events["time"], 6))
    pressed_times = np.unique(np.round(events["time"][np.isin(events["mechanism"], pressed)], 6))
    chosen = list(pressed_times[:BREAK_STEPS // 2])
    rest = [t for t in times if t not in chosen]
    if rest:
        picks = np.linspace(0, len(rest) - 1, min(BREAK_STEPS - len(chosen), len(rest))).round().astype(int)
        chosen += [rest[i] for i in sorted(set(picks))]
    return sorted(chosen)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("outdir")
    parser.add_argument("--icedem", default=os.path.join(ROOT, "build", "dem", "icedem"))
    parser.add_argument("--only", nargs="*", choices=list(SETS), help="sets to make (default: all)")
    args = parser.parse_args()
    for name in args.only or SETS:
        scen, extra, export = SETS[name]
        target = os.path.join(args.outdir, name)
        if os.path.isdir(target) and os.listdir(target):
            print(f"{name}: already made, skipped")
            continue
        print(f"{name}:", flush=True)
        with tempfile.TemporaryDirectory() as tmp:
            if export is None:
                first = os.path.join(tmp, "first.h5")
                run(args.icedem, scen, extra, first)
                times = break_times(first)
                if not times:
                    print(f"  no joint broke: nothing to write for {name}")
                    continue
                export = ["--export-at", ",".join(f"{t:.6f}" for t in times), "--export-min-contacts", "20"]
            run(args.icedem, scen, extra, os.path.join(tmp, "run.h5"), target, export, name)
        print(f"  {len(os.listdir(target))} problems in {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
