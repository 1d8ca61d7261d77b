"""The analytic level tow over ice thickness and tow speed, for docs/model/level_ice.md (scripts/level_ice_report
--thickness-speed SWEEP): each finished tow of SWEEP (sweeps/studies/level_ice_thickness_speed.toml: frictions as
scenarios, speeds as variants, ice.thickness as its grid) beside ISO 19906's and Ralston's loads for its own cone,
ice and friction, a table and a figure of the mean, the 5 Hz low-passed maximum and the mean of the 10 s blocks'
maxima (with its interval over the tow's blocks, stats/block_change.py) against thickness, one line per speed. One
start per point: the analytic ensemble says how far one start scatters."""
import dataclasses
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ..runs import spec  # noqa: E402
from ..sweeps import aggregate as agg, execute  # noqa: E402
from ..reports.report_tables import fmt  # noqa: E402
from ..stats import block_change  # noqa: E402
from . import level_ice_analytic as la, level_ice_blocks  # noqa: E402

SPEED = "structure.speed"


@dataclasses.dataclass
class Tow:
    scenario: str
    speed: float      # m/s
    thickness: float  # m
    record: dict      # aggregate.load_record's
    loads: dict       # `icedem cone-load` for the run, or None
    why: str          # why there are no design loads, or None
    law: str          # contact.model


def points(sweep, out, design_loads):
    """The sweep's finished tows (Tow), by scenario, speed, thickness."""
    _, runs = spec.load(sweep)
    found = []
    for r in runs:
        if execute.status(r, out).state != "done":
            continue
        loads, why = design_loads(r)
        found.append(Tow(r.scenario, float(spec.run_value(r, SPEED)), la.thickness(r), agg.load_record(r, out),
                         loads, why, spec.run_value(r, "contact.model")))
    return sorted(found, key=lambda t: (t.scenario, t.speed or 0.0, t.thickness or 0.0))


def block_max(record):
    """(mean, 95 % half-width) of the tow's 10 s blocks' maxima (aggregate.block_loads), or None without blocks."""
    blocks = level_ice_blocks.record_blocks(record, "max_fx_N", None)
    if not blocks:
        return None
    m, h, _ = block_change.mean_ci([blocks])
    return m, h


