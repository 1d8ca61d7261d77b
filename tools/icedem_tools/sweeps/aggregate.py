"""Aggregation of a sweep's finished runs, per configuration (a scenario with one
grid combination, over its seeds):

- mean over seeds of the mean surge load and of the max surge load, each with a
  95 % confidence interval (Student's t with n - 1 degrees of freedom; none for
  one seed);
- a Gumbel (type I) fit of the seed maxima by moments (docs/model/validation_targets.md §7),
  for extrapolating the max to longer records, and their coefficient of variation;
- the mean peak interval of the load (icedem's summary), and the spectral peak:
  the frequency of the largest power of the ensemble spectrum (the Welch spectra
  of the seeds' surge loads over their analysis windows, averaged), searched
  above MIN_PEAK_HZ (its period beside it);
- breaks by failure mode and by mechanism (dem/fracture/break_context.hpp), summed over seeds;
- the summed run time, wall and CPU.

Written as one table: CSV and HDF5 (a compound dataset /configurations, and the
ensemble spectra under /spectra/<row index>).
"""
import collections
import csv
import json
import math
import os
import sys

import h5py
import numpy as np
from scipy import signal

from ..runs import pieces, results
from ..stats.intervals import gumbel_fit, mean_ci
from ..runs.results import mode_key
from ..runs.runner import RUN_FILES

SEGMENT_S = 60.0
# The load spectrum of a pack is red: its largest power sits at the lowest bin,
# the slow build-up and release of the compacted pack over tens of seconds. The
# floe-passage peak the paper reports (L/v = 4.3 s small, 8.6 s large floes) is
# searched above 0.05 Hz: periods under 20 s, more than twice the larger floes'.
MIN_PEAK_HZ = 0.05


def window_loads(summary, t_end=None):
    """Mean, 99th percentile and max of the surge load over the run's analysis
    window, or over the part of it before t_end (s)."""
    run = results.load_run(os.path.join(summary["run_dir"], RUN_FILES["h5"]))
    t, surge = run["/load/time"], run["/load/surge"]
    end = summary["window_end_s"] if t_end is None else min(t_end, summary["window_end_s"])
    w = (t >= summary["window_start_s"]) & (t <= end)
    if not w.any():
        return float("nan"), float("nan"), float("nan")
    return float(surge[w].mean()), float(np.percentile(surge[w], 99)), float(surge[w].max())


TOP_FLOES = 20  # the floes whose load / capacity ratios make a run's failure ratio


def fracture_figures(summary):
    """A run's failure ratio and its floes broken, read from its file at once.

    The failure ratio says how near its ice came to breaking: the mean of the TOP_FLOES
    largest per-floe load / capacity ratios (/fracture/floe_max_ratio), or None for rigid
    floes. At the paper's strength the lattices break a floe in one run of several, so
    breaks per run cannot tell two solves apart over five seeds; this tail of the ratios,
    which every run has, can (a solve that inflates the joints' loads raises it).
    Floes broken, not joints: joints break in clusters (a floe at several joints in a step
    or two), so the floes are the independent events."""
    with h5py.File(os.path.join(summary["run_dir"], RUN_FILES["h5"]), "r") as f:
        events = f["/fracture/events"][()]
        r = np.sort(f["/fracture/floe_max_ratio"][:])[::-1] if "/fracture/floe_max_ratio" in f else []
    ratio = float(r[:TOP_FLOES].mean()) if len(r) and r[0] > 0 else None
    return ratio, len(set(int(x) for x in events["floe"])) if len(events) else 0


def finished(summary):
    """Whether a run finished with statistics (its summary's status and mean)."""
    return summary.get("status") == "complete" and summary.get("mean_fx_N") is not None


