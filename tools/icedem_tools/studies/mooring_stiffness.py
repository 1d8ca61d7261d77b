"""The moored cone's stiffness study: the paper's small floes (f_ii 0.5, f_is 0.2) against the cone moored
to the carriage by the linear mooring, its surge stiffness over two decades and beyond
(sweeps/studies/mooring_stiffness.toml, 10 seeds each), beside the fixed cone, which is the paper grid's
small_rigid runs of the same seeds (sweeps/paper_grid.toml). Made from the committed records of both:

    scripts/mooring_stiffness [--report docs/model/mooring.md] [--figure docs/model/mooring_stiffness.png]

writes the page's table (per stiffness: the ice load's mean and max, the mooring force's mean and max, the
surge offset's mean and standard deviation, each over the seeds with its 95 % interval; the ice load's
mean and max against the fixed cone's, paired seed by seed by the project's one rule, stats/verdict.py;
the family's multiplicity statement), the figure, and the page's spans ("mooring | ..."): the stiffness
from which on the moored cone's ice loads are the fixed cone's, and what the changes are there."""
import argparse
import os
import re
import sys

import numpy as np

from ..runs import output_guard, spec
from ..runs.spec import ROOT
from ..reports import spans
from ..reports.flow_table import GRID_SWEEP, summaries
from ..reports.report_tables import at_reference
from ..stats import verdict
from ..stats.intervals import mean_ci

STUDY = os.path.join(ROOT, "sweeps", "studies", "mooring_stiffness.toml")
PAGE = os.path.join(ROOT, "docs", "model", "mooring.md")
BEGIN, END = "<!-- mooring stiffness table: scripts/mooring_stiffness writes below -->", "<!-- end of the mooring stiffness table -->"
# (name, the summary's value, its unit's scale, digits): the columns over the seeds
MEASURES = [("ice mean", lambda s: s["mean_fx_N"], 1, 2), ("ice max", lambda s: s["max_fx_N"], 1, 1),
            ("mooring mean", lambda s: s["mooring"]["mean_N"], 1, 2), ("mooring max", lambda s: s["mooring"]["max_N"], 1, 1),
            ("offset mean", lambda s: s["mooring"]["offset_mean_m"], 1e3, 2),
            ("offset std", lambda s: s["mooring"]["offset_std_m"], 1e3, 2)]
CRITERIA = [("mean", "mean_fx_N"), ("max", "max_fx_N")]  # the ice load against the fixed cone's


def stiffness(run):
    """The surge stiffness (N/m) a run's variant sets (its mooring.stiffness's first component)."""
    for s in run.sets:
        m = re.match(r"mooring\.stiffness=\[\s*([^,\]]+)", s)
        if m:
            return float(m.group(1))
    raise spec.SweepError(f"{STUDY}: variant {run.variant!r} sets no mooring.stiffness")


def facts(study=STUDY):
    """The study's finished runs per stiffness and the fixed cone's, their means and the changes of the ice
    load against the fixed cone's over the seeds both ran. Raises spec.SweepError for a sweep file that
    cannot be read."""
    _, runs = spec.load(study)
    _, grid = spec.load(GRID_SWEEP)
    fixed = summaries([r for r in grid if r.scenario == "small_rigid" and at_reference(r)])
    ks = sorted({stiffness(r) for r in runs})
    moored = {k: summaries([r for r in runs if stiffness(r) == k]) for k in ks}
    f = {"ks": ks, "runs": moored, "fixed": fixed, "means": {}, "changes": {}, "planned": len(runs)}
    for k in ks:
        for name, value, scale, _ in MEASURES:
            f["means"][(k, name)] = mean_ci([scale * value(s) for s in moored[k].values()])
        seeds = sorted(set(moored[k]) & set(fixed))
        for name, key in CRITERIA:
            if len(seeds) < 2:
                continue
            a, b = [moored[k][x][key] for x in seeds], [fixed[x][key] for x in seeds]
            f["changes"][(k, name)] = verdict.judged_change(a, b)
    for name, key in CRITERIA:
        f["means"][("fixed", "ice " + name)] = mean_ci([s[key] for s in fixed.values()])
    f["limit"] = fixed_limit(f)
    return f


def fixed_limit(f):
    """The least stiffness from which on, at it and at every stiffer one, neither the ice load's mean nor its
    max moves against the fixed cone's (both unresolved at 95 %); None if the stiffest's does, or the study
    has no changes yet."""
    limit = None
    for k in reversed(f["ks"]):
        c = [f["changes"].get((k, name)) for name, _ in CRITERIA]
        if None in c or any(x[2] == "moves" for x in c):
            break
        limit = k
    return limit


def k_text(k):
    return f"{k:,.0f}" if k >= 1000 else f"{k:g}"


def table(f):
    L = ["| surge stiffness N/m | seeds | ice load mean N | ice load max N | mooring force mean N | mooring force max N | "
         "surge offset mean mm | offset std mm | ice mean against the fixed cone | ice max against it |",
         "|---|---|---|---|---|---|---|---|---|---|"]
    for k in f["ks"]:
        cells = [f"{m:.{dg}f} ± {h:.{dg}f}" for m, h, dg in
                 ((*f["means"][(k, name)], dg) for name, _, _, dg in MEASURES)]
        ch = [f["changes"].get((k, name)) for name, _ in CRITERIA]
        L.append(f"| {k_text(k)} | {len(f['runs'][k])} | " + " | ".join(cells) + " | "
                 + " | ".join(verdict.change_text(c[:3]) if c else "" for c in ch) + " |")
    m, x = f["means"][("fixed", "ice mean")], f["means"][("fixed", "ice max")]
    L.append(f"| fixed (the paper grid's small_rigid) | {len(f['fixed'])} | {m[0]:.2f} ± {m[1]:.2f} | "
             f"{x[0]:.1f} ± {x[1]:.1f} | | | | | | |")
    return L


