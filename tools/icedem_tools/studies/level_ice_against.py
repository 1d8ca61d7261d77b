"""The analytic level tow's ensemble changed in one thing, against the tows without leave_behind of the analytic
sweep, for docs/model/level_ice.md (scripts/level_ice_report --analytic SWEEP with --step STEP_SWEEP, the step
halved, sweeps/studies/level_ice_analytic_step.toml; --crushing CRUSHING_SWEEP, the crushing contact law,
sweeps/studies/level_ice_analytic_crushing.toml; --solve SOLVE_SWEEP, the solve tightened,
sweeps/studies/level_ice_analytic_solve.toml; --sheet-crushing SHEET_SWEEP, the floes crushing against the sheet's
edge too, sweeps/studies/level_ice_analytic_sheet_crushing.toml): per scenario (friction) and criterion, each
ensemble's mean over its starts, its step and its solve, and the change over the starts both ran.

The tow is chaotic: a start at a halved step, or under another contact law, parts from the same start's tow
within the first breaks, so the two are not one path but two draws. The change is still taken over the starts
both ran (the project's one estimator, stats/verdict.judged_change): pairing independent draws costs nothing in
bias, and its interval, over few starts, is wide and says so."""
import os

from ..runs import spec
from ..stats import verdict
from . import level_ice_analytic as la


def solve_text(members):
    """How an ensemble's tows were solved, from what its sweep sets (spec.run_value): the merit and the tolerance an
    island touching the structure is solved to ("siconos 0.001"); "n/a" for none or a scenario that cannot be read."""
    if not members:
        return "n/a"
    run = next(iter(members.values()))[0]
    try:
        tolerance = min(float(spec.run_value(run, "solver.merit_tolerance")),
                        float(spec.run_value(run, "solver.structure_merit_tolerance")))
        return f"{spec.run_value(run, 'solver.merit')} {tolerance:g}"
    except (OSError, KeyError, ValueError):
        return "n/a"


def _ensemble(values):
    """An ensemble's mean with its interval (level_ice_analytic.mean_text) and its number of starts."""
    v = [x for x in values if x is not None]
    return la.mean_text(v) + (f" ({len(v)})" if v else "")


# (heading, what the changed tows are, why they are run or how to read them)
STEP = ("### Halving the step", "the same tows at half their step (each against the tows above of its scenario's name)",
        "The 5 Hz low-passed maximum is the one maximum a step does not set by construction; the unfiltered "
        "maximum is a single step's. The halved step is solved to the impulse merit's 1e-4 (its solve column), "
        "meant as the same accuracy of the forces: Siconos' merit, the default, loosens relative to the forces as "
        "the step shrinks, and a looser solve lowers these tows' loads (\"Tightening the solve\"). But the merit "
        "alone moves who breaks the sheet (\"Who breaks the sheet, solve by solve\"), so these changes are the "
        "step's and the solve's together.")
CRUSHING = ("### The crushing contact law",
            "the same tows with the ice crushing against the cone (contact.model = \"crushing\", at the structure "
            "only, docs/model/crushing.md) instead of rigid contacts",
            "The sheet's own contact zones bear load by that law already, while its pieces met the cone rigidly, "
            "and a piece locked between the cone and the held sheet then took in one step whatever stopped it.")
SOLVE = ("### Tightening the solve", "the same tows with their contacts solved to a tighter merit (each against the "
         "tows above of its scenario's name)",
         "A looser solve lowered these tows' loads (a tow solved to the impulse merit's 1e-3, not kept: why is not "
         "measured; a solve stopped short leaves part of the jam's push to the split impulse's position pass, "
         "which no load reads). The default's loads are converged only where a tighter solve leaves them.")