def ensemble(runs, per_run, summary=lambda run: run, counts=finished):
    """The project's one reduction of a setting's runs over seeds, for every study and report.

    `runs`: one item per seed (a summary, or a record that `summary` takes its summary from);
    those `counts` accepts are reduced. `per_run(run)` gives a run's numbers by name (None or
    left out where a run has none); a number is reduced only where every counted run has it.
    Returns None without a counted run, else {"n", "failed" (runs not counted), "message" (the
    first of theirs), "seeds", "runs": {name: array over the counted runs}, name: (mean,
    half-width of its 95 % interval, nan for one run) for each name, and the means of the cost and solver
    figures "cpu" (s per run), "rtf" (simulated over CPU time), "sweeps" (iterations per step)
    and "capped" (share of the window's steps stopped at the cap)}."""
    ok = [r for r in runs if counts(r)]
    if not ok:
        return None
    sums = [summary(r) for r in ok]
    rows = [per_run(r) for r in ok]
    e = {"n": len(ok), "failed": len(runs) - len(ok),
         "message": next((str(summary(r).get("message", "")) for r in runs if not counts(r)), ""),
         "seeds": [x.get("seed") for x in sums],
         "runs": {k: np.array([row[k] for row in rows], dtype=float) for k in rows[0]
                  if all(row.get(k) is not None for row in rows)}}
    for k, v in e["runs"].items():
        e[k] = mean_ci(v)
    nan = float("nan")
    cpu = np.array([x.get("cpu_time_s", nan) for x in sums], dtype=float)
    e["cpu"] = float(cpu.mean())
    with np.errstate(divide="ignore", invalid="ignore"):
        e["rtf"] = float(np.mean(np.array([x.get("sim_time_s", nan) for x in sums], dtype=float) / cpu))
    e["sweeps"] = float(np.mean([x.get("solver", {}).get("iterations_mean", nan) for x in sums]))
    e["capped"] = float(np.mean([x.get("solver", {}).get("capped_window_fraction", nan) for x in sums]))
    return e


def welch_spectrum(t, x, segment_s=SEGMENT_S):
    """(frequencies Hz, power N^2/Hz) of x(t) (uniform steps): Welch, Hann window, half
    overlap, segments of segment_s (or the whole record if shorter), each detrended
    linearly so that a slow drift does not leak into the low bins."""
    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    if len(x) < 8:
        return np.array([]), np.array([])
    fs = 1.0 / float(np.median(np.diff(t)))
    nperseg = min(len(x), int(round(segment_s * fs)))
    return signal.welch(x, fs=fs, nperseg=nperseg, detrend="linear")


def peak_frequency(f, p, min_hz=MIN_PEAK_HZ):
    """Frequency of the largest power at or above min_hz (nan if there is none)."""
    f, p = np.asarray(f), np.asarray(p)
    band = f >= min_hz
    if not band.any():
        return float("nan")
    return float(f[band][np.argmax(p[band])])


def spectral_peak(t, x, segment_s=SEGMENT_S, min_hz=MIN_PEAK_HZ):
    """Frequency (Hz) of the largest Welch power of one record above min_hz."""
    return peak_frequency(*welch_spectrum(t, x, segment_s), min_hz)


def ensemble_spectrum(spectra):
    """Mean of the seeds' spectra that share the most common frequency grid (records
    shorter than a segment each get their own grid); (f, p) or two empty arrays."""
    spectra = [(f, p) for f, p in spectra if len(f)]
    if not spectra:
        return np.array([]), np.array([])
    grids = [(len(f), round(float(f[1] - f[0]), 12)) for f, _ in spectra]
    common = max(set(grids), key=grids.count)
    same = [s for s, g in zip(spectra, grids) if g == common]
    return same[0][0], np.mean([p for _, p in same], axis=0)


# A record keeps the spectrum up to this frequency: the peaks of interest (floe
# passages at 0.1-0.3 Hz) lie far below it, and the record stays a few kB.
RECORD_MAX_HZ = 2.0


def break_names(summaries, key):
    """The failure modes (key "breaks_by_mode") or break mechanisms ("breaks_by_mechanism") the
    runs' summaries count, spaces and hyphens as "_", sorted. icedem declares them once
    (/fracture/events mode_names and mechanism_names) and every summary counts all of them, so
    the tools read them instead of repeating them."""
    return sorted({mode_key(k) for x in summaries for k in (x.get(key) or {})})


# the low-pass cut-offs a record keeps its window's maximum at (a load cell and carriage have a
# bandwidth the runs' record has not: docs/model/tank_maxima.md)
LOWPASS_HZ = [10.0, 5.0]


