"""Pictures of breaks like the seed paper's Fig. 18: a side and a top view of the
ice around the structure just before a joint breaks, the broken floe in red.

    scripts/break_pictures.py SWEEP.toml [--out DIR] [--figures DIR] [--icedem PATH]

The paper shows two pictures: at f_ii = 0.3 an approaching floe presses a
submerged floe against the cone and breaks it; at f_ii = 0.7 floes break while
sliding on the slope. For every breakable scenario of the sweep this picks,
from the kept records (tools/icedem_tools/sweeps/aggregate.py), the first break (lowest seed,
then lowest f_is) of the class "pressed under" at f_ii 0.3 and of "on the slope"
at 0.7 (dem/fracture/break_context.hpp); with none of that class, the first break at that
f_ii, and the title says so. The run is repeated with snapshots every 0.2 s up
to just after the break (runs are deterministic; the title says whether the
repeat broke the same joint at the same time), in OUT/pictures/, and drawn as
figures/break_<scenario>_fii<f>.png. Prints the pictures it wrote.
"""
import argparse
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from scipy.spatial import ConvexHull  # noqa: E402

from ..sweeps import aggregate as agg, execute
from ..runs import output_guard, results, runner, spec
from .report_tables import FII, FIS
from ..runs.xdmf import quat_to_matrix

WANTED = ((0.3, "pressed under"), (0.7, "on the slope"))  # Fig. 18 (a) and (b)
SNAPSHOT_S = 0.2     # snapshot interval of the repeated run, s
AFTER_S = 0.3        # the repeat runs this long past the break, s
SIDE_BAND_M = 0.45   # the side view shows bodies within this sway of the broken joint, m
TOP_HALF_M = 2.5     # the top view shows this far around the structure axis, m


def pick(records, scenario, fii, mechanism):
    """(run, event, exact) of the first break of `mechanism` at `fii` (lowest seed, then f_is), or
    of the first break at `fii` with exact False; None without breaks there."""
    cands = sorted(((r, rec) for r, rec in records if r.scenario == scenario and dict(r.grid).get(FII) == fii),
                   key=lambda x: (x[0].seed, dict(x[0].grid).get(FIS, 0)))
    for want in (True, False):
        for r, rec in cands:
            for e in rec.get("fracture_events", []):
                if not want or e.get("mechanism_name") == mechanism:
                    return r, e, want
    return None


def repeat(run, event, out, icedem):
    """Run `run` again into OUT/pictures/... with snapshots up to just after the event; the HDF5 path."""
    d = os.path.join(out, "pictures", run.path)
    h5 = os.path.join(d, runner.RUN_FILES["h5"])
    if results.status(h5) == "complete":  # a finished repeat is reused
        return h5
    duration = SNAPSHOT_S * np.ceil((event["time"] + AFTER_S) / SNAPSHOT_S)
    sets = run.sets + (f"output.snapshot_interval={SNAPSHOT_S}", f"time.duration={duration:.2f}")
    r = runner.execute(run.scenario_file, d, sets, icedem=icedem)
    if not r.ok:
        sys.exit(f"break_pictures: the repeat of {run.path} failed: {r.error}")
    return h5


def body_points(h, k):
    """Every output body's prism corners in the tank frame at snapshot k: a list of (n, 3) arrays."""
    off, verts, thick = h["/bodies/vertex_offset"], h["/bodies/vertices"], h["/bodies/thickness"]
    pos = h["/snapshots/position"][k]
    q = h["/snapshots/orientation"][k]
    out = []
    for b in range(len(off) - 1):
        v = verts[off[b]:off[b + 1]]
        local = np.vstack([np.column_stack([v[:, 0], np.full(len(v), y), v[:, 1]])
                           for y in (-thick[b] / 2, thick[b] / 2)])
        out.append(pos[b] + local @ quat_to_matrix(q[b]).T)
    return out


def collection(polys, colours, red):
    """The bodies as polygons, the broken floe's drawn last (on top)."""
    order = sorted(range(len(polys)), key=lambda i: colours[i] == red)
    return PolyCollection([polys[i] for i in order], facecolor=[colours[i] for i in order],
                          edgecolor="0.25", lw=0.4)


def hull(points2d):
    try:
        return points2d[ConvexHull(points2d).vertices]
    except Exception:  # a degenerate projection (a body seen edge-on): its bounding segment
        return points2d


