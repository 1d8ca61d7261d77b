"""The model-error budget against the tank: what each factor of the model does to the loads.

    scripts/budget [--out DIR] [--report PATH]

The runs are those of the sweep file sweeps/studies/load_budget.toml: per scenario, a "default"
variant and variants that each move one factor from it (friction, boundaries, layout, water, the
paper's numerics), over the same layout seeds, made by `scripts/sweep run` into DIR (default
sweeps/load_budget); this script only reads them, from their records (the sweep's committed
docs/model/load_budget_records, or made from a finished run's directory), so it can report while the
sweep runs and on a machine that has only the records.

Per variant, over its finished seeds: the mean surge load over the analysis window, its 99th
percentile, the mean of the runs' maxima and of their maxima after a 5 Hz low-pass (the filter
stats.lowpass_hz applies: a load cell and carriage have a bandwidth the runs' record has not;
docs/model/tank_maxima.md) (each with the half-width of its 95 % interval), and
the runs whose maximum reaches the tank's largest load ([study.tank_max_N], per scenario: the tank's
single largest load of a run), with the Clopper-Pearson 95 % interval of that share. Against the default
(or the variant [study.paired_with] names for it, such as a factor's own run at half the step): each
number's change, paired seed by seed (the same seed is the same layout), with its 95 % interval and
the project's verdict (stats.verdict.judge: "within" the bound, "beyond" it, "moves", "unresolved";
bounds 5 % for the mean, 10 % for p99 and both maxima), and Fisher's exact test of the share reaching
the tank against the default's. The variants are ranked by the change of the mean of maxima.
Writes the tables to the report (default docs/model/load_budget.md, below its own text kept between
the markers) and prints them.
"""
import argparse
import datetime
import os
import sys
import tomllib

import numpy as np
from scipy import stats

from ..sweeps import aggregate as agg, execute
from ..runs import output_guard, spec
from ..stats import verdict
from ..stats.intervals import share_text
from ..stats.verdict import change_text
from ..reports import spans
from ..runs.spec import ROOT

STUDY_FILE = os.path.join(ROOT, "sweeps", "studies", "load_budget.toml")
TOLERANCE = {"mean": 0.05, "p99": 0.10, "max": 0.10, "max5": 0.10}
XMAX = 300  # %, the figure's scale; larger changes are named at its edge
BEGIN, END = "<!-- budget tables: scripts/budget writes below -->", "<!-- end of the budget tables -->"


def ensemble(records, tank):
    """A variant's finished runs over the seeds (aggregate.ensemble), from their records (kept with
    the sweep, so a fresh machine reports from the committed ones): the window's mean, p99 and max,
    and whether the run's max reaches the tank's largest load."""
    def per_run(r):
        s, peak, window = r["summary"], r["summary"].get("max_fx_N"), r.get("window", {})
        peak5 = window.get("max_lowpass_fx_N", {}).get("5")  # after the 5 Hz low-pass, where kept
        return {"mean": s.get("mean_fx_N"), "p99": window.get("p99_fx_N"), "max": peak, "max5": peak5,
                "reach": None if peak is None else float(peak >= tank),
                "reach5": None if peak5 is None else float(peak5 >= tank)}
    return agg.ensemble(records, per_run, summary=lambda r: r["summary"], counts=lambda r: agg.finished(r["summary"]))


def with_interval(value, half):
    """A number and the half-width of its interval ("n/a" for one seed)."""
    return f"{value:.1f} ± {'n/a' if half != half else f'{half:.1f}'}"


def change_cell(changes, key):
    return change_text(changes[key], digits=0) if key in changes else "n/a"


