"""The report's comparison of fracture models on the paper's larger floes (tools/icedem_tools/reports/report.py):
rigid floes, rigid floes that split analytically (fracture.mode = "analytic"), and the lattices of
0.20 m and 0.15 m square elements, at the ice-structure friction of the paper's Fig. 18 and both its
ice-ice frictions, over the seeds every model with runs has finished; beside the tank's largest load
and the ISO 19906 load of level ice on the cone, in one table and one figure. The lattices of
hexagonal elements are an element shape, not another model of the ice: each is set against the
squares of its size on the seeds both have finished, seed by seed, so that a shape still running
does not narrow the models' table to its few seeds."""
import os

import numpy as np

from ..sweeps import aggregate as agg, execute
from ..runs import spec
from ..stats.intervals import mean_ci
from .paper_findings import TARGETS
from .report_breakage import mechanism_names, mechanism_table
from .report_sweeps import convergence_section
from .report_tables import FII, FIS, run_records

# the models, in the order of the table: grid scenario (or the models sweep's) and label
MODELS = (("large_rigid", "rigid, no fracture"),
          ("large_analytic", "rigid, splitting analytically"),
          ("large_breakable_020", "lattice, 0.20 m elements"),
          ("large_breakable_015", "lattice, 0.15 m elements"))
# element shapes against the squares of their size: (shape's model, its label, the squares' model)
SHAPES = (("large_hexagon_020", "lattice, 0.20 m hexagons", "large_breakable_020"),
          ("large_hexagon_015", "lattice, 0.15 m hexagons", "large_breakable_015"))
# the numbers the shapes' table differences seed by seed (per_run()'s keys, in the table's order)
PAIRED = ("mean_fx_N", "p99_fx_N", "max_fx_N", "breaks")
FIS_VALUE = 0.3           # the paper's Fig. 18
FII_VALUES = (0.3, 0.7)   # its two states of failure
ISO_SCENARIO = "scenarios/paper/large_floes_rigid.toml"  # the paper's cone and ice


def _friction(run, key):
    return dict(run.labels).get(key)


def model_runs(records, scenario, fii):
    """{seed: record} of a model's finished runs at (f_ii, FIS_VALUE)."""
    return {r.seed: rec for r, rec in records.get(scenario, [])
            if _friction(r, FII) == fii and _friction(r, FIS) == FIS_VALUE}


def per_run(rec):
    """One run's numbers for the tables (p99 None for a record kept before the window's p99 was)."""
    s = rec["summary"]
    # a lattice's floe breaks in two when a line of 3-4 joints has; the floes that broke at all
    # compare the models on one footing
    return {"mean_fx_N": s["mean_fx_N"], "max_fx_N": s["max_fx_N"], "breaks": s.get("breaks", 0),
            "floes": len({e["floe"] for e in rec.get("fracture_events", [])}),
            "p99_fx_N": rec.get("window", {}).get("p99_fx_N")}


def stats(recs):
    """The table's numbers over the runs `recs` (records of finished runs; aggregate.ensemble):
    (mean, ci) of the mean, p99 and max, the largest max, breaks and floes broken per run, and
    CPU s per run."""
    e = agg.ensemble(recs, per_run, summary=lambda rec: rec["summary"], counts=lambda rec: True)
    out = {k: e.get(k) for k in ("mean_fx_N", "max_fx_N", "p99_fx_N")}  # p99: None unless every run has one
    out["largest"] = float(e["runs"]["max_fx_N"].max())
    out["breaks"] = e["breaks"][0]
    out["floes"] = e["floes"][0]
    out["cpu"] = e["cpu"]
    # how far past its capacity a break's load went within the step of the break (1: resolved)
    ratios = [ev["ratio"] for rec in recs for ev in rec.get("fracture_events", []) if "ratio" in ev]
    out["ratio"] = (float(np.median(ratios)), float(np.percentile(ratios, 90))) if ratios else None
    return out