def lowpass(x, dt, cutoff_hz):
    """The load filtered as icedem's stats.lowpass_hz filters it (dem/output/statistics.cpp): a 2nd-order
    Butterworth (scipy.signal.butter's design), run forward then backward from rest over the record padded
    at both ends by odd reflection over about 3/fc."""
    n = len(x)
    b, a = signal.butter(2, cutoff_hz / (0.5 / dt))
    pad = min(n - 1, int(max(9.0, math.ceil(3.0 / (cutoff_hz * dt)))))
    ext = np.concatenate([2 * x[0] - x[pad:0:-1], x, 2 * x[-1] - x[-2:-pad - 2:-1]])
    y = signal.lfilter(b, a, ext)
    y = signal.lfilter(b, a, y[::-1])[::-1]
    return y[pad:pad + n]


def lowpassed(t, x):
    """{cut-off Hz as text: the whole record low-passed at it} for each of LOWPASS_HZ (the whole record, so that a
    window's edges see no filter start-up)."""
    dt = (t[-1] - t[0]) / (len(t) - 1)
    return {f"{fc:g}": lowpass(x, dt, fc) for fc in LOWPASS_HZ}


def lowpass_maxima(t, x, inside, filtered=None):
    """{cut-off Hz as text: the load's maximum over the samples `inside` after that low-pass} for each of
    LOWPASS_HZ; `filtered`: lowpassed(t, x) where the caller has it already."""
    return {k: float(y[inside].max()) for k, y in (filtered or lowpassed(t, x)).items()}


# the quantiles a record keeps of a level sheet's breaks and pieces (sheet_record)
SHEET_QUANTILES = (0.1, 0.25, 0.5, 0.75, 0.9)
# a break whose zone bore more than this times its breaking load: the check comes after the step's solve, so a zone
# passes its load by what one step adds, and further where its cut broke off no piece and the sheet stood
# (docs/model/breakage.md, "A piece's corner on the edge")
OVERLOAD = 2.0
# a break of the sheet below this times its breaking load: a floe the contact solve held at its patch's bound breaks
# the sheet after the step, by the patch the forces then make, whose load can be higher (a corner's opening angle
# depends on the patch's centre); the solve leaves a held patch within a few tenths of a percent of its bound, so a
# break below 0.99 of its load is the patches' difference, not the solve's (docs/model/breakage.md, "The edge's bound
# in the solve")
UNDERLOAD = 0.99


def longest_without_break(run, breaks):
    """The longest time (s, to 4 digits) from one of a sheet's `breaks` to the next, or from the last to the run's
    end (its last /load/time); None without breaks."""
    if not len(breaks):
        return None
    t = np.sort(np.asarray(breaks["time"], dtype=float))
    end = max(float(np.asarray(run["/load/time"])[-1]), t[-1]) if "/load/time" in run else t[-1]
    return float(f"{np.diff(np.append(t, end)).max():.4g}")


def at_the_cap(run, breaks, by_floe):
    """(the breaks a floe made (`by_floe`: a mask of `breaks`, or None where the run does not say) at a step whose
    solve reached its cap, handed an island over there or left one capped; the breaks of any kind at such a step; the
    share of all the run's steps that are such), from /diagnostics (per step, as /load/time); None without them. A
    floe's push that breaks the sheet is the solve's answer: where that stopped short of its tolerance, the break is
    the cap's as much as the ice's."""
    if not ("/diagnostics/solver_capped" in run and "/diagnostics/handovers" in run and "/load/time" in run):
        return None
    t = np.asarray(run["/load/time"], dtype=float)
    at_cap = (np.asarray(run["/diagnostics/solver_capped"]) > 0) | (np.asarray(run["/diagnostics/handovers"]) > 0)
    n = min(len(t), len(at_cap))
    if not n:
        return None
    k = np.clip(np.searchsorted(t[:n], np.asarray(breaks["time"], dtype=float) - 1e-9), 0, n - 1)
    hit = at_cap[:n][k]
    return (int((hit & by_floe).sum()) if by_floe is not None else 0), int(hit.sum()), float(f"{at_cap[:n].mean():.4g}")


