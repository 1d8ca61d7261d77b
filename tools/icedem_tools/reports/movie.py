"""A movie of a run: the floes seen from above and from the side, the joints that have broken
marked, and the surge load running beside them, one frame per snapshot.

    scripts/movie RUN.h5 [-o MOVIE.gif] [--every N] [--start T] [--end T] [--fps F] [--span M]

The run must keep snapshots (`output.snapshot_interval` > 0; the paper scenarios keep one a
second). The movie is an animated GIF (Pillow, which the project installs), or an MP4 when the
name ends in .mp4 and Debian's ffmpeg is installed. Top view: every body's outline where the
snapshot has it, in shades of blue by floe, pale while asleep; the joints broken by then as red lines (their
glued faces, dem/output/xdmf's joints); the structure's waterline section; level ice cut by closed forms, its
held sheet as it stood at the frame's time (/sheet/outline_*), pale grey. Side view: the same
bodies as prisms across the channel, the structure's profile (heaved and pitched as it moves, for a
moored one, with its mooring's lines in orange: /snapshots/mooring_lines). Both follow the structure, `--span`
metres either side of it (default 4). Right: the surge load over the run, a marker at the frame's
time. Nothing of the run is written to: the movie goes to -o (default beside the run, RUN.gif).
"""
import argparse
import os
import shutil
import sys
import tomllib

import h5py
import numpy as np

from ..runs import output_guard
from ..runs.results import ABSENT, snapshot_field
from ..runs.xdmf import joint_faces, quat_to_matrix


def structure_profile(h):
    """The hull's (height, radius) stations of the run's scenario (its resolved text in /meta)."""
    text = h["/meta"].attrs["scenario"]
    text = text.decode() if isinstance(text, bytes) else str(text)
    return np.array(tomllib.loads(text)["structure"]["profile"], dtype=float)


def radius_at(profile, y):
    """The hull's radius at height y (0 outside its stations)."""
    if y < profile[0, 0] or y > profile[-1, 0]:
        return 0.0
    return float(np.interp(y, profile[:, 0], profile[:, 1]))


def read(path):
    """What the movie draws, from the run's file."""
    with h5py.File(path, "r") as h:
        if "/snapshots/time" not in h or len(h["/snapshots/time"]) == 0:
            raise output_guard.Refused(f"{path}: the run kept no snapshots (set output.snapshot_interval > 0 "
                                       "and run it again)")
        off, vertices, thickness = h["/bodies/vertex_offset"][:], h["/bodies/vertices"][:], h["/bodies/thickness"][:]
        run = {
            "times": h["/snapshots/time"][:],
            "field": snapshot_field(h),
            "outlines": [vertices[off[b]:off[b + 1]] for b in range(len(off) - 1)],
            "thickness": thickness,
            "floe": h["/bodies/floe_id"][:],
            "load_time": h["/load/time"][:],
            "surge": h["/load/surge"][:],
            "structure": h["/structure/position"][:],
            # a moored structure's rotation vector per step and its lines per snapshot (none when towed)
            "rotation": h["/structure/rotation"][:] if "/structure/rotation" in h else None,
            "lines": h["/snapshots/mooring_lines"][:] if "/snapshots/mooring_lines" in h else None,
            "profile": structure_profile(h),
            "joints": joint_faces(h, off, vertices, thickness),
            "sheet": sheet_outlines(h),
        }
    return run


def sheet_outlines(h):
    """Level ice cut by closed forms: the times of the sheet's breaks and its outlines, at the start and after each
    (outline i + 1 stands from break i on); None for other runs."""
    if "/sheet/breaks" not in h:
        return None
    end, vertices = h["/sheet/outline_end_row"][:], h["/sheet/outline_vertices"][:]
    start = np.concatenate([[0], end[:-1]])
    return {"times": h["/sheet/breaks"]["time"][:], "outlines": [vertices[a:b] for a, b in zip(start, end)]}


def sheet_at(sheet, t):
    """The sheet's outline at time t: the last one written by then (a file cut between an outline and its break
    row holds one outline more than breaks: it is not yet the sheet's)."""
    i = int(np.searchsorted(sheet["times"], t, side="right"))
    return sheet["outlines"][min(i, len(sheet["times"]))]


