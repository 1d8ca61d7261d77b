"""The report's sections on breakage: the mechanism of every break per f_ii against the
paper's Fig. 18, with pictures, and how close the floes near the structure came to breaking
(tools/icedem_tools/report.py)."""
import collections
import os

from . import aggregate as agg
from .report_tables import BREAKABLE, FII, fmt, quantile

def breaks_of(records, scenario, fii=None):
    """Every break of a scenario's runs (at one f_ii, or all): [(run, event dict)], and the runs."""
    runs = [(r, rec) for r, rec in records.get(scenario, []) if fii is None or dict(r.grid).get(FII) == fii]
    return [(r, e) for r, rec in runs for e in rec.get("fracture_events", [])], runs

def mechanism_section(records, figs, report):
    """Breaks by mechanism per f_ii (dem/break_context.hpp), against the paper's Fig. 18."""
    L = ["## Breakage mechanisms", "",
         "Every break is recorded with what its floe was doing in the step of the break "
         "(`/fracture/events`; docs/model/breakage.md): whether an element of it touched the structure, the "
         "depth of the joint below the waterline, the contact force of other floes on it (down and "
         "towards the structure axis) and its distance from the structure. Classes: **on the slope** "
         "(touching the structure), **pressed under** (touching, submerged at least one thickness and "
         "pressed by another floe), **in the rubble** (not touching, submerged), **in the pack** (not "
         "touching, afloat). Summed over f_is and seeds.", ""]
    share = {}
    # the mechanisms as the events name them (icedem declares them; every summary counts all)
    mechanisms = [m.replace("_", " ") for m in agg.break_names(
        [rec["summary"] for v in records.values() for _, rec in v], "breaks_by_mechanism")]
    for s in BREAKABLE:
        if s not in records:
            continue
        L += [f"### {s}", "",
              "| f_ii | runs | breaks | per run | " + " | ".join(mechanisms) + " | median depth mm | "
              "median distance m | median force of other floes N |", "|---" * (7 + len(mechanisms)) + "|"]
        fiis = sorted({dict(r.grid).get(FII) for r, _ in records[s]} - {None})
        for fii in fiis:
            ev, runs = breaks_of(records, s, fii)
            counts = collections.Counter(e.get("mechanism_name", "") for _, e in ev)
            n = len(ev)
            share[(s, fii)] = {m: counts[m] / n for m in mechanisms} if n else None
            cells = " | ".join(f"{counts[m]} ({100 * counts[m] / n:.0f} %)" if n else "0" for m in mechanisms)
            depth = quantile([1e3 * e["depth"] for _, e in ev if "depth" in e], 0.5)
            dist = quantile([e["distance"] for _, e in ev if "distance" in e], 0.5)
            press = quantile([e["press_down"] + e["press_toward"] for _, e in ev if "press_down" in e], 0.5)
            L.append(f"| {fii:g} | {len(runs)} | {n} | {n / len(runs):.2f} | {cells} | {fmt(depth, '', 0)} | "
                     f"{fmt(dist, '', 2)} | {fmt(press, '', 1)} |")
        L.append("")
        lo, hi = share.get((s, 0.3)), share.get((s, 0.7))
        if lo and hi:
            pu = (lo["pressed under"], hi["pressed under"])
            sl = (lo["on the slope"], hi["on the slope"])
            agree = pu[0] > pu[1] and sl[1] > sl[0]
            L += [f"Fig. 18 says: at f_ii 0.3 a submerged floe pressed against the cone by an approaching floe "
                  f"breaks; at 0.7 floes break sliding on the slope. Here pressed under is {100 * pu[0]:.0f} % of "
                  f"the breaks at f_ii 0.3 and {100 * pu[1]:.0f} % at 0.7; on the slope {100 * sl[0]:.0f} % and "
                  f"{100 * sl[1]:.0f} %: the shift with f_ii {'agrees' if agree else '**does not agree**'} with "
                  "the paper's picture.", ""]
        pictures = [f for f in sorted(os.listdir(figs)) if f.startswith(f"break_{s}_")] if os.path.isdir(figs) else []
        if pictures:
            L += ["Just before a break, like the paper's Fig. 18 (scripts/break_pictures.py: side and top view, the "
                  "broken floe in red):", ""]
            L += [f"![{f}]({os.path.relpath(figs, os.path.dirname(report))}/{f})" for f in pictures] + [""]
    return L

def margin_section(records, figs, report):
    """How close the floes that reach the structure come to breaking: the largest joint load ratio
    per floe (summary near_structure_max_ratio), its distribution per scenario and f_ii."""
    rel = os.path.relpath(figs, os.path.dirname(report))
    L = ["## How close the ice comes to failure", "",
         "For every floe whose joints came within 1 m of the structure, the largest load / capacity "
         "ratio any of its joints reached under any criterion (eq. 1-3) during the run; 1 breaks the joint. "
         "A 0.6 m floe on water breaks when about 45 N of vertical load presses one edge "
         "(docs/model/breakage.md: a beam on an elastic foundation, 47 N at the first joint line of 0.15 m "
         "elements, 45 N at 0.20 m), far below the loads the cone carries; a distribution far below 1 "
         "means the cone's load does not reach the joints as edge bending.", ""]
    present = set(os.listdir(figs)) if os.path.isdir(figs) else set()
    for s in BREAKABLE:
        if s not in records:
            continue
        L += [f"### {s}", "", "| f_ii | runs | floes near the structure per run | median ratio | 90 % | 99 % | "
              "share ≥ 0.5 | share ≥ 1 (broke) |", "|---|---|---|---|---|---|---|---|"]
        fiis = sorted({dict(r.grid).get(FII) for r, _ in records[s]} - {None})
        for fii in fiis + [None]:
            runs = [rec for r, rec in records[s] if fii is None or dict(r.grid).get(FII) == fii]
            ratios = [x for rec in runs for x in rec["summary"].get("near_structure_max_ratio", [])]
            if not runs:
                continue
            n = len(ratios)
            L.append(f"| {'all' if fii is None else f'{fii:g}'} | {len(runs)} | {n / len(runs):.1f} | "
                     f"{fmt(quantile(ratios, 0.5), '', 2)} | {fmt(quantile(ratios, 0.9), '', 2)} | "
                     f"{fmt(quantile(ratios, 0.99), '', 2)} | "
                     f"{fmt(100 * sum(x >= 0.5 for x in ratios) / n if n else None, ' %', 0)} | "
                     f"{fmt(100 * sum(x >= 1 for x in ratios) / n if n else None, ' %', 0)} |")
        L.append("")
        if f"ratios_{s}.png" in present:
            L += [f"![ratios_{s}.png]({rel}/ratios_{s}.png)", ""]
    return L