def sheet_record(run):
    """Of a run of level ice cut by closed forms (/sheet/breaks), its breaks' crack distances (x*, m), the
    areas they broke off, how many bore more than OVERLOAD times their breaking load (and of those, how many broke
    off no piece), when they were and the largest such ratio, how many broke below UNDERLOAD times it and the
    smallest ratio, how many a floe's push on the edge made (the rest the cone's crushed zone: by_floe), the longest
    time from a break to the next or to the run's end (a floe's breaks can clear the sheet ahead of the cone, which
    then meets none for a while), how many fell at a step whose solve reached its cap (at_the_cap), and the pieces at
    the run's end (the bodies no split made two of): their count, the quantiles of their areas and of their
    equivalent diameters sqrt(4 A / pi), and the area-weighted mean diameter; None for any other run. Quantiles, not
    lists: a tow makes hundreds of pieces and a record stays a few kB."""
    if "/sheet/breaks" not in run:
        return None
    b = np.asarray(run["/sheet/breaks"])
    areas = np.asarray(pieces.body_areas(run), dtype=float)
    parents = np.asarray(run["/bodies/parent"])
    whole = np.ones(len(areas), dtype=bool)
    whole[parents[parents >= 0]] = False  # split into two pieces: its pieces count instead
    a = areas[whole]
    d = np.sqrt(4 * a / np.pi)

    def q(x):
        return [float(f"{v:.6g}") for v in np.quantile(x, SHEET_QUANTILES)] if len(x) else []
    ratio = b["load"] / b["breaking_load"]
    over = ratio > OVERLOAD
    # the breaks a floe's push made (by_floe 1; 0: the hull's crushed zone), None for a run that does not say
    by_floe = (b["by_floe"] == 1) if "by_floe" in (b.dtype.names or ()) else None
    cap = at_the_cap(run, b, by_floe)
    return {"breaks": int(len(b)), "crack_distance_m": q(b["crack_distance"]) if len(b) else [],
            "overloaded": int(over.sum()),
            "overloaded_no_piece": int((over & (b["pieces"] == 0)).sum()),
            "largest_overload": float(f"{ratio.max():.6g}") if len(b) else None, "overload": OVERLOAD,
            "overload_times_s": [float(f"{v:.6g}") for v in b["time"][over]],
            "underloaded": int((ratio < UNDERLOAD).sum()),
            "smallest_load_ratio": float(f"{ratio.min():.6g}") if len(b) else None, "underload": UNDERLOAD,
            "by_floe": int(by_floe.sum()) if by_floe is not None else None,
            "longest_without_break_s": longest_without_break(run, b),
            "at_cap": dict(zip(("by_floe", "breaks", "steps"), cap)) if cap else None,
            "broken_area_m2": float(f"{b['broken_area'].sum():.6g}") if len(b) else 0.0,
            "crushed_area_m2": float(f"{b['crushed_area'].sum():.6g}") if len(b) else 0.0,
            "pieces": int(len(a)), "piece_area_m2": q(a), "piece_diameter_m": q(d),
            "area_weighted_diameter_m": float(f"{(a * d).sum() / a.sum():.6g}") if a.sum() > 0 else None,
            "quantiles": list(SHEET_QUANTILES)}


# how many of a window's largest loads a record describes step by step (largest_steps)
LARGEST_STEPS = 5


def largest_steps(run, t, x, inside, count=LARGEST_STEPS):
    """The window's `count` largest surge loads, largest first, each with what the contact solve did in its step: its
    iterations, whether an island was handed over at the cap and whether one stayed capped (/diagnostics; None where
    the run does not have them). A rigid contact that locks a piece between the cone and the held sheet has no
    answer short of an impulse the step sets, and its solve runs to the cap: the step's load is the solver's, not the
    ice's."""
    index = np.flatnonzero(inside)
    top = index[np.argsort(x[index])[::-1][:count]]

    def column(name, k):
        path = "/diagnostics/" + name
        return int(run[path][k]) if path in run and len(run[path]) > k else None
    return [{"time_s": float(t[k]), "surge_N": float(x[k]), "iterations": column("solver_iterations", k),
             "handovers": column("handovers", k), "capped": column("solver_capped", k)} for k in top]


