"""Figures of a friction sweep laid out like the seed paper's (run
`scripts/sweep aggregate` first):

  loads_vs_fis_<scenario>.png   average and max surge load against f_is, one line per
                                f_ii, 95 % confidence bars over seeds (Figs. 8, 12, 16)
  history_<scenario>.png        surge load time histories at f_ii = 0.5 for each f_is,
                                first seed, from the first ice contact (Figs. 9, 13, 17)
  topview_<scenario>.png        floes and cone seen from above at the start, at the snapshot
                                nearest the largest load and at the end, f_ii = 0.5,
                                f_is = 0.2, first seed (Figs. 4, 11, 14, 18)
  frontview_<scenario>.png      front view of floe trajectories: heave against sway relative
                                to the cone axis, of every body within 1 m ahead or behind
                                the axis, from the snapshots of the same run (Fig. 10)
  spectrum_<scenario>.png       ensemble load spectra (Welch, mean over seeds) at f_ii = 0.5
                                for each f_is, with the floe-passage frequency v/L marked
                                (the paper's "peaks at about 4 s intervals")
  ratios_<scenario>.png         breakable floes: histogram of the largest joint load ratio of
                                every floe that came within 1 m of the structure, per f_ii

The drawn runs' HDF5 files are needed; a run known only by its kept record
(tools/icedem_tools/runs/spec.py) is run again for them. And, beside the run the top view
shows, run.xdmf and run_views.h5: its snapshots for ParaView
(scripts/xdmf_snapshots.py).

    scripts/sweep_figures.py SWEEP.toml [--out DIR] [--figures DIR] [--icedem PATH] [--jobs N]
"""
import argparse
import os
import sys

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

from ..sweeps import aggregate as agg, execute
from ..runs import output_guard, results, runner, spec, xdmf
from .report_tables import FII, FIS, read_rows

RUN_H5 = runner.RUN_FILES["h5"]


def save(fig, path):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def reference_run(runs, out, scenario):
    """The finished run of `scenario` at the paper's reference friction (f_ii 0.5, f_is 0.2,
    or whatever the sweep does not vary) with the lowest seed; None if there is none."""
    sel = [r for r in runs if r.scenario == scenario and dict(r.grid).get(FII, 0.5) == 0.5
           and dict(r.grid).get(FIS, 0.2) == 0.2 and execute.status(r, out).state == "done"]
    return min(sel, key=lambda r: r.seed) if sel else None


def loads_vs_fis(rows, scenario, path):
    rows = [r for r in rows if r["scenario"] == scenario and r.get(FIS)]
    if not rows:
        return False
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    # one line per f_ii; a sweep that does not vary it gives one line (the scenario's f_ii)
    fiis = sorted({float(r[FII]) for r in rows}) if rows[0].get(FII) else [None]
    for fii in fiis:
        pts = sorted(((float(r[FIS]), r) for r in rows if fii is None or float(r[FII]) == fii), key=lambda p: p[0])
        x = [p[0] for p in pts]
        for ax, key in zip(axes, ("mean_fx_N", "max_fx_N")):
            y = [float(p[1][key]) for p in pts]
            e = [float(p[1][key + "_ci95"]) for p in pts]
            e = [0 if np.isnan(v) else v for v in e]
            ax.errorbar(x, y, yerr=e, marker="o", capsize=3,
                        label=f"f_ii = {fii:g}" if fii is not None else "scenario's f_ii")
    for ax, title in zip(axes, ("average surge load", "maximum surge load")):
        ax.set_xlabel("ice-structure friction f_is")
        ax.set_ylabel("N")
        ax.set_title(f"{scenario}: {title}")
        ax.grid(alpha=0.3)
        ax.legend()
    save(fig, path)
    return True


def history(runs, out, scenario, path):
    """Surge load against the time since the first ice contact, as the paper shifts its Figs. 9,
    13 and 17, with the analysis window shaded."""
    sel = [r for r in runs if r.scenario == scenario and dict(r.grid).get(FII, 0.5) == 0.5
           and r.seed == min(x.seed for x in runs) and execute.status(r, out).state == "done"]
    if not sel:
        return False
    fig, axes = plt.subplots(len(sel), 1, figsize=(10, 2.2 * len(sel)), sharex=True, squeeze=False)
    for ax, r in zip(axes[:, 0], sorted(sel, key=lambda r: dict(r.grid).get(FIS, 0))):
        summary = results.load_summary(os.path.join(out, r.path, runner.RUN_FILES["summary"]))
        t0 = summary.get("first_contact_s") or 0.0
        t0 = t0 if t0 > 0 else 0.0  # -1: no contact
        h = results.load_run(os.path.join(out, r.path, RUN_H5))
        ax.plot(h["/load/time"] - t0, h["/load/surge"], lw=0.6)
        if summary.get("window_start_s") is not None:
            ax.axvspan(summary["window_start_s"] - t0, summary["window_end_s"] - t0, color="0.93", zorder=0)
        ax.set_ylabel("surge N")
        ax.set_title(f"{scenario}, f_ii = 0.5, f_is = {dict(r.grid).get(FIS)}, seed {r.seed} "
                     f"(shaded: the analysis window)", fontsize=9)
        ax.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time since the first ice contact, s")
    axes[-1, 0].set_xlim(left=-5.0)  # the open-water approach before the contact carries no load
    save(fig, path)
    return True


