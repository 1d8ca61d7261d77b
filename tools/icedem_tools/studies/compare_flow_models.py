"""Compare the hydrodynamic models on one scenario: still water, the analytic
potential flow (strip-wise cylinder), and the OpenFOAM potential flow (field
mode, and with --probe the probe-mode exchange).

    scripts/compare_flow_models.py [--scenario FILE] [--duration S] [--seed N]
                                   [--probe] [--out DIR] [--icedem PATH]

For each model it runs the scenario (`icedem run`, timed) and samples the
model's water velocity around the structure (`icedem flow`). The OpenFOAM case
is first solved into a fresh cache to time the set-up. It writes to OUT
(default docs/coupling/):
  flow_models.md         load statistics, costs, velocities at sample points
  flow_velocity.png      relative speed along the bow and shoulder lines
  flow_loads.png         the surge load histories
  flow_paths.png         floe paths past the structure (top view, structure frame)
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from ..runs.spec import ROOT
from ..runs import output_guard, runner
from ..runs.results import load_run


def run(cmd, env=None):
    """Runs a command; returns its wall time and the CPU time of it and its
    children (OpenFOAM, the partner), s. Costs are compared by CPU time: the wall
    time of one run drifts by 2x on a shared machine."""
    t0 = time.monotonic()
    before = os.times()
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    after = os.times()
    if p.returncode != 0:
        sys.exit(f"compare_flow_models: {' '.join(cmd)} failed ({p.returncode}):\n{p.stderr[-2000:]}")
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return time.monotonic() - t0, cpu


def read_flow(path):
    rows = list(csv.DictReader(open(path)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenario", default=os.path.join(ROOT, "scenarios", "paper", "small_floes.toml"))
    ap.add_argument("--duration", type=float, help="override time.duration")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--probe", action="store_true", help="also run probe mode (one OpenFOAM call per exchange)")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "coupling"))
    ap.add_argument("--icedem", default=os.path.join(ROOT, "build", "dem", "icedem"))
    a = ap.parse_args(argv)
    output_guard.guard([("--out", a.out, output_guard.DIRECTORY)], [a.scenario])
    os.makedirs(a.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="icedem-flow-models-")
    cache = os.path.join(work, "foam_cache")
    env = dict(os.environ, ICEDEM_FOAM_CACHE=cache)
    common = [f"seed={a.seed}", "output.snapshot_interval=0.5"] + ([f"time.duration={a.duration}"] if a.duration else [])

    # the one-time OpenFOAM set-up, timed from an empty cache
    setup = run([a.icedem, "foam-solve", a.scenario], env)

    models = {"still water": ["flow.model=still"], "analytic potential": ["flow.model=potential"],
              "OpenFOAM, field mode": ["flow.model=coupled"]}
    if a.probe:
        models["OpenFOAM, probe mode"] = ["flow.model=coupled", "coupling.mode=probe"]
    results = {}
    for name, sets in models.items():
        tag = name.split(",")[-1].strip().replace(" ", "_")
        r = runner.execute(a.scenario, os.path.join(work, tag), common + sets, icedem=a.icedem, env=env)
        if not r.ok:
            sys.exit(f"compare_flow_models: {' '.join(r.command)} failed ({r.returncode}): {r.error}")
        wall, cpu = r.wall_time_s, r.cpu_time_s
        fl = os.path.join(work, tag, "flow.csv")
        run([a.icedem, "flow", a.scenario, "-o", fl] + runner.sets_args(sets), env)
        results[name] = {"summary": r.summary, "h5": r.h5, "flow": read_flow(fl), "wall": wall, "cpu": cpu}
        print(f"{name}: {wall:.1f} s wall, {cpu:.1f} s CPU", file=sys.stderr)

    V = load_run(results["analytic potential"]["h5"]).scenario["structure"]["speed"]  # m/s
    write_report(a, results, setup, V)
    plots(a, results, V)
    print(f"wrote {a.out}/flow_models.md and the plots", file=sys.stderr)


def rel_speed(flow, V, depth, angle, r):
    """|water velocity - structure velocity| / V at the sample nearest to r."""
    sel = (np.abs(flow["depth"] - depth) < 1e-6) & (flow["angle_deg"] == angle)
    i = np.argmin(np.abs(flow["r"][sel] - r))
    u = np.array([flow["ux"][sel][i] - V, flow["uy"][sel][i], flow["uz"][sel][i]])
    return np.linalg.norm(u) / V


def write_report(a, results, setup, V):
    pot = results["analytic potential"]["summary"]
    lines = ["# Hydrodynamic models compared", "",
             f"Command: `scripts/compare_flow_models.py{' --probe' if a.probe else ''}"
             f"{f' --duration {a.duration:g}' if a.duration else ''} --seed {a.seed}` on "
             f"`{os.path.relpath(a.scenario, ROOT)}`, at the scenario's own numerics. One core per run.", "",
             "One seed is one sample of a chaotic pack: the loads below differ between the models by less "
             "than they differ between seeds. Whether a flow model moves the mean or the maximum beyond that "
             "scatter is measured over 10 seeds per model (`sweeps/flow_models.toml`) in the paper report's "
             "section \"Flow models over seeds\" ([report](../paper_reproduction/report.md)). This page "
             "gives what one run cannot be told from the ensemble: the costs and the flow itself.", "",
             f"OpenFOAM set-up (coarse mesh: blockMesh, snappyHexMesh, potentialFoam, grad, probes on the grid) "
             f"from an empty cache: {setup[0]:.1f} s wall, {setup[1]:.1f} s CPU.", "",
             "Costs are CPU times (of icedem and, in probe mode, the partner and OpenFOAM); wall times "
             "drift on a shared machine.", "",
             "| model | mean surge N | max N | std N | peak spacing s | CPU s | x real time (CPU) | CPU / analytic | mean vs analytic | max vs analytic |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    cpu0 = results["analytic potential"]["cpu"]
    for name, r in results.items():
        s = r["summary"]
        fmt = lambda v: "n/a" if v is None else f"{v:.2f}"
        dm = (s["mean_fx_N"] - pot["mean_fx_N"]) / pot["mean_fx_N"] if s["mean_fx_N"] is not None else float("nan")
        dx = (s["max_fx_N"] - pot["max_fx_N"]) / pot["max_fx_N"] if s["max_fx_N"] is not None else float("nan")
        lines.append(f"| {name} | {fmt(s['mean_fx_N'])} | {fmt(s['max_fx_N'])} | {fmt(s['std_fx_N'])} | "
                     f"{fmt(s['peak_interval_s'])} | {r['cpu']:.1f} | {s['sim_time_s'] / r['cpu']:.1f} | "
                     f"{r['cpu'] / cpu0:.2f} | {100 * dm:+.1f} % | {100 * dx:+.1f} % |")
    water = {n: 1e6 * r["summary"]["stage_time_s"]["water"] / max(r["summary"]["steps"], 1) for n, r in results.items()}
    lines += ["", "Water stage (buoyancy, drag, damping with the flow model) per step: "
              + ", ".join(f"{n} {w:.0f} us" for n, w in water.items()) + "."]
    probe = results.get("OpenFOAM, probe mode")
    if probe:
        st = probe["summary"]["stage_time_s"]
        n = probe["summary"]["steps"] // 50 + 1
        lines += ["", f"Probe mode: {st.get('coupling', 0):.1f} s in the exchanges, about "
                      f"{st.get('coupling', 0) / max(n, 1):.2f} s per exchange (every 50 steps)."]
    lines += ["", "Relative water speed past the structure, |u - V| / V (1 far away), tank frame samples "
                  "(`icedem flow`):", "",
              "| point | analytic potential | OpenFOAM | OpenFOAM / analytic disturbance |", "|---|---|---|---|"]
    for label, depth, angle, r in [("shoulder, waterline, r 0.7 m", 0.001, 90, 0.7), ("shoulder, waterline, r 1.0 m", 0.001, 90, 1.0),
                                   ("shoulder, waterline, r 1.5 m", 0.001, 90, 1.5), ("45 deg, waterline, r 0.8 m", 0.001, 45, 0.8),
                                   ("bow, waterline, r 0.7 m", 0.001, 0, 0.7), ("bow, waterline, r 1.0 m", 0.001, 0, 1.0),
                                   ("shoulder, half keel depth, r 0.5 m", 0.2215, 90, 0.5)]:
        p = rel_speed(results["analytic potential"]["flow"], V, depth, angle, r)
        c = rel_speed(results["OpenFOAM, field mode"]["flow"], V, depth, angle, r)
        lines.append(f"| {label} | {p:.3f} | {c:.3f} | {(c - 1) / (p - 1):.2f} |")
    with open(os.path.join(a.out, "flow_models.md"), "w") as f:
        f.write("\n".join(lines) + "\n\n![velocity](flow_velocity.png)\n![loads](flow_loads.png)\n![paths](flow_paths.png)\n")
    print("\n".join(lines))


def plots(a, results, V):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for ax, depth, title in [(axes[0], 0.001, "waterline"), (axes[1], 0.2215, "half keel depth")]:
        for name, style in [("analytic potential", "-"), ("OpenFOAM, field mode", "--")]:
            fl = results[name]["flow"]
            for angle, color in [(0, "tab:red"), (90, "tab:blue"), (180, "tab:green")]:
                sel = (np.abs(fl["depth"] - depth) < 1e-6) & (fl["angle_deg"] == angle)
                rel = np.hypot(np.hypot(fl["ux"][sel] - V, fl["uy"][sel]), fl["uz"][sel]) / V
                ax.plot(fl["r"][sel], rel, style, color=color, label=f"{name}, {angle} deg")
        ax.axhline(1, color="grey", lw=0.5)
        ax.set_xlabel("distance from the axis r (m)")
        ax.set_ylabel("|u - V| / V")
        ax.set_title(f"relative water speed, {title}", fontsize=9)
        ax.legend(fontsize=6)
    fig.suptitle("0 deg: bow (ahead), 90: shoulder, 180: stern (the bow and stern lines coincide)", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "flow_velocity.png"), dpi=120)

    fig, ax = plt.subplots(figsize=(11, 4))
    for name, r in results.items():
        f = load_run(r["h5"])
        ax.plot(f["/load/time"], f["/load/surge"], lw=0.6, label=name)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("surge load (N)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "flow_loads.png"), dpi=120)

    fig, axes = plt.subplots(1, len(results), figsize=(4 * len(results), 4), sharey=True)
    for ax, (name, r) in zip(np.atleast_1d(axes), results.items()):
        f = load_run(r["h5"], snapshots=True)
        t, P = f["/snapshots/time"], f["/snapshots/position"]
        lt, S = f["/load/time"], f["/structure/position"]
        sx = np.interp(t, lt, S[:, 0])
        rel = P[:, :, 0] - sx[:, None]
        near = np.where((np.abs(rel) < 1.2).any(axis=0) & (np.abs(P[:, :, 2]) < 1.2).any(axis=0))[0]
        for b in near[:: max(1, len(near) // 80)]:
            m = np.abs(rel[:, b]) < 2.5
            ax.plot(rel[m, b], P[m, b, 2], lw=0.5)
        ax.add_patch(plt.Circle((0, 0), 0.614, fill=False, color="k"))
        ax.set_xlim(-2.5, 2.5)
        ax.set_ylim(-2.4, 2.4)
        ax.set_aspect("equal")
        ax.set_title(name, fontsize=8)
        ax.set_xlabel("x - x_structure (m)")
    np.atleast_1d(axes)[0].set_ylabel("z (m)")
    fig.suptitle("floe paths past the structure (top view, structure frame)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "flow_paths.png"), dpi=120)


if __name__ == "__main__":
    main()