def figure(found, path):
    """The mean, the 5 Hz low-passed maximum and the 10 s blocks' mean maximum (its 95 % interval as a bar)
    against thickness, a line per speed, per friction (rows), ISO 19906's and Ralston's loads over the same
    thicknesses dashed and dotted."""
    scenarios = sorted({t.scenario for t in found})
    fig, axes = plt.subplots(len(scenarios), 3, figsize=(14, 3.6 * len(scenarios)), squeeze=False)
    panels = (("mean", lambda rec: (la._value(rec, "mean_fx_N"), None)),
              ("max 5 Hz", lambda rec: (la._value(rec, la.LOWPASS), None)),
              ("10 s blocks' mean max", lambda rec: block_max(rec) or (None, None)))
    for row, scenario in zip(axes, scenarios):
        mine = [t for t in found if t.scenario == scenario]
        for ax, (label, value) in zip(row, panels):
            for speed in sorted({t.speed for t in mine}):
                line = [(t.thickness, *value(t.record)) for t in mine if t.speed == speed and value(t.record)[0]]
                if line:
                    h, v, e = zip(*line)
                    bars = None if all(x is None for x in e) else [x if x == x and x is not None else 0 for x in e]
                    ax.errorbar(h, v, yerr=bars, fmt="o-", capsize=3, label=f"{speed:g} m/s")
            design = sorted({(t.thickness, t.loads["total_N"], t.loads["ralston_total_N"]) for t in mine if t.loads})
            if design:
                h = [d[0] for d in design]
                ax.plot(h, [d[1] for d in design], "k--", label="ISO 19906")
                ax.plot(h, [d[2] for d in design], "k:", label="Ralston")
            mu = next((t.loads["friction"] for t in mine if t.loads), None)
            ax.set_title(f"{scenario}" + (f" (mu {mu:g})" if mu is not None else "") + f": {label}")
            ax.set_xlabel("ice thickness, m")
            ax.set_ylabel("surge load, N")
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def section(sweep, out, design_loads, figure_path=None):
    """The page's lines on the tows of `sweep` (runs in `out`); design_loads(run) as level_ice_analytic's;
    with `figure_path`, the figure is written there and the section shows it (by its name: beside the page)."""
    L = ["### Thickness and speed", "",
         f"Runs of `{os.path.relpath(sweep, spec.ROOT)}` finished so far: the analytic tow over ice thickness and "
         "tow speed, each over the same 19.6 m of sheet, the model ice's strength and modulus the paper's; one "
         "start each (the ensemble above says how far one start scatters). Loads in N, surge, over the analysis "
         "window, beside ISO 19906 and Ralston for the run's own ice and friction (neither depends on speed). x*: "
         "the median crack distance; d_w: the pieces' area-weighted diameter; both against the run's "
         "characteristic length l_c. Block max: the mean of the maxima of the tow's 10 s blocks with its 95 % "
         "interval over them (their correlation taken in; the section above), the peak a tow reaches every 10 s, "
         "steadier than its one maximum; a faster tow crosses more ice in a block.", ""]
    found = points(sweep, out, design_loads)
    if not found:
        return L + ["No finished run yet.", ""]
    L += [f"Contact law: {', '.join(sorted({t.law for t in found}))} (contact.model).", "",
          "| run | mu | speed m/s | h m | mean | p99 | max | max 5 Hz | block max | ISO 19906 | Ralston | mean / ISO | "
          "max 5 Hz / ISO | block max / ISO | breaks | l_c m | x* / l_c | d_w / l_c | real time (CPU) |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for t in found:
        scenario, speed, h, rec, loads, why = t.scenario, t.speed, t.thickness, t.record, t.loads, t.why
        s = rec["summary"]
        mean, p99, mx, m5 = (la._value(rec, k) for k in la.CRITERIA.values())
        iso = loads["total_N"] if loads else None
        lc = loads["characteristic_length_m"] if loads else None
        sheet = rec.get("sheet") or {}
        x = d = None
        if sheet.get("crack_distance_m"):
            x = sheet["crack_distance_m"][sheet["quantiles"].index(0.5)]
        if sheet.get("area_weighted_diameter_m"):
            d = sheet["area_weighted_diameter_m"]
        cpu = s.get("cpu_time_s")
        mu = f"{loads['friction']:g}" if loads else "n/a"
        bm = block_max(rec)
        bm_text = "n/a" if bm is None else f"{bm[0]:.1f}" + (f" ± {bm[1]:.1f}" if bm[1] == bm[1] else "")
        L.append(f"| {scenario} | {mu} | "
                 f"{fmt(speed, digits=3)} | {fmt(h, digits=3)} | {fmt(mean)} | {fmt(p99)} | {fmt(mx)} | {fmt(m5)} | "
                 f"{bm_text} | "
                 f"{fmt(iso) if loads else f'n/a ({why})'} | {fmt(loads['ralston_total_N']) if loads else 'n/a'} | "
                 f"{fmt(mean / iso if mean and iso else None, digits=2)} | "
                 f"{fmt(m5 / iso if m5 and iso else None, digits=2)} | "
                 f"{fmt(bm[0] / iso if bm and iso else None, digits=2)} | {s.get('breaks', 'n/a')} | "
                 f"{fmt(lc, digits=3)} | {fmt(x / lc if x and lc else None, digits=2)} | "
                 f"{fmt(d / lc if d and lc else None, digits=2)} | "
                 f"{fmt(s['sim_time_s'] / cpu if cpu else None, digits=2)} |")
    if figure_path:
        figure(found, figure_path)
        L += ["", f"![mean, 5 Hz maximum and 10 s blocks' mean maximum against thickness, a line per speed]"
              f"({os.path.basename(figure_path)})"]
    return L + [""]