def yaw_of(q):
    """Rotation about the vertical (y) axis of quaternions w, x, y, z (floes stay nearly flat)."""
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.arctan2(2 * (w * y + x * z), 1 - 2 * (y * y + x * x))


def waterline_radius(run):
    """The structure's radius at the waterline, from the resolved scenario in /meta."""
    profile = run.scenario["structure"]["profile"]
    ys = [p[0] for p in profile]
    rs = [p[1] for p in profile]
    return float(np.interp(0.0, ys, rs))


def topview(runs, out, scenario, path):
    r = reference_run(runs, out, scenario)
    if r is None:
        return False
    h = results.load_run(os.path.join(out, r.path, RUN_H5), snapshots=True)
    if h.snapshot_count == 0:
        return False
    st, off, verts = h["/snapshots/time"], h["/bodies/vertex_offset"], h["/bodies/vertices"]
    t, spos, surge = h["/load/time"], h["/structure/position"], h["/load/surge"]
    radius = waterline_radius(h)
    # start, the snapshot nearest the largest load (the paper's Fig. 14 shows the pack
    # when the load peaks), end
    t_max = t[int(np.argmax(surge))]
    picks = [0, int(np.argmin(np.abs(st - t_max))), len(st) - 1]
    fig, axes = plt.subplots(3, 1, figsize=(11, 8), sharex=True)
    for ax, k in zip(axes, picks):
        pos = h["/snapshots/position"][k]
        yaw = yaw_of(h["/snapshots/orientation"][k])
        present = h["/snapshots/awake"][k] != results.ABSENT  # split floes are their pieces
        polys = []
        for b in np.where(present)[0]:
            v = verts[off[b]:off[b + 1]]
            c, s = np.cos(yaw[b]), np.sin(yaw[b])
            # body frame (x, z) -> tank (x, z): rotation by yaw about +y
            x = pos[b, 0] + c * v[:, 0] + s * v[:, 1]
            z = pos[b, 2] - s * v[:, 0] + c * v[:, 1]
            polys.append(np.column_stack([x, z]))
        ax.add_collection(PolyCollection(polys, facecolor="0.85", edgecolor="0.3", lw=0.3))
        i = min(np.searchsorted(t, st[k]), len(t) - 1)
        ax.add_patch(plt.Circle((spos[i, 0], spos[i, 2]), radius, color="tab:red", alpha=0.6))
        ax.set_aspect("equal")
        ax.set_ylabel("z, m")
        ax.set_title(f"{scenario}, t = {st[k]:.0f} s, surge load {int(round(surge[i]))} N"
                     + (f" (largest {surge.max():.0f} N at {t_max:.0f} s)" if k == picks[1] else ""), fontsize=9)
        ax.autoscale_view()
    axes[-1].set_xlabel("x, m (towing direction)")
    save(fig, path)
    return True


def front_view(runs, out, scenario, path):
    r = reference_run(runs, out, scenario)
    if r is None:
        return False
    h = results.load_run(os.path.join(out, r.path, RUN_H5), snapshots=True)
    if h.snapshot_count < 2:
        return False
    st, pos, t, spos = h["/snapshots/time"], h["/snapshots/position"], h["/load/time"], h["/structure/position"]
    radius = waterline_radius(h)
    axis = spos[np.clip(np.searchsorted(t, st), 0, len(t) - 1)]
    dx = pos[:, :, 0] - axis[:, None, 0]
    near = (np.abs(dx) < 1.0) & (h["/snapshots/awake"] != results.ABSENT)
    fig, ax = plt.subplots(figsize=(8, 4))
    for b in np.where(near.any(axis=0))[0]:
        k = near[:, b]
        ax.plot(pos[k, b, 2] - axis[k, 2], pos[k, b, 1], "-", lw=0.5, alpha=0.6)
    ax.axvspan(-radius, radius, color="tab:red", alpha=0.15, label="cone at the waterline")
    ax.set_xlabel("sway z relative to the cone axis, m")
    ax.set_ylabel("heave y, m")
    ax.set_title(f"{scenario}: floe trajectories within 1 m of the cone axis (f_ii 0.5, f_is 0.2)", fontsize=9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, path)
    return True