# the length of the blocks a record cuts its window into (block_loads): several breaking cycles of level ice
# (a few seconds each) and of a floe's passage (4-9 s in the paper's fields), short enough for a tow's window to
# hold some twenty
BLOCK_S = 10.0


def block_loads(t, x, inside, filtered, block_s=BLOCK_S):
    """The window's surge load cut into whole blocks of block_s seconds from its start (a last part block left
    out): each block's mean, its maximum, and its maximum low-passed at each of LOWPASS_HZ (`filtered`:
    lowpassed(t, x), the whole record filtered), in time order. A tow gives some twenty of each: the spread of a run's own
    blocks, which its one mean and one maximum do not show, is what a change of setting is judged against when
    the starts are few."""
    index = np.flatnonzero(inside)
    if len(index) < 2:
        return None
    dt = (t[-1] - t[0]) / (len(t) - 1)
    per = int(round(block_s / dt))
    count = len(index) // per
    if count < 1:
        return None
    blocks = [index[k * per:(k + 1) * per] for k in range(count)]

    def r(v):
        return float(f"{v:.6g}")
    return {"block_s": block_s, "mean_fx_N": [r(x[b].mean()) for b in blocks],
            "max_fx_N": [r(x[b].max()) for b in blocks],
            "max_lowpass_fx_N": {k: [r(y[b].max()) for b in blocks] for k, y in filtered.items()}}


def make_record(run_dir):
    """The record of a finished run, from its directory: its summary, the Welch spectrum of its
    surge load over the analysis window (up to RECORD_MAX_HZ), its breaks (every field of
    /fracture/events, mode and mechanism also by name), the sizes of the pieces they broke off
    (pieces.summary; kept since 2026-11-27) and, for level ice cut by closed forms, its breaks' crack
    distances and its pieces (sheet_record; kept since 2026-11-30); and the window's largest loads step by step
    with what the contact solve did there (largest_steps; kept since 2026-11-30) and its 10 s blocks (block_loads;
    kept since 2026-11-30)."""
    summary = results.load_summary(os.path.join(run_dir, RUN_FILES["summary"]))
    freq, power, events, window = [], [], [], {}
    run = results.load_run(os.path.join(run_dir, RUN_FILES["h5"]))
    start, end = summary.get("window_start_s"), summary.get("window_end_s")
    if start is not None and end is not None:
        t, x = run["/load/time"], run["/load/surge"]
        sel = (t >= start) & (t <= end)
        f, p = welch_spectrum(t[sel], x[sel])
        keep = f <= RECORD_MAX_HZ
        freq, power = f[keep].tolist(), [float(f"{v:.6g}") for v in p[keep]]
        if sel.any():  # the load a run exceeds 1 % of its window, less driven by one event than the max
            window["p99_fx_N"] = float(np.quantile(x[sel], 0.99))
            filtered = lowpassed(t, x)  # once, for the window's filtered maxima and its blocks'
            window["max_lowpass_fx_N"] = lowpass_maxima(t, x, sel, filtered)
            window["largest_steps"] = largest_steps(run, t, x, sel)
            window["blocks"] = block_loads(t, x, sel, filtered)  # None for a window shorter than a block
    ev = run.events
    fields = [k for k in (ev.dtype.names or ()) if k not in ("mode_name", "mechanism_name")]
    for row in ev:
        e = {k: (int(row[k]) if np.issubdtype(ev.dtype[k], np.integer) else float(f"{row[k]:.9g}")) for k in fields}
        e["mode_name"] = str(row["mode_name"])
        if "mechanism" in e:
            e["mechanism_name"] = str(row["mechanism_name"])
        events.append(e)
    record = {"summary": summary, "spectrum": {"frequency_hz": freq, "power_N2_per_hz": power},
              "fracture_events": events, "window": window, "pieces": pieces.summary(*pieces.piece_areas(run))}
    sheet = sheet_record(run)
    if sheet is not None:
        record["sheet"] = sheet
    return record


# what a kept record's window must hold to stand for its run when the run's directory is there (load_record);
# an older record is made again from it
RECORD_WINDOW_KEYS = {"largest_steps", "blocks"}

# what says that a run directory holds the run a kept record was made from (load_record)
SAME_RUN_KEYS = ("steps", "mean_fx_N", "max_fx_N", "breaks")