def multiplicity(f):
    return verdict.family_text(f["changes"], lambda k: f"{k_text(k[0])} N/m {k[1]}")


def limit_text(f):
    k = f["limit"]
    stiffest = len(set(f["runs"][f["ks"][-1]]) & set(f["fixed"]))
    if k is None and stiffest < 2:
        return f"not known yet (the stiffest mooring has {stiffest} of its seeds paired with the fixed cone's)"
    if k is None:
        return "no stiffness of the study: the stiffest's ice load still moves against the fixed cone's"
    return f"{k_text(k)} N/m"


def resolver(f):
    def resolve(key):
        parts = [x.strip() for x in key.split("|")]
        if parts[0] != "mooring":
            raise KeyError(key)
        if parts[1:] == ["limit"]:
            return limit_text(f)
        if parts[1:] == ["multiplicity"]:
            return multiplicity(f)
        if parts[1:] == ["runs"]:
            return f"{sum(len(r) for r in f['runs'].values())} of its {f['planned']} runs"
        where = f["ks"][-1] if parts[1] == "stiffest" else f["ks"][0] if parts[1] == "softest" else float(parts[1])
        what = parts[2]
        if (where, what) in f["changes"]:
            return verdict.change_text(f["changes"][(where, what)][:3])
        if what in [name for name, _ in CRITERIA]:  # a change not judged yet: fewer than two seeds paired
            return f"(not known yet: {len(set(f['runs'][where]) & set(f['fixed']))} seed paired)"
        if (where, what) in f["means"]:
            dg = next(d for n, _, _, d in MEASURES if n == what)
            m, h = f["means"][(where, what)]
            return f"{m:.{dg}f} ± {h:.{dg}f}"
        raise KeyError(key)
    return resolve


def figure(f, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ks = f["ks"]
    fig, ax = plt.subplots(1, 3, figsize=(13, 4))
    for a, names, ylabel in ((ax[0], ("ice mean", "ice max"), "ice load on the hull N"),
                             (ax[1], ("mooring mean", "mooring max"), "mooring force along the travel N"),
                             (ax[2], ("offset mean", "offset std"), "surge offset mm (log)")):
        for name, style in zip(names, ("o-", "s--")):
            m = np.array([f["means"][(k, name)][0] for k in ks])
            h = np.array([f["means"][(k, name)][1] for k in ks])
            label = name
            if name == "offset mean":  # pushed back: drawn as a distance, on the log scale
                m, label = -m, "pushed back (mean)"
            a.errorbar(ks, m, yerr=h, fmt=style, capsize=3, label=label)
        if a is ax[0]:
            for name, colour in (("ice mean", "C0"), ("ice max", "C1")):
                m, h = f["means"][("fixed", name)]
                a.axhspan(m - h, m + h, color=colour, alpha=0.15, label=f"fixed cone, {name.split()[1]}")
        if f["limit"] is not None and a is ax[0]:
            a.axvline(f["limit"], color="grey", lw=0.8, ls=":", label="loads as the fixed cone's from here")
        a.set_xscale("log")
        a.set_xlabel("mooring surge stiffness N/m")
        a.set_ylabel(ylabel)
        a.legend(fontsize=7)
    ax[2].set_yscale("log")
    fig.suptitle("The moored cone on the paper's small floes (f_ii 0.5, f_is 0.2): means over seeds, 95 % intervals")
    fig.tight_layout()
    output_guard.save_figure(fig, path, dpi=110)
    plt.close(fig)


def about(f):
    return (f"Made by `scripts/mooring_stiffness` from the committed records of {resolver(f)('mooring | runs')} of "
            f"`{os.path.relpath(STUDY, ROOT)}` and of the paper grid's small_rigid runs at f_ii 0.5, f_is 0.2 (the fixed "
            "cone). ± is the half-width of the 95 % interval over the seeds; a change is paired seed by seed with the "
            "fixed cone's run of the same layout (the log ratio, docs/model/estimators.md), its 95 % interval in "
            "brackets; \"moves\" when that interval excludes no change, \"unresolved\" when it does not. The mooring "
            "force and the offset are over the ice load's window, low-passed as it is; a negative offset is the "
            "structure pushed back from its attachment's rest.")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--report", help="the page (default docs/model/mooring.md)")
    ap.add_argument("--figure", help="the figure (default docs/model/mooring_stiffness.png); 'none' for none")
    a = ap.parse_args(argv)
    try:
        f = facts()
    except spec.SweepError as e:
        sys.exit(f"scripts/mooring_stiffness: {e}")
    path = a.report or PAGE
    fig = a.figure or os.path.join(ROOT, "docs", "model", "mooring_stiffness.png")
    outputs = [("--report", path, output_guard.FILE)] + ([("--figure", fig, output_guard.FILE)] if fig != "none" else [])
    output_guard.guard(outputs, [STUDY])
    if not any(f["runs"].values()):
        sys.exit(f"scripts/mooring_stiffness: no finished run of {os.path.relpath(STUDY, ROOT)} has a record yet")
    block = "\n".join([BEGIN, "", about(f), ""] + table(f) + ["", multiplicity(f), "", END])
    page = open(path).read()
    page = spans.replace_block(page, block, BEGIN, END)
    try:
        page = spans.fill(page, resolver(f), only="mooring |")
    except spans.UnknownKey as e:
        sys.exit(f"scripts/mooring_stiffness: {path}: {e}")
    output_guard.write_text(path, page)
    print(f"wrote {path}")
    if fig != "none":
        figure(f, fig)
        print(f"wrote {fig}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