def spectrum(runs, out, rows, scenario, path):
    """Ensemble spectra of results.h5 at f_ii = 0.5 (or the scenario's), one line per f_is."""
    idx = [i for i, r in enumerate(rows) if r["scenario"] == scenario and float(r.get(FII) or 0.5) == 0.5]
    ref = reference_run(runs, out, scenario)
    if not idx or ref is None or not os.path.isfile(os.path.join(out, "results.h5")):
        return False
    sc = results.load_run(os.path.join(out, ref.path, RUN_H5)).scenario
    passage_hz = sc["structure"]["speed"] / sc["ice"]["floe_size"]
    fig, ax = plt.subplots(figsize=(8, 4))
    drawn = False
    spectra = agg.read_spectra(os.path.join(out, "results.h5"))
    for i in idx:
        if i not in spectra:
            continue
        f, p = spectra[i]
        k = f > 0
        ax.semilogy(f[k], p[k], lw=1.0, label=f"f_is = {rows[i].get(FIS) or '-'} ({rows[i]['seeds']} seeds), "
                    f"peak {float(rows[i]['spectral_peak_period_s']):.2f} s")
        drawn = True
    if not drawn:
        plt.close(fig)
        return False
    ax.axvline(passage_hz, color="k", ls="--", lw=0.8, label=f"floe passage v/L = {passage_hz:.3f} Hz "
               f"({1 / passage_hz:.2f} s)")
    ax.axvspan(0, agg.MIN_PEAK_HZ, color="0.9", label="pack drift, not searched for the peak")
    ax.set_xlim(0, 1.0)
    ax.set_xlabel("frequency, Hz")
    ax.set_ylabel("surge load power, N$^2$/Hz")
    ax.set_title(f"{scenario}: ensemble spectra of the surge load, f_ii = 0.5", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3, which="both")
    save(fig, path)
    return True


def ratios(records, scenario, path):
    """Histogram of the largest joint load ratio of every floe that came near the structure
    (summary near_structure_max_ratio), one line per f_ii; False without breakable floes."""
    by_fii = {}
    for r, rec in records.items():
        if r.scenario == scenario:
            by_fii.setdefault(dict(r.grid).get(FII), []).extend(rec["summary"].get("near_structure_max_ratio", []))
    if not any(by_fii.values()):
        return False
    fig, ax = plt.subplots(figsize=(7, 3.6))
    top = max(1.3, max(max(v) for v in by_fii.values() if v))
    bins = np.linspace(0, top, 40)
    for fii in sorted(by_fii, key=lambda v: (v is None, v)):
        v = by_fii[fii]
        if v:
            ax.hist(v, bins=bins, histtype="step", density=True, lw=1.3,
                    label=f"f_ii = {fii} ({len(v)} floes)" if fii is not None else f"{len(v)} floes")
    ax.axvline(1.0, color="k", ls="--", lw=0.8, label="capacity (eq. 1-3): breaks")
    ax.set_xlabel("largest joint load / capacity of a floe near the structure")
    ax.set_ylabel("probability density")
    ax.set_title(f"{scenario}: how close the floes within 1 m of the structure came to breaking", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    save(fig, path)
    return True


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("sweep")
    ap.add_argument("--out", help="the sweep's output directory (default sweeps/<name>)")
    ap.add_argument("--figures", help="where the PNGs go (default OUT/figures)")
    ap.add_argument("--icedem", default=execute.DEFAULT_ICEDEM,
                    help="to run again the drawn runs known only by their kept records")
    ap.add_argument("--jobs", type=int, default=0, help="parallel jobs for those runs (0: one per core)")
    args = ap.parse_args(argv)
    name, runs = spec.load(args.sweep)
    out = os.path.abspath(args.out or os.path.join(spec.ROOT, "sweeps", name))
    figs = args.figures or os.path.join(out, "figures")
    output_guard.guard([("--figures", figs, output_guard.DIRECTORY)], [args.sweep])
    os.makedirs(figs, exist_ok=True)
    rows = read_rows(out)
    # the runs drawn from their HDF5 files (a kept record holds no time series): run again
    # those finished on another machine
    lowest = min(r.seed for r in runs)
    drawn = [r for r in runs if dict(r.grid).get(FII, 0.5) == 0.5 and r.seed == lowest
             and execute.status(r, out).state == "done"]
    execute.run_here(drawn, out, os.path.abspath(args.icedem), args.jobs)
    records = {r: agg.load_record(r, out) for r in runs if execute.status(r, out).state == "done"}
    written = []
    for scenario in dict.fromkeys(r.scenario for r in runs):
        for kind, fn in (("loads_vs_fis", lambda p: loads_vs_fis(rows, scenario, p)),
                         ("history", lambda p: history(runs, out, scenario, p)),
                         ("topview", lambda p: topview(runs, out, scenario, p)),
                         ("frontview", lambda p: front_view(runs, out, scenario, p)),
                         ("spectrum", lambda p: spectrum(runs, out, rows, scenario, p)),
                         ("ratios", lambda p: ratios(records, scenario, p))):
            p = os.path.join(figs, f"{kind}_{scenario}.png")
            if fn(p):
                written.append(p)
        ref = reference_run(runs, out, scenario)
        if ref is not None:
            run_h5 = os.path.join(out, ref.path, RUN_H5)
            if results.load_run(run_h5).snapshot_count > 0:
                xdmf.write_views(run_h5)
    for p in written:
        print("wrote", p)
    return 0 if written else 1


if __name__ == "__main__":
    sys.exit(main())
