#!/usr/bin/python3
"""The report's check of whether the findings are converged (tools/icedem_tools/reports/report_convergence.py):
a number whose every seed moves the same way by far more than the tolerance and the seeds'
scatter is beyond it; one whose interval excludes no change but straddles the tolerance moves;
one that moves within a tight interval inside the tolerance is within; the larger/smaller
ratio takes each seed's change of both cases; breaks compare seed by seed; a mechanism's
share changes only when resampling the seeds keeps the whole interval on one side."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # checks, beside this file
from checks import check, finish  # noqa: E402
from icedem_tools.reports.report_convergence import (  # noqa: E402
    MEAN_TOLERANCE, headline_section, max_bounds, seeds_for_tolerance, verdict)
from icedem_tools.stats.verdict import log_change  # noqa: E402


def summary(mean, peak, breaks=0, mechanisms=None, p99=None):
    s = {"mean_fx_N": mean, "max_fx_N": peak, "breaks": breaks, "breaks_by_mechanism": mechanisms or {}}
    return s if p99 is None else {**s, "p99_fx_N": p99}


seeds = [1, 2, 3, 4, 5]
scatter = {1: 0.8, 2: 1.3, 3: 1.0, 4: 0.9, 5: 1.1}  # layouts differ by far more than the numerics
got = {
    # small floes: dt/2 leaves the mean within 1 % in every seed, raises the max by 30 % in every seed
    # and its p99 by 2 % in every seed
    ("small_rigid", "default"): {s: summary(12 * scatter[s], 50 * scatter[s], p99=30 * scatter[s]) for s in seeds},
    ("small_rigid", "dt_half"): {s: summary(12 * scatter[s] * (1 + 0.002 * (s - 3)), 65 * scatter[s],
                                            p99=30.6 * scatter[s]) for s in seeds},
    # larger floes: dt/2 raises the mean by 3-7 % (the seeds' interval about +3 to +7 %, across
    # the 5 % tolerance) and leaves the max as it was, so the larger/smaller max ratio falls by 1/1.3
    ("large_rigid", "default"): {s: summary(20 * scatter[s], 90 * scatter[s]) for s in seeds},
    ("large_rigid", "dt_half"): {s: summary(20 * scatter[s] * (1.05 + 0.01 * (s - 3)), 90 * scatter[s])
                                 for s in seeds},
    # a lattice: pressed under 8 of 10 breaks in every seed at the default, on the slope 8 of 10 at dt/2
    ("large_breakable_015", "default"): {s: summary(20, 60, 10 + s, {"pressed_under": 8, "on_the_slope": 2})
                                         for s in seeds},
    ("large_breakable_015", "dt_half"): {s: summary(20 * (1.3 if s % 2 else 0.75), 60, 10 + s,
                                                    {"pressed_under": 2, "on_the_slope": 8}) for s in seeds},
}
text = "\n".join(headline_section(got))
print(text)
rows = {line.split(" | ")[0].strip("| "): line for line in text.splitlines() if line.startswith("| ")}


def row_verdict(name):
    return cells(rows[name])[6] if name in rows else None


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


check(row_verdict("small_rigid mean load") == "within", "a mean within 1 % in every seed is within")
check(row_verdict("small_rigid max load") == "**beyond**", "a max 30 % up in every seed is beyond 10 %")
check("+30 %" in rows.get("small_rigid max load", ""), "and its change reads +30 %")
check(row_verdict("small_rigid p99 load") == "within" and "+2 %" in rows.get("small_rigid p99 load", ""),
      "a p99 up 2 % in every seed is within 10 %")
check("large_rigid p99 load" not in rows and not any("p99" in k for k in rows if k.startswith("larger")),
      "no p99 row where the runs do not give one, and no p99 ratio (the paper's ratios are of mean and max)")
check(row_verdict("large_rigid mean load") == "**moves**",
      f"a mean up 3-7 % in the seeds moves, its size against 5 % unresolved: {rows.get('large_rigid mean load')}")
check(row_verdict("large_rigid max load") == "within", "no change at all is within")
ratio = rows.get("larger / smaller rigid floes, max load", "")
check("-23 %" in ratio and row_verdict("larger / smaller rigid floes, max load") == "**beyond**",
      f"the ratio of maxima falls by 1 - 1/1.3 = 23 % in every seed: {ratio}")
check(row_verdict("large_breakable_015 mean load") == "unresolved",
      "a mean that goes up in some seeds and down in others by 25-30 % is unresolved")
check(row_verdict("large_breakable_015 breaks per run") == "within" and "+0.0" in
      rows.get("large_breakable_015 breaks per run", ""), "the same breaks in every seed hold")
check("-0 " not in text, "no change is written +0, never -0")
check(row_verdict("large_breakable_015 share pressed under") == "**beyond**"
      and "-60 points" in rows.get("large_breakable_015 share pressed under", ""),
      "pressed under from 80 % to 20 % of the breaks in every seed is beyond 5 points, by -60 points")
check("Beyond tolerance with the numerics:" in text and "small_rigid max load with dt_half" in text
      and "Moving with the numerics" in text and "large_rigid mean load with dt_half" in text,
      "the sentences list what is beyond and what moves")
few = {k: {s: v[s] for s in (1, 2, 3)} for k, v in got.items()}
few_rows = {line.split(" | ")[0].strip("| "): line for line in headline_section(few) if line.startswith("| ")}
check("no interval: 3 seeds" in few_rows.get("large_breakable_015 share pressed under", "")
      and cells(few_rows["large_breakable_015 share pressed under"])[6] == "unresolved",
      "3 seeds give a bootstrap 10 distinct resamples: no interval, the share is unresolved")

# the pieces
c = log_change([(1.1, 1.0), (1.1, 1.0), (1.1, 1.0)])
check(abs(c[0] - 0.1) < 1e-12 and c[2] == 3, f"a 10 % rise in every seed is +10 %: {c}")
check(log_change([(None, 1.0)]) is None, "no pair: no change")
check(verdict(None, MEAN_TOLERANCE) == "unresolved", "one seed is unresolved")
check(verdict((-0.04, 0.04), MEAN_TOLERANCE) == "within" and verdict((-0.06, 0.04), MEAN_TOLERANCE) == "unresolved",
      "an interval inside the tolerance is within; one that includes 0 and reaches beyond it is unresolved")
check(verdict((-0.2, 0.01), None) == "unresolved" and verdict((0.01, 0.2), None) == "**moves**",
      "without a tolerance an interval that includes 0 is unresolved; one above 0 moves")
check(verdict((0.01, 0.03), MEAN_TOLERANCE) == "within",
      "a change resolved from 0 but inside the tolerance is within: the findings carry it")
check(verdict((0.02, 0.20), 0.10) == "**moves**" and verdict((0.11, 0.20), 0.10) == "**beyond**"
      and verdict((-0.30, -0.12), 0.10) == "**beyond**",
      "an interval above 0 across the bound moves; one wholly outside the bound, on either side, is beyond")
check(headline_section({}) == [], "no runs: no section")
bounds = max_bounds(got, ["dt_half"])
mean_peak = 50 * sum(scatter.values()) / len(scatter)  # the default's mean of maxima, 51 N
check(abs(bounds["small_rigid"][0] - mean_peak) < 1e-9 and abs(bounds["small_rigid"][1] - 1.3 * mean_peak) < 1e-6
      and bounds["small_rigid"][2] == "dt_half",
      f"a max up 30 % in every seed (a zero-width interval) is bounded by 1.3 x the default's: {bounds.get('small_rigid')}")
check(abs(bounds["large_breakable_015"][1] - 60) < 1e-6 and "at most 66.3 N" in text,
      "an unchanged max is bounded by the default's own, and the report gives the bounds")
check(seeds_for_tolerance((-0.2, 0.2), 0.05, 10, student=False) == "160"
      and seeds_for_tolerance((-0.02, 0.02), 0.05, 10) == "10"
      and seeds_for_tolerance(None, 0.05, 3) == "" and seeds_for_tolerance((-1.0, 1.0), 0.0, 3) == "",
      "an interval 4 times the tolerance needs 16 times the seeds; one inside it no more seeds; none without "
      "an interval or a tolerance")
# Student's t at 3 seeds (4.303) against the normal quantile (1.960): 16 x 3 x (1.960 / 4.303)^2 = 9.96
check(seeds_for_tolerance((-0.2, 0.2), 0.05, 3) == "10",
      "a t interval over 3 seeds also narrows as t falls from 4.30 to 1.96")
lo, hi = math.expm1(-0.2), math.expm1(0.2)
check(seeds_for_tolerance((lo, hi), math.expm1(0.1), 5, log=True, student=False) == "20",
      "a ratio's interval is sized as logs: exp(+-0.2) against a tolerance exp(0.1) - 1 needs 4 times the seeds")
big = cells(rows["large_breakable_015 mean load"])
check(int(big[7]) > 5, f"a mean scattered by 25-30 % per seed needs more than its 5 seeds for +-5 %: {big[7]}")

finish()