def draw(h5, run, event, exact, mechanism, path):
    h = results.load_run(h5, snapshots=True)
    st = h["/snapshots/time"]
    k = max(int(np.searchsorted(st, event["time"], side="right")) - 1, 0)  # last snapshot before it
    floe_id = h["/bodies/floe_id"]
    bodies = body_points(h, k)
    t = h["/load/time"]
    axis = h["/structure/position"][min(int(np.searchsorted(t, st[k])), len(t) - 1)]
    again = [e for e in h.events
             if e["floe"] == event["floe"] and e["joint"] == event["joint"] and abs(e["time"] - event["time"]) < 1e-6]
    profile = np.array(h.scenario["structure"]["profile"], dtype=float)  # (y, r) keel to deck
    zj = event["z"]
    broken = floe_id == event["floe"]
    fig, (side, top) = plt.subplots(2, 1, figsize=(9, 8.5), gridspec_kw={"height_ratios": [1, 1.4]})

    # side view: bodies within a band of sway around the broken joint, and the structure's cut there
    polys, colours = [], []
    for b, p in enumerate(bodies):
        if abs(p[:, 2].mean() - zj) <= SIDE_BAND_M and abs(p[:, 0].mean() - axis[0]) <= TOP_HALF_M:
            polys.append(hull(p[:, [0, 1]]))
            colours.append("tab:red" if broken[b] else "0.8")
    side.add_collection(collection(polys, colours, "tab:red"))
    half = np.sqrt(np.clip(profile[:, 1] ** 2 - (zj - axis[2]) ** 2, 0, None))
    cut = np.concatenate([np.column_stack([axis[0] + half, profile[:, 0]]),
                          np.column_stack([axis[0] - half, profile[:, 0]])[::-1]])
    side.fill(cut[:, 0], cut[:, 1], color="tab:blue", alpha=0.35, lw=0)
    side.axhline(0, color="tab:blue", lw=0.6)
    side.plot([event["x"]], [-event["depth"]], "kx", ms=8, label="breaking joint")
    side.set_aspect("equal")
    side.set_xlim(axis[0] - 0.5, axis[0] + TOP_HALF_M)
    side.set_ylim(profile[0, 0] - 0.05, max(profile[-1, 0], 0.15))
    side.set_xlabel("x, m (towing direction)")
    side.set_ylabel("y, m")
    side.set_title(f"side view, bodies within {SIDE_BAND_M} m of z = {zj:.2f} m", fontsize=9)
    side.legend(fontsize=7, loc="lower right")

    # top view: every body near the structure
    polys, colours = [], []
    for b, p in enumerate(bodies):
        if np.abs(p[:, [0, 2]].mean(axis=0) - axis[[0, 2]]).max() <= TOP_HALF_M + 0.5:
            polys.append(hull(p[:, [0, 2]]))
            submerged = p[:, 1].max() < 0  # its top under the waterline
            colours.append("tab:red" if broken[b] else ("0.55" if submerged else "0.85"))
    top.add_collection(collection(polys, colours, "tab:red"))
    r0 = float(np.interp(0.0, profile[:, 0], profile[:, 1]))
    top.add_patch(plt.Circle((axis[0], axis[2]), r0, color="tab:blue", alpha=0.35))
    top.plot([event["x"]], [zj], "kx", ms=8)
    top.set_aspect("equal")
    top.set_xlim(axis[0] - 0.5, axis[0] + TOP_HALF_M)
    top.set_ylim(axis[2] - TOP_HALF_M / 1.6, axis[2] + TOP_HALF_M / 1.6)
    top.set_xlabel("x, m")
    top.set_ylabel("z, m")
    top.set_title("top view (darker: bodies with their top under water)", fontsize=9)

    g = dict(run.grid)
    what = mechanism if exact else f"no '{mechanism}' break at this f_ii; the first break, '{event.get('mechanism_name')}'"
    fig.suptitle(f"{run.scenario}, f_ii {g.get(FII)}, f_is {g.get(FIS)}, seed {run.seed}: {what}\n"
                 f"floe {event['floe']} joint {event['joint']} breaks in {event['mode_name']} at t = {event['time']:.2f} s "
                 f"(snapshot {st[k]:.1f} s); depth {1e3 * event['depth']:.0f} mm, other floes press "
                 f"{event['press_down']:.0f} N down, {event['press_toward']:.0f} N towards the axis; "
                 f"structure {event['structure_force']:.0f} N"
                 + ("" if again else "\n(the repeated run did not break this joint at this time: the picture may differ)"),
                 fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sweep")
    ap.add_argument("--out", help="the sweep's output directory (default sweeps/<name>)")
    ap.add_argument("--figures", help="where the PNGs go (default OUT/figures)")
    ap.add_argument("--icedem", default=execute.DEFAULT_ICEDEM)
    args = ap.parse_args(argv)
    name, runs = spec.load(args.sweep)
    out = os.path.abspath(args.out or os.path.join(spec.ROOT, "sweeps", name))
    figs = os.path.abspath(args.figures or os.path.join(out, "figures"))
    output_guard.guard([("--figures", figs, output_guard.DIRECTORY)], [args.sweep])
    os.makedirs(figs, exist_ok=True)
    records = [(r, agg.load_record(r, out)) for r in runs if execute.status(r, out).state == "done"]
    for scenario in dict.fromkeys(r.scenario for r in runs):
        for fii, mechanism in WANTED:
            chosen = pick(records, scenario, fii, mechanism)
            if chosen is None:
                continue
            run, event, exact = chosen
            h5 = repeat(run, event, out, os.path.abspath(args.icedem))
            path = os.path.join(figs, f"break_{scenario}_fii{fii:g}.png")
            draw(h5, run, event, exact, mechanism, path)
            print("wrote", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