def load_record(run, out):
    """The record of a finished run: the kept file when the sweep keeps records and it is at
    least as new as the run's summary (and has the window's quantiles and filtered maxima, kept since
    2026-11-26, its largest steps, its blocks and a sheet's overloads, kept since 2026-11-30, and its breaks below
    their load, since 2026-12-01); else made from the
    run's directory (reading its HDF5 file) and kept. A kept record is never replaced by a run directory holding
    another run (a figure's rerun by another build: its SAME_RUN_KEYS differ): the record stays, and a warning names
    the directory."""
    from . import execute
    run_dir = os.path.join(out, run.path)
    summary = os.path.join(run_dir, RUN_FILES["summary"])
    existing = None  # the kept record, read once
    if run.record_file and os.path.isfile(run.record_file):
        with open(run.record_file) as f:
            existing = json.load(f)
    # it stands for the run if it is at least as new as the run's summary
    kept = existing if existing is not None and (
        not os.path.isfile(summary) or os.path.getmtime(run.record_file) >= os.path.getmtime(summary)) else None
    finished_here = execute.finished_here(run, out)
    if finished_here and (kept is None or not RECORD_WINDOW_KEYS <= set(kept.get("window", {}))
                          or ("sheet" in kept and not {"overload_times_s", "underloaded"} <= set(kept["sheet"]))):
        if existing is not None:
            here = results.load_summary(summary)
            was = existing["summary"]
            if any(was.get(k) != here.get(k) for k in SAME_RUN_KEYS):
                moved = ", ".join(f"{k} {was.get(k)} -> {here.get(k)}" for k in SAME_RUN_KEYS)
                print(f"warning: {run_dir} holds another run than its record {run.record_file} ({moved}; "
                      "another build?): the record is kept", file=sys.stderr)
                return existing
        record = make_record(run_dir)
        if run.record_file:
            os.makedirs(os.path.dirname(run.record_file), exist_ok=True)
            tmp = run.record_file + ".tmp"
            with open(tmp, "w") as f:
                json.dump(record, f, separators=(",", ":"))
            os.replace(tmp, run.record_file)  # never a half-written record
        return record
    if existing is not None:
        return existing
    with open(run.record_file) as f:  # none kept: the error names the missing file
        return json.load(f)


NO_BUILD = "not recorded"  # a record made before summaries named their build (2026-11-28)


def build_label(summary):
    """The build that made a run, from its summary's build: the commit's first 12 digits, with
    " (modified)" when the tracked sources differed from it; NO_BUILD for older records."""
    b = summary.get("build")
    if not b:
        return NO_BUILD
    return b["commit"][:12] + (" (modified)" if b.get("modified") else "")


def mixed_builds(groups):
    """{config: {build label: runs}} of the configurations whose records were made by more than
    one build (groups as aggregate() takes them, run_record()s): their seeds are samples of
    different dynamics if a change between the builds moved results (CHANGELOG.md says which)."""
    counts = {config: collections.Counter(r["build"] for r in records) for config, (_, _, records) in groups.items()}
    return {config: dict(c) for config, c in counts.items() if len(c) > 1}


def run_record(run, out):
    """What aggregation needs from one finished run (from its record)."""
    record = load_record(run, out)
    s = record["summary"]
    spectrum = (np.asarray(record["spectrum"]["frequency_hz"], dtype=float),
                np.asarray(record["spectrum"]["power_N2_per_hz"], dtype=float))
    return {"mean_fx_N": s.get("mean_fx_N"), "max_fx_N": s.get("max_fx_N"),
            "peak_interval_s": s.get("peak_interval_s"), "spectrum": spectrum,
            "spectral_peak_hz": peak_frequency(*spectrum) if len(spectrum[0]) else float("nan"),
            "breaks_by_mode": {mode_key(k): v for k, v in s.get("breaks_by_mode", {}).items()},
            "breaks_by_mechanism": {mode_key(k): v for k, v in s.get("breaks_by_mechanism", {}).items()},
            "realtime_factor": s.get("realtime_factor"), "wall_time_s": s.get("wall_time_s"),
            "cpu_time_s": s.get("cpu_time_s"), "build": build_label(s)}