def body_shapes(run, k):
    """Per body at snapshot k: its top-view outline (x, z) and its side-view outline (x, y, the
    convex hull of its prism's corners), and whether it is in the run and awake."""
    position, orientation, awake = (a[k] for a in run["field"])
    top, side = [], []
    for b, outline in enumerate(run["outlines"]):
        R = quat_to_matrix(orientation[b])
        half = run["thickness"][b] / 2
        n = len(outline)
        corners = np.empty((2 * n, 3))
        corners[:n] = np.column_stack([outline[:, 0], np.full(n, half), outline[:, 1]])
        corners[n:] = np.column_stack([outline[:, 0], np.full(n, -half), outline[:, 1]])
        world = corners @ R.T + position[b]
        top.append(world[:n][:, [0, 2]])
        side.append(hull_2d(world[:, [0, 1]]))
    return top, side, awake


def hull_2d(points):
    """The convex hull of points in the plane, counter-clockwise."""
    from scipy.spatial import ConvexHull
    return points[ConvexHull(points).vertices]


def structure_at(run, t):
    """The structure's reference point (its axis at the waterline) at time t, m."""
    lt = run["load_time"]
    return np.array([np.interp(t, lt, run["structure"][:, i]) for i in range(3)])


def rotation_at(run, t):
    """The structure's rotation matrix at time t (the identity for a towed one)."""
    if run["rotation"] is None:
        return np.eye(3)
    from scipy.spatial.transform import Rotation
    lt = run["load_time"]
    return Rotation.from_rotvec([np.interp(t, lt, run["rotation"][:, i]) for i in range(3)]).as_matrix()