SHEET_CRUSHING = ("### Crushing against the sheet's edge",
                  "the same tows with the floes crushing against the held sheet's edge too (contact.crushing_contacts "
                  "= \"structure_and_sheet\", docs/model/crushing.md, \"Against the level sheet\"; each against the "
                  "tows above of its scenario's name)",
                  "Solved further, the rubble pressed pieces against the sheet's rigid face, and their friction there "
                  "broke the sheet the more often the tighter the solve (\"Who breaks the sheet, solve by solve\"); "
                  "the ice's face crushes as the cone's contact does, which bounds that push. Who broke these tows' "
                  "sheet: \"Where the changed tows' sheet broke\", its column of breaks by floes.")


def section(bases, other, other_configs, what, base_of=lambda scenario: scenario):
    """The page's lines: each scenario's tows of the sweep file `other` (its configurations `other_configs`,
    level_ice_analytic.configurations) against the tows without leave_behind of scenario `base_of(name)` among the
    configurations `bases` (a list, one a sweep, their scenarios' names distinct); `what` is CRUSHING, STEP, SOLVE
    or SHEET_CRUSHING."""
    heading, text, why = what
    L = [heading, "",
         f"The tows above without leave_behind against {text} (`{os.path.relpath(other, spec.ROOT)}`). {why} The "
         "tow is chaotic, so a start of these tows is another draw, not the same path: each ensemble's mean over "
         "its starts (their number in brackets) with Student's 95 % interval, and the change over the starts both "
         "ran (the log ratio's 95 % interval and verdict, docs/model/estimators.md; wide over few starts).", ""]
    base = {sc: m for configs in bases for (sc, leave), m in configs.items() if leave == 0.0}
    changed = {sc: m for (sc, _), m in other_configs.items()}
    if not changed:
        return L + ["No finished run yet.", ""]
    L += ["| run | against | criterion | step s | solve | against's | step s | solve | these | "
          "change, starts both ran | starts |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    changes, names = {}, {}
    for scenario in sorted(changed):
        h_members, b_members = changed[scenario], base.get(base_of(scenario), {})
        dt_b, dt_h = la.ensemble_step(b_members), la.ensemble_step(h_members)
        solve_b, solve_h = solve_text(b_members), solve_text(h_members)
        common = sorted(set(h_members) & set(b_members))
        for label, key in la.CRITERIA.items():
            a = [la._value(h_members[s][1], key) for s in common]
            b = [la._value(b_members[s][1], key) for s in common]
            pairs = [(x, y) for x, y in zip(a, b) if x is not None and y is not None]
            if len(pairs) >= 2:
                k = (scenario, label)
                changes[k] = verdict.judged_change([x for x, _ in pairs], [y for _, y in pairs])
                names[k] = f"{scenario}: {label}"
                change = verdict.change_text(changes[k][:3])
            elif pairs:
                change = f"{100 * (pairs[0][0] / pairs[0][1] - 1):+.1f} % (one start)"
            else:
                change = "n/a"
            L.append(f"| {scenario} | {base_of(scenario)} | {label} | {'n/a' if dt_b is None else f'{dt_b:g}'} | "
                     f"{solve_b} | {_ensemble(la._value(rec, key) for _, rec in b_members.values())} | "
                     f"{'n/a' if dt_h is None else f'{dt_h:g}'} | {solve_h} | "
                     f"{_ensemble(la._value(rec, key) for _, rec in h_members.values())} | {change} | {len(pairs)} |")
    rtf = [rec["summary"]["sim_time_s"] / rec["summary"]["cpu_time_s"] for members in changed.values()
           for _, rec in members.values() if rec["summary"].get("cpu_time_s")]
    capped = [(rec["summary"].get("solver") or {}).get("capped_window_fraction") for members in changed.values()
              for _, rec in members.values()]
    capped = [c for c in capped if c is not None]
    if rtf:
        L += ["", f"These tows ran at {sum(rtf) / len(rtf):.2f} times real time in CPU on average"
              + (f"; {100 * sum(capped) / len(capped):.1f} % of their analysis windows' steps stopped at the solve's "
                 "iteration cap above its tolerance (their loads not converged)" if capped else "") + "."]
    L += [""]
    if changes:
        L += [verdict.family_text(changes, lambda k: names[k]), ""]
    return L