def _finite(values):
    return [v for v in values if v is not None and math.isfinite(v)]


def aggregate(groups):
    """groups: {config: (scenario, labels: the variant and grid values as ((key, value), ...),
    [run records])} -> (list of row dicts, list of ensemble spectra (f, p), one per row)."""
    rows, spectra = [], []
    everything = [r for _, _, records in groups.values() for r in records]
    modes, mechanisms = break_names(everything, "breaks_by_mode"), break_names(everything, "breaks_by_mechanism")
    for config, (scenario, labels, records) in groups.items():
        row = {"configuration": config, "scenario": scenario}
        for k, v in labels:
            row[k] = v
        row["seeds"] = len(records)
        for key in ("mean_fx_N", "max_fx_N"):
            m, half = mean_ci(_finite(r[key] for r in records))
            row[key] = m
            row[key + "_ci95"] = half
        maxima = _finite(r["max_fx_N"] for r in records)
        row["max_fx_gumbel_u_N"], row["max_fx_gumbel_beta_N"] = gumbel_fit(maxima)
        # coefficient of variation of the seed maxima: seeds for a +-eps mean of maxima at 95 %
        # are (1.96 CoV / eps)^2 (docs/model/validation_targets.md §7)
        row["max_fx_cov"] = (float(np.std(maxima, ddof=1) / np.mean(maxima))
                             if len(maxima) >= 2 and np.mean(maxima) > 0 else float("nan"))
        pi = _finite(r["peak_interval_s"] for r in records)
        row["peak_interval_s"] = float(np.mean(pi)) if pi else float("nan")
        # from the ensemble spectrum when the runs carry theirs; else the mean of the seeds' peaks
        f, p = ensemble_spectrum(r["spectrum"] for r in records if "spectrum" in r)
        if len(f):
            row["spectral_peak_hz"] = peak_frequency(f, p)
        else:
            sp = _finite(r.get("spectral_peak_hz") for r in records)
            row["spectral_peak_hz"] = float(np.mean(sp)) if sp else float("nan")
        hz = row["spectral_peak_hz"]
        row["spectral_peak_period_s"] = 1.0 / hz if math.isfinite(hz) and hz > 0 else float("nan")
        for mode in modes:
            row["breaks_" + mode] = int(sum(r["breaks_by_mode"].get(mode, 0) for r in records))
        for mechanism in mechanisms:
            row["breaks_" + mechanism] = int(sum(r.get("breaks_by_mechanism", {}).get(mechanism, 0) for r in records))
        rtf = _finite(r["realtime_factor"] for r in records)
        row["realtime_factor"] = float(np.mean(rtf)) if rtf else float("nan")
        wall = _finite(r.get("wall_time_s") for r in records)
        row["run_wall_time_s"] = float(np.sum(wall)) if wall else float("nan")
        cpu = _finite(r.get("cpu_time_s") for r in records)
        row["run_cpu_time_s"] = float(np.sum(cpu)) if cpu else float("nan")
        rows.append(row)
        spectra.append((f, p))
    return rows, spectra


def write_csv(rows, path):
    keys = list(dict.fromkeys(k for r in rows for k in r))
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)


def write_hdf5(rows, path, spectra=()):
    """One compound dataset /configurations; strings as UTF-8, numbers as f8 (grid values too);
    each row's ensemble spectrum as /spectra/<row index>/{frequency (Hz), power (N^2/Hz)}."""
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
                                  "Gumbel u and beta of the seed maxima (N), breaks by mode summed over seeds, "
                                  "summed run wall time (s)")
        for i, (f, p) in enumerate(spectra):
            if len(f):
                g = h.create_group(f"spectra/{i}")
                g.attrs["configuration"] = rows[i]["configuration"]
                g.create_dataset("frequency", data=f).attrs["units"] = "Hz"
                g.create_dataset("power", data=p).attrs["units"] = "N^2/Hz"


def read_spectra(path):
    """{row index: (frequency Hz, power N^2/Hz)} of a results.h5 that write_hdf5 wrote."""
    with h5py.File(path, "r") as h:
        return {int(i): (g["frequency"][:], g["power"][:]) for i, g in h.get("spectra", {}).items()}