def draw(run, frames, path, fps, span):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
    from matplotlib import animation  # noqa: E402
    from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402

    fig = plt.figure(figsize=(11, 5.2))
    grid = fig.add_gridspec(2, 2, width_ratios=[2.2, 1], height_ratios=[2.2, 1])
    top_ax, side_ax, load_ax = fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[1, 0]), fig.add_subplot(grid[:, 1])
    profile = run["profile"]
    # floes in shades of ice blue by floe (so that red is the cracks' alone)
    floe_colour = plt.get_cmap("Blues")(0.3 + 0.5 * ((run["floe"] * 0.618034) % 1.0))
    load_ax.plot(run["load_time"], run["surge"], lw=0.6, color="0.3")
    load_ax.set_xlabel("time, s")
    load_ax.set_ylabel("surge load, N")
    cursor = load_ax.axvline(run["times"][frames[0]], color="C3", lw=1)
    marker, = load_ax.plot([], [], "o", color="C3", ms=4)
    # the hull: its profile mirrored about the axis (side), its waterline circle (top)
    hull_side = np.concatenate([np.column_stack([profile[:, 1], profile[:, 0]]),
                                np.column_stack([-profile[::-1, 1], profile[::-1, 0]])])
    r0 = radius_at(profile, 0.0)
    circle = np.column_stack([r0 * np.cos(np.linspace(0, 2 * np.pi, 64)), r0 * np.sin(np.linspace(0, 2 * np.pi, 64))])
    joints = run["joints"]
    # across the channel: the floes' extent at the first frame, and the structure's
    first_top, _, _ = body_shapes(run, frames[0])
    sheet = run["sheet"]
    z_all = np.concatenate([o[:, 1] for o in first_top] + [[-r0, r0]] +
                           ([sheet["outlines"][0][:, 1]] if sheet is not None else []))
    z_lim = (z_all.min() - 0.1, z_all.max() + 0.1)

    def frame(i):
        k = frames[i]
        t = run["times"][k]
        top, side, awake = body_shapes(run, k)
        s = structure_at(run, t)
        for ax in (top_ax, side_ax):
            ax.clear()
        if sheet is not None:  # the held sheet, beneath the floes
            top_ax.add_collection(PolyCollection([sheet_at(sheet, t)], facecolors="0.85", edgecolors="0.5",
                                                 linewidths=0.5, zorder=0))
        present = [b for b in range(len(top)) if awake[b] != ABSENT]
        colours = [(*floe_colour[b][:3], 1.0 if awake[b] == 1 else 0.45) for b in present]
        top_ax.add_collection(PolyCollection([top[b] for b in present], facecolors=colours, edgecolors="0.2",
                                             linewidths=0.3))
        side_ax.add_collection(PolyCollection([side[b] for b in present], facecolors=colours, edgecolors="0.2",
                                              linewidths=0.3))
        if joints is not None:  # the broken joints' glued faces, seen from above: their top edge
            quads, first, _, break_time, _, _ = joints
            broken = np.flatnonzero((break_time >= 0) & (break_time <= t))
            if len(broken):
                position, orientation, _ = (a[k] for a in run["field"])
                segs = []
                for j in broken:
                    b = first[j]
                    w = quads[j][:2] @ quat_to_matrix(orientation[b]).T + position[b]
                    segs.append(w[:, [0, 2]])
                top_ax.add_collection(LineCollection(segs, colors="red", linewidths=1.6))
        # the hull see-through: floes pushed under it stay in view; a moored one's heave and pitch
        R = rotation_at(run, t)
        side = np.column_stack([hull_side, np.zeros(len(hull_side))]) @ R.T
        top_ax.fill(circle[:, 0] + s[0], circle[:, 1] + s[2], color="0.4", alpha=0.45, zorder=3)
        side_ax.fill(side[:, 0] + s[0], side[:, 1] + s[1], color="0.4", alpha=0.45, zorder=3)
        if run["lines"] is not None:  # the mooring's lines, anchors to fairleads
            for line in run["lines"][k]:
                top_ax.plot(line[:, 0], line[:, 2], color="C1", lw=1.2, zorder=4)
                side_ax.plot(line[:, 0], line[:, 1], color="C1", lw=1.2, zorder=4)
        side_ax.axhline(0.0, color="C0", lw=0.8, zorder=0)
        top_ax.set_xlim(s[0] - span, s[0] + span)
        top_ax.set_ylim(*z_lim)
        top_ax.set_aspect("equal", adjustable="box")
        top_ax.set_title(f"t = {t:.1f} s, from above", fontsize=9)
        top_ax.set_ylabel("z, m")
        side_ax.set_xlim(s[0] - span, s[0] + span)
        side_ax.set_ylim(profile[0, 0] - 0.05, profile[-1, 0] + 0.1)
        side_ax.set_xlabel("x, m")
        side_ax.set_ylabel("y, m")
        side_ax.set_title("from the side", fontsize=9)
        cursor.set_xdata([t, t])
        marker.set_data([t], [np.interp(t, run["load_time"], run["surge"])])
        return []

    fig.tight_layout()
    movie = animation.FuncAnimation(fig, frame, frames=len(frames), blit=False)
    writer = (animation.FFMpegWriter(fps=fps) if path.endswith(".mp4") else animation.PillowWriter(fps=fps))
    # written whole through a temporary file beside it (output_guard's rule)
    output_guard.write_with(path, lambda tmp: movie.save(tmp, writer=writer, dpi=80))
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="a run's HDF5 output with snapshots")
    ap.add_argument("-o", "--output", help="the movie: .gif, or .mp4 with ffmpeg (default: RUN.gif beside the run)")
    ap.add_argument("--every", type=int, default=1, help="one frame every N snapshots (default 1)")
    ap.add_argument("--start", type=float, default=None, help="first time, s")
    ap.add_argument("--end", type=float, default=None, help="last time, s")
    ap.add_argument("--fps", type=float, default=10.0, help="frames per second of the movie (default 10)")
    ap.add_argument("--span", type=float, default=4.0, help="m shown either side of the structure (default 4)")
    a = ap.parse_args(argv)
    path = a.output or os.path.splitext(a.run)[0] + ".gif"
    if not path.endswith((".gif", ".mp4")):
        raise output_guard.Refused(f"-o {path}: a movie is a .gif or an .mp4")
    if path.endswith(".mp4") and shutil.which("ffmpeg") is None:
        raise output_guard.Refused(f"-o {path}: an MP4 needs ffmpeg (apt-get install ffmpeg); a .gif needs nothing")
    if a.every < 1 or not a.fps > 0 or not a.span > 0:
        raise output_guard.Refused("--every must be at least 1, --fps and --span above 0")
    output_guard.guard([("-o", path, output_guard.FILE)], [a.run])
    if not os.path.isfile(a.run):
        raise output_guard.Refused(f"{a.run}: no such file (a run's HDF5 output)")
    try:
        run = read(a.run)
    except (OSError, KeyError) as e:  # not HDF5, or not an icedem output
        raise output_guard.Refused(f"{a.run}: not a run's output that a movie can be made of ({e})") from e
    times = run["times"]
    frames = [k for k in range(0, len(times), a.every)
              if (a.start is None or times[k] >= a.start) and (a.end is None or times[k] <= a.end)]
    if not frames:
        raise output_guard.Refused(f"no snapshot of {a.run} lies in the times asked for "
                                   f"(its snapshots: {times[0]:.2f} to {times[-1]:.2f} s)")
    draw(run, frames, path, a.fps, a.span)
    print(f"wrote {path}: {len(frames)} frames of {a.run}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