def tables(name, runs, found, tanks):
    """The budget's tables, one per scenario, as Markdown lines, and what the figure draws:
    {scenario: [(variant label, change of the maxima, of the 5 Hz maxima: (change, (lo, hi)) or None)]}."""
    lines, ranked, facts = [], {}, {}
    seeds = sorted({r.seed for r in runs})
    study = tomllib.load(open(STUDY_FILE, "rb"))["study"]
    for m in dict.fromkeys(r.scenario for r in runs):
        names = list(dict.fromkeys(r.variant for r in runs if r.scenario == m))
        tank = tanks[m]
        ens = {n: ensemble([found[(m, n, s)] for s in seeds if (m, n, s) in found], tank) for n in names}
        base = ens.get(study["baseline"])
        file = os.path.relpath(next(r.scenario_file for r in runs if r.scenario == m), ROOT)
        lines += [f"### {m} (`{file}`): the tank's {tank:.0f} N" + (" (an inference: 150 N / 2)" if tank < 150 else ""),
                  ""]
        if base is None:
            lines += ["The default has no finished run yet.", ""]
            continue
        k0 = int(round(base["runs"]["reach"].sum()))
        rows, tests = [], []  # tests: (label, criterion, p of "no change") of every change judged
        for n in names:
            e = ens[n]
            if e is None:
                rows.append((0.0, f"| {n} | 0 | no finished run yet ||||||||||||"))
                continue
            # a variant is paired with the default, or with the variant [study.paired_with] names (a
            # check of that variant's convergence: the same factor at half the step)
            against = study.get("paired_with", {}).get(n, study["baseline"])
            ref = ens.get(against)
            k = int(round(e["runs"]["reach"].sum()))
            if n == study["baseline"] or ref is None:
                changes, p = {}, None
            else:
                changes, _, _, _ = verdict.judge(e, ref, TOLERANCE)
                for c in changes:
                    tests.append((n if against == study["baseline"] else f"{n} (against {against})", c,
                                  verdict.paired_p(*verdict.paired_values(e, ref, c))))
                k_ref = int(round(ref["runs"]["reach"].sum()))
                p = stats.fisher_exact([[k, e["n"] - k], [k_ref, ref["n"] - k_ref]])[1]
            facts[(m, n)] = {"e": e, "changes": changes, "reach": k}
            label = n if against == study["baseline"] else f"{n} (against {against})"
            cells = [label, str(e["n"]), with_interval(*e["mean"]), change_cell(changes, "mean"),
                     with_interval(*e["p99"]), change_cell(changes, "p99"),
                     with_interval(*e["max"]), change_cell(changes, "max"),
                     with_interval(*e["max5"]) if "max5" in e else "n/a", change_cell(changes, "max5"),
                     share_text(k, e["n"]),
                     share_text(int(round(e["runs"]["reach5"].sum())), e["n"]) if "reach5" in e["runs"] else "n/a",
                     "" if p is None else f"{p:.2f}", f"{e['cpu']:.0f}"]
            rank = abs(changes["max"][0]) if "max" in changes and n != study["baseline"] else float("inf")
            rows.append((rank, "| " + " | ".join(cells) + " |"))
            if "max" in changes:
                ranked.setdefault(m, []).append((label, changes["max"][:2], changes["max5"][:2] if "max5" in changes else None))
        lines += [f"{base['n']} seeds of the default: mean {base['mean'][0]:.1f} N, mean of maxima "
                  f"{base['max'][0]:.1f} N; {k0} of {base['n']} runs reach the tank's {tank:.0f} N.", "",
                  "| variant | seeds | mean N | change | p99 N | change | max N | change | max at 5 Hz N | change | "
                  "runs reaching the tank (95 %) | at 5 Hz | Fisher p | CPU s/run |",
                  "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        lines += [row for _, row in sorted(rows, key=lambda x: -x[0])] + [""]
        lines += multiplicity(tests)
    return lines, ranked, facts


def resolver(facts):
    """What the page's prose spans (reports/spans.py) name, "SCENARIO | VARIANT | WHAT": WHAT a
    criterion of TOLERANCE, its change against the run the variant is paired with, with its interval
    and verdict; "CRITERION N" its mean over the seeds with its half-width; "reach" and "reach5" the
    runs reaching the tank as recorded and at 5 Hz, "k of n"."""
    def resolve(key):
        m, n, what = (x.strip() for x in key.split("|"))
        f = facts[(m, n)]
        e = f["e"]
        if what in TOLERANCE:
            return change_text(f["changes"][what], digits=0)
        if what.endswith(" N") and what[:-2] in TOLERANCE:
            return f"{with_interval(*e[what[:-2]])} N"
        if what == "reach":
            return f"{f['reach']} of {e['n']}"
        if what == "reach5":
            return f"{int(round(e['runs']['reach5'].sum()))} of {e['n']}"
        raise KeyError(key)
    return resolve


def multiplicity(tests):
    """A scenario's family of changes judged at 95 % each, and what holds of them corrected for their
    number (stats.verdict.family), as Markdown lines."""
    if not tests:
        return []
    holm, bh = verdict.family([p for _, _, p in tests])
    raw = sum(p < 0.05 for _, _, p in tests)
    held = [f"{label}: {c}" for (label, c, _), h in zip(tests, holm) if h]
    return [f"Of its {len(tests)} changes, {raw} exclude no change at 95 % each (about {0.05 * len(tests):.1f} would by "
            f"chance if nothing changed); {sum(holm)} hold under Holm's correction over the {len(tests)} (the chance of "
            f"any false one 5 %), {sum(bh)} under Benjamini-Hochberg's (a 5 % share of false ones expected)"
            + (f": {'; '.join(held)}." if held else "."), ""]


def figure(ranked, path):
    """Per scenario, each variant's change of the mean of the runs' maxima against the default (or the
    variant it is paired with), unfiltered and after the 5 Hz low-pass, with their 95 % intervals,
    ranked by the unfiltered change; the band is the bound a change is judged "within"."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: E402
    models = [m for m in ranked if ranked[m]]
    if not models:  # nothing paired yet: a figure that says so, not a stale one
        fig = plt.figure(figsize=(6, 1))
        fig.text(0.5, 0.5, "no variant has a finished run paired with the default yet", ha="center", va="center")
        output_guard.save_figure(fig, path, dpi=100)
        return
    heights = [0.8 + 0.28 * len(ranked[m]) for m in models]
    fig, axes = plt.subplots(len(models), 1, figsize=(8.5, sum(heights) + 0.4), squeeze=False,
                             gridspec_kw={"height_ratios": heights})
    for ax, m in zip(axes[:, 0], models):
        rows = sorted(ranked[m], key=lambda r: r[1][0])
        y = np.arange(len(rows))
        def bars(values, offset, colour, label):
            d = np.array([100 * v[0] if v else np.nan for v in values])
            lo = np.array([100 * v[1][0] if v and v[1] else x for v, x in zip(values, d)])
            hi = np.array([100 * v[1][1] if v and v[1] else x for v, x in zip(values, d)])
            ax.errorbar(d, y + offset, xerr=[d - lo, hi - d], fmt="o", ms=3.5, color=colour, lw=1, capsize=2,
                        label=label)
            for k in np.flatnonzero(d > XMAX):  # off the scale: named at its edge
                ax.annotate(f"{d[k]:+.0f} % →", (XMAX, y[k] + offset), fontsize=6, color=colour, ha="right",
                            va="center")
        bars([r[1] for r in rows], 0.12, "C0", "mean of the runs' maxima")
        bars([r[2] for r in rows], -0.12, "C1", "the same after a 5 Hz low-pass")
        ax.axvspan(-100 * TOLERANCE["max"], 100 * TOLERANCE["max"], color="0.9", zorder=0)
        ax.axvline(0, color="0.5", lw=0.8)
        ax.set_yticks(y)
        ax.set_yticklabels([r[0] for r in rows], fontsize=7)
        ax.set_title(m, fontsize=9)
        ax.set_xlabel("change against the default, % (95 % interval over the seeds)", fontsize=8)
        ax.set_xlim(-100, XMAX)
        ax.tick_params(axis="x", labelsize=7)
    axes[0, 0].legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    output_guard.save_figure(fig, path, dpi=100)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", help="the sweep's run directory (default: sweeps/load_budget)")
    ap.add_argument("--report", help="the Markdown page (default: docs/model/load_budget.md)")
    ap.add_argument("--figure", help="the ranked changes (default: beside the report, load_budget.png)")
    a = ap.parse_args(argv)
    try:
        name, runs = spec.load(STUDY_FILE)
    except spec.SweepError as e:
        sys.exit(f"scripts/budget: {e}")
    study = tomllib.load(open(STUDY_FILE, "rb"))["study"]
    out = a.out or os.path.join(ROOT, "sweeps", name)
    path = a.report or os.path.join(ROOT, "docs", "model", "load_budget.md")
    figure_path = a.figure or os.path.splitext(path)[0] + ".png"
    output_guard.guard([("--report", path, output_guard.FILE), ("--figure", figure_path, output_guard.FILE)],
                       [STUDY_FILE])
    # each run's record (made from its directory, or the kept one), its summary with its seed: the
    # changes are paired seed by seed (stats.verdict.judge)
    found = {}
    for r in runs:
        if execute.status(r, out).state == "done":
            record = agg.load_record(r, out)
            found[(r.scenario, r.variant, r.seed)] = dict(record, summary=dict(record["summary"], seed=r.seed))
    done = sum(1 for v in found.values() if agg.finished(v["summary"]))
    today = datetime.date.today().isoformat()
    lines = [BEGIN, "", f"Made {today} by `scripts/budget` from {done} of {len(runs)} runs of "
             f"`{os.path.relpath(STUDY_FILE, ROOT)}` in `{os.path.relpath(out, ROOT)}`. "
             "± is the half-width of the 95 % interval over the seeds. A change is paired seed by seed with the "
             "default's run of the same layout (the log ratio, docs/model/estimators.md), its 95 % interval in "
             "brackets, judged within 5 % (mean) and 10 % (p99, maxima). \"max at 5 Hz\" is "
             "the mean of the runs' maxima after the 5 Hz low-pass `stats.lowpass_hz` applies.", ""]
    table_lines, ranked, facts = tables(name, runs, found, study["tank_max_N"])  # per scenario
    figure(ranked, figure_path)
    lines += [f"![each variant's change of the maxima, ranked]({os.path.basename(figure_path)})", ""]
    lines += table_lines + [END]
    text = "\n".join(lines)
    print(text)
    page = open(path).read() if os.path.isfile(path) else ""
    try:  # the numbers of the page's own text, in their spans
        page = spans.fill(page, resolver(facts))
    except spans.UnknownKey as e:
        sys.exit(f"scripts/budget: {path}: {e}")
    output_guard.write_text(path, spans.replace_block(page, text, BEGIN, END))  # the tables replaced
    print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