def comparison(records):
    """{f_ii: (the seeds every model with runs finished, {model: stats() over them, or None})}.
    A model without any run at a friction (one whose sweep has not started) is left out of the
    seeds' intersection there, so that a new model does not empty the table until it runs."""
    out = {}
    for fii in FII_VALUES:
        by_model = {m: model_runs(records, m[0], fii) for m in MODELS}
        started = [set(v) for v in by_model.values() if v]
        common = sorted(set.intersection(*started)) if started else []
        out[fii] = (common, {m: stats([by_model[m][s] for s in common]) if common and by_model[m] else None
                             for m in MODELS})
    return out


def shape_comparison(records):
    """{f_ii: {shape: None (no seed both have finished) or (seeds, shape's stats(), squares' stats(),
    {key: (mean difference shape - squares, its 95 % half-width; nan for one seed; None without
    the number in every run)})}}: each element shape against the squares of its size on the same
    layouts, so the layout's scatter, which both share, drops out of the difference."""
    out = {}
    for fii in FII_VALUES:
        out[fii] = {}
        for shape, _, squares in SHAPES:
            a, b = model_runs(records, shape, fii), model_runs(records, squares, fii)
            seeds = sorted(set(a) & set(b))
            if not seeds:
                out[fii][shape] = None
                continue
            diffs = {}
            for key in PAIRED:
                pairs = [(per_run(a[s])[key], per_run(b[s])[key]) for s in seeds]
                ok = all(x is not None and y is not None for x, y in pairs)
                diffs[key] = mean_ci([x - y for x, y in pairs]) if ok else None
            out[fii][shape] = (seeds, stats([a[s] for s in seeds]), stats([b[s] for s in seeds]), diffs)
    return out


def shape_lines(records):
    """The Markdown of the element shapes against the squares (shape_comparison)."""
    got = shape_comparison(records)
    if not any(v for t in got.values() for v in t.values()):
        return []
    L = ["### Hexagonal elements against squares", "",
         "The lattices of hexagonal elements (`fracture.element_shape = \"hexagon\"`, the models sweep's; "
         "0.20 m and 0.15 m across flats, their calibrated strength, docs/model/breakage.md) against the "
         "squares of the same size, on the seeds both have finished: the same layouts, so the difference "
         "is taken seed by seed (mean difference ± the half-width of its 95 % interval, none for one seed). "
         "A shape whose sweep is still running is compared on the seeds it has.", "",
         "| f_ii | lattice | seeds | mean, N | p99, N | mean of maxima, N | breaks / run | floes broken / run | "
         "CPU s / run |", "|---|---|---|---|---|---|---|---|---|"]
    for fii, shapes in got.items():
        for shape, label, squares in SHAPES:
            if shapes[shape] is None:
                L.append(f"| {fii} | {label} | 0 | n/a | n/a | n/a | n/a | n/a | n/a |")
                continue
            seeds, st_shape, st_squares, diffs = shapes[shape]
            seed_text = ", ".join(str(s) for s in seeds)
            for lab, st in ((label, st_shape), (dict(MODELS)[squares], st_squares)):
                L.append(f"| {fii} | {lab} | {seed_text} | {_ci(st['mean_fx_N'])} | {_ci(st['p99_fx_N'])} | "
                         f"{_ci(st['max_fx_N'])} | {st['breaks']:.1f} | {st['floes']:.1f} | {st['cpu']:.0f} |")
            cells = ["n/a" if diffs[key] is None else f"{diffs[key][0]:+.1f}"
                     + (f" ± {diffs[key][1]:.1f}" if np.isfinite(diffs[key][1]) else " (one seed)") for key in PAIRED]
            L.append(f"| {fii} | hexagons - squares | {len(seeds)} | {cells[0]} | {cells[1]} | {cells[2]} | "
                     f"{cells[3]} | | |")
    return L + [""]


