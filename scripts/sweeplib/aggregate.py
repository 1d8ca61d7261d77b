"""Aggregation of a sweep's finished runs, per configuration (a scenario with one
grid combination, over its seeds):

- mean over seeds of the mean surge load and of the max surge load, each with a
  95 % confidence interval (Student's t with n - 1 degrees of freedom; none for
  one seed);
- the mean peak interval of the load (icedem's summary), and the spectral peak:
  the frequency of the largest Welch power of the surge load over the analysis
  window, averaged over seeds (its period beside it);
- breaks by failure mode, summed over seeds.

Written as one table: CSV and HDF5 (a compound dataset /configurations).
"""
import csv
import json
import math
import os

import h5py
import numpy as np
from scipy import signal, stats

MODES = ("compression", "shear", "bending", "tension", "in_plane_bending")


def mean_ci(values, level=0.95):
    """(mean, half-width of the two-sided confidence interval); half-width nan for n < 2."""
    x = np.asarray(values, dtype=float)
    n = len(x)
    if n == 0:
        return float("nan"), float("nan")
    m = float(np.mean(x))
    if n < 2:
        return m, float("nan")
    half = float(stats.t.ppf(0.5 + level / 2, n - 1) * np.std(x, ddof=1) / math.sqrt(n))
    return m, half


def spectral_peak(t, x, segment_s=60.0):
    """Frequency (Hz) of the largest Welch power of x(t) (uniform steps), the mean removed,
    segments of segment_s (or the whole record if shorter), Hann window, half overlap."""
    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    if len(x) < 8:
        return float("nan")
    fs = 1.0 / float(np.median(np.diff(t)))
    nperseg = min(len(x), int(round(segment_s * fs)))
    f, p = signal.welch(x - np.mean(x), fs=fs, nperseg=nperseg)
    if len(f) < 2:
        return float("nan")
    return float(f[1 + np.argmax(p[1:])])  # skip the zero frequency


def run_record(run_dir):
    """What aggregation needs from one finished run: its summary and its load spectrum peak."""
    with open(os.path.join(run_dir, "summary.json")) as f:
        s = json.load(f)
    peak_hz = float("nan")
    start, end = s.get("window_start_s"), s.get("window_end_s")
    if start is not None and end is not None:
        with h5py.File(os.path.join(run_dir, "run.h5"), "r") as h:
            t = h["/load/time"][:]
            x = h["/load/surge"][:]
        sel = (t >= start) & (t <= end)
        peak_hz = spectral_peak(t[sel], x[sel])
    return {"mean_fx_N": s.get("mean_fx_N"), "max_fx_N": s.get("max_fx_N"),
            "peak_interval_s": s.get("peak_interval_s"), "spectral_peak_hz": peak_hz,
            "breaks_by_mode": s.get("breaks_by_mode", {}), "realtime_factor": s.get("realtime_factor")}


def _finite(values):
    return [v for v in values if v is not None and math.isfinite(v)]


def aggregate(groups):
    """groups: {config: (scenario, grid tuple, [run records])} -> list of row dicts."""
    rows = []
    for config, (scenario, grid, records) in groups.items():
        row = {"configuration": config, "scenario": scenario}
        for k, v in grid:
            row[k] = v
        row["seeds"] = len(records)
        for key in ("mean_fx_N", "max_fx_N"):
            m, half = mean_ci(_finite(r[key] for r in records))
            row[key] = m
            row[key + "_ci95"] = half
        pi = _finite(r["peak_interval_s"] for r in records)
        row["peak_interval_s"] = float(np.mean(pi)) if pi else float("nan")
        sp = _finite(r["spectral_peak_hz"] for r in records)
        row["spectral_peak_hz"] = float(np.mean(sp)) if sp else float("nan")
        row["spectral_peak_period_s"] = 1.0 / row["spectral_peak_hz"] if sp and row["spectral_peak_hz"] > 0 else float("nan")
        for mode in MODES:
            row["breaks_" + mode] = int(sum(r["breaks_by_mode"].get(mode, 0) for r in records))
        rtf = _finite(r["realtime_factor"] for r in records)
        row["realtime_factor"] = float(np.mean(rtf)) if rtf else float("nan")
        rows.append(row)
    return rows


def write_csv(rows, path):
    keys = list(dict.fromkeys(k for r in rows for k in r))
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


def write_hdf5(rows, path):
    """One compound dataset /configurations; strings as UTF-8, numbers as f8 (grid values too)."""
    keys = list(dict.fromkeys(k for r in rows for k in r))
    text = {k for k in keys if any(isinstance(r.get(k), str) for r in rows)}
    dtype = [(k, h5py.string_dtype()) if k in text else (k, "f8") for k in keys]
    data = np.zeros(len(rows), dtype=dtype)
    for i, r in enumerate(rows):
        for k in keys:
            v = r.get(k)
            data[i][k] = (v if v is not None else "") if k in text else (float(v) if v is not None else np.nan)
    with h5py.File(path, "w") as h:
        d = h.create_dataset("configurations", data=data)
        d.attrs["description"] = ("per configuration: mean over seeds of the mean and max surge load (N) "
                                  "with 95 % CI half-widths, peak interval (s), spectral peak (Hz, s), "
                                  "breaks by mode summed over seeds")