def iso19906(icedem):
    """(the ISO 19906 terms at FIS_VALUE from `icedem cone-load --json`, None) or (None, why
    not): the report says why rather than dropping the row."""
    return execute.cone_load(icedem, os.path.join(spec.ROOT, ISO_SCENARIO), [f"friction.ice_structure={FIS_VALUE}"])


def _ci(pair, digits=1):
    if pair is None:
        return "n/a"
    m, h = pair
    return f"{m:.{digits}f}" + (f" ± {h:.{digits}f}" if np.isfinite(h) else "")


def figure(table, iso, tank_max, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(FII_VALUES), figsize=(11, 4), sharey=True)
    for ax, fii in zip(np.atleast_1d(axes), FII_VALUES):
        rows = [(label, st) for (scenario, label), st in table[fii].items() if st]
        x = np.arange(len(rows))
        for key, name, marker, dx in (("mean_fx_N", "mean", "o", -0.15), ("p99_fx_N", "p99", "s", 0.0),
                                      ("max_fx_N", "mean of maxima", "^", 0.15)):
            pts = [(i, st[key]) for i, (_, st) in enumerate(rows) if st.get(key)]
            if pts:
                ax.errorbar([i + dx for i, _ in pts], [m for _, (m, _) in pts],
                            yerr=[h if np.isfinite(h) else 0 for _, (_, h) in pts], fmt=marker, capsize=3, label=name)
        ax.axhline(tank_max, color="k", ls="--", lw=1, label=f"tank, largest ({tank_max:.0f} N)")
        if iso:
            ax.axhline(iso["total_N"], color="tab:red", ls=":", lw=1, label=f"ISO 19906, total ({iso['total_N']:.0f} N)")
            ax.axhline(iso["breaking_only_N"], color="tab:red", ls="-.", lw=1,
                       label=f"ISO 19906, breaking alone ({iso['breaking_only_N']:.0f} N)")
        ax.set_xticks(x)
        ax.set_xticklabels([label.replace(", ", ",\n") for label, _ in rows], fontsize=8)
        ax.set_title(f"f_ii {fii}, f_is {FIS_VALUE}", fontsize=9)
        ax.grid(alpha=0.3, axis="y")
        ax.set_ylim(bottom=0)  # a load's interval over few seeds may reach below 0
    np.atleast_1d(axes)[0].set_ylabel("surge load, N")
    np.atleast_1d(axes)[-1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def fracture_models_section(models_sweep, grid_records, figs, report, icedem=None, convergence=None):
    """The section's Markdown lines, and its figure in `figs`. grid_records: the grid's
    run_records(); the analytic model's come from `models_sweep`; `convergence`: the analytic
    model's sweep at other numerics (sweeps/paper_fracture_models_convergence.toml), if any."""
    name, runs = spec.load(models_sweep)
    out = os.path.join(spec.ROOT, "sweeps", name)
    records = dict(grid_records)
    records.update(run_records(runs, out))
    tank_max = TARGETS["large_breakable_max"]["value"]
    iso, iso_missing = iso19906(icedem)
    L = ["## Fracture models compared", "",
         f"The paper's larger floes (0.6 m) at its Fig. 18's frictions (f_is {FIS_VALUE}, f_ii "
         f"{' and '.join(str(v) for v in FII_VALUES)}) with these models of the ice: rigid floes (the grid's "
         "`large_rigid`), rigid floes that split in two when the cone's load normal to a floe reaches a floating "
         "beam's breaking load (`fracture.mode = \"analytic\"`, `sweeps/paper_fracture_models.toml`; "
         "docs/model/breakage.md) and the lattices of 0.20 m and 0.15 m square elements (the grid's; the "
         "hexagonal elements of the same sizes are set against them below). "
         "Each over the seeds every model with runs has finished, the same layouts (a model not yet run shows "
         "n/a); loads are the surge load over each run's analysis "
         "window, the mean over seeds ± the half-width of the 95 % interval. p99 is the load a run exceeds "
         "1 % of its window. Breaks are joints broken (lattices) or splits (analytic, a piece splitting again "
         "counts again) per run; floes broken counts each layout floe that broke at all once. A break's "
         "load over its capacity says how far the load went past the capacity within the step of the "
         "break: an elastic lattice's joints load up over several steps, a rigid floe's contact load can "
         "jump within one (docs/model/breakage.md). CPU "
         "is one run's, on this machine beside other runs (ratios within a column's runs only).", ""]
    compared = comparison(records)
    table = {fii: models for fii, (_, models) in compared.items()}
    for fii, (common, models) in compared.items():
        L += [f"f_ii {fii}, f_is {FIS_VALUE}: {len(common)} seed(s) finished by every model with runs"
              + (f" ({', '.join(str(s) for s in common)})" if common else "") + ".", "",
              "| model | mean, N | p99, N | mean of maxima, N | largest, N | breaks / run | floes broken / run | "
              "break's load / capacity, median (p90) | CPU s / run |", "|---|---|---|---|---|---|---|---|---|"]
        for m in MODELS:
            st = models[m]
            if st is None:
                L.append(f"| {m[1]} | n/a | n/a | n/a | n/a | n/a | n/a | n/a | n/a |")
                continue
            L.append(f"| {m[1]} | {_ci(st['mean_fx_N'])} | {_ci(st['p99_fx_N'])} | {_ci(st['max_fx_N'])} | "
                     f"{st['largest']:.1f} | {st['breaks']:.1f} | {st['floes']:.1f} | "
                     + (f"{st['ratio'][0]:.2f} ({st['ratio'][1]:.2f})" if st["ratio"] else "") + f" | {st['cpu']:.0f} |")
        L += [f"| tank (NMRI, f_is and f_ii as measured) | not given | not given | about {tank_max:.0f} "
              "(the largest) | | | | | |"]
        if not iso:
            L += [f"| ISO 19906, level ice | not available: {iso_missing} | | | | | | | |"]
        else:
            L += [f"| ISO 19906, level ice (`icedem cone-load`, mu {FIS_VALUE}) | | | breaking "
                  f"{iso['breaking_N']:.1f} + ride-up {iso['ride_N']:.1f} + turning {iso['turning_N']:.1f} = "
                  f"{iso['total_N']:.1f} (breaking alone {iso['breaking_only_N']:.1f}; no rubble pile, so its "
                  "push and lift terms are 0) | | | | | |"]
        L.append("")
    if not any(st for t in table.values() for st in t.values()):
        L += ["No seed has finished for every model with runs yet.", ""]
        return L + (convergence_section(convergence, {}, title="### Convergence of the analytic model")
                    if convergence else [])
    os.makedirs(figs, exist_ok=True)
    path = os.path.join(figs, "fracture_models.png")
    figure(table, iso, tank_max, path)
    L += [f"![fracture models](" + os.path.relpath(path, os.path.dirname(report)) + ")", "",
          "ISO 19906's load is for level ice, a continuous sheet failing in bending on the cone; the "
          "floes here are a managed field of 75 % concentration, which the standard does not cover. It is "
          "the designer's check, not a target: loads in managed ice are usually below those of the level ice "
          "it assumes.", ""]
    L += shape_lines(records)
    if "large_analytic" in records:
        # what the analytic model's split floes were doing, classified as the lattices' breaks are
        # ("Breakage mechanisms" above), and whether Fig. 18's shift appears in it
        L += ["### What the splitting floes were doing", "",
              "Each split is classified as a lattice's break is (\"Breakage mechanisms\" above), from the "
              "contacts of the one floe that split; the analytic model's runs at both frictions, shares with "
              "95 % intervals over runs.", ""]
        L += mechanism_table(records, "large_analytic", mechanism_names(records), np.random.default_rng(28))
    if convergence:
        L += convergence_section(convergence, {}, title="### Convergence of the analytic model")
    return L
