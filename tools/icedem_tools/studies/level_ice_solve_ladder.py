"""The analytic level tow's first 45 s over a ladder of contact solves, for docs/model/level_ice.md
(scripts/level_ice_report --solve-ladder SWEEP): each finished tow of SWEEP
(sweeps/studies/level_ice_analytic_solve_ladder.toml: frictions as scenarios, the solves as variants) with its
step, merit, tolerance, iteration cap, hand-over and the contacts that crush, who broke the sheet (the cone's
crushed zone, or a floe's push on the edge), its breaks below their breaking load, the longest time the sheet went
without a break, its loads over the window and what the solve cost; and, per friction and contacts that crush, what
going from the default solve to the tightest one at the default's step, merit, cap and hand-over does. One start
per rung: a rung changes the path from the first breaks on (the tow is chaotic), so a rung's loads are one draw,
not a converged value; who breaks the sheet, counted over some ninety breaks, is what the ladder resolves."""
import dataclasses
import os

from ..runs import spec
from ..sweeps import execute, aggregate as agg
from ..reports.report_tables import fmt
from . import level_ice_analytic as la


@dataclasses.dataclass
class Rung:
    run: object       # spec.Run
    record: dict      # aggregate.load_record's
    step: float       # the Bullet step, s
    merit: str        # solver.merit
    tolerance: float  # solver.merit_tolerance
    cap: int          # solver.method_iterations
    handover: str     # solver.handover_method
    crushing: str     # contact.crushing_contacts: "structure", or "structure_and_sheet" (the sheet's edge too)

    def same_but_tolerance(self, other):
        return ((self.step, self.merit, self.cap, self.handover, self.crushing)
                == (other.step, other.merit, other.cap, other.handover, other.crushing))


def rungs(sweep, out):
    """The sweep's finished tows (Rung), in the sweep's order (scenario, then variant)."""
    _, runs = spec.load(sweep)
    return [Rung(r, agg.load_record(r, out), float(spec.bullet_step(r)), str(spec.run_value(r, "solver.merit")),
                 float(spec.run_value(r, "solver.merit_tolerance")), int(spec.run_value(r, "solver.method_iterations")),
                 str(spec.run_value(r, "solver.handover_method")), str(spec.run_value(r, "contact.crushing_contacts")))
            for r in runs if execute.status(r, out).state == "done"]


def _share(part, whole):
    return "n/a" if part is None or not whole else f"{part} ({100 * part / whole:.0f} %)"


def tightest_against_default(found, design):
    """Per friction and contacts that crush, the sentence of what the tightest solve at the default's step, merit, cap
    and hand-over does against the default (the sweep's first rung of that scenario and crushing), from the records;
    none where either is missing."""
    L = []
    for scenario, crushing in dict.fromkeys((x.run.scenario, x.crushing) for x in found):
        base, *rest = [x for x in found if (x.run.scenario, x.crushing) == (scenario, crushing)]
        same = [x for x in rest if x.same_but_tolerance(base)]
        if not same:
            continue
        tight = min(same, key=lambda x: x.tolerance)
        loads, _ = design(base.run)
        b, t = base.record, tight.record
        bs, ts = b.get("sheet") or {}, t.get("sheet") or {}
        if bs.get("by_floe") is None or ts.get("by_floe") is None:
            continue
        mean_b, mean_t = la._value(b, "mean_fx_N"), la._value(t, "mean_fx_N")
        cap = ts.get("at_cap")
        L.append(f"{scenario}" + (f" (mu {loads['friction']:g})" if loads else "")
                 + (f", crushing at {crushing.replace('_', ' ')}" if crushing != "structure" else "")
                 + f": from {base.merit} {base.tolerance:g} to {tight.merit} {tight.tolerance:g} at {base.step:g} s, "
                 f"the breaks by floes go from {bs['by_floe']} of {bs['breaks']} to {ts['by_floe']} of {ts['breaks']}, "
                 f"those below {agg.UNDERLOAD:g} of their load from {bs['underloaded']} to {ts['underloaded']}, the "
                 f"longest time without a break from {bs['longest_without_break_s']:.1f} s to "
                 f"{ts['longest_without_break_s']:.1f} s, and the mean load from {mean_b:.1f} N to {mean_t:.1f} N "
                 f"({100 * (mean_t / mean_b - 1):+.1f} %, one start each)"
                 + (f"; {100 * cap['steps']:.0f} % of the tightest's steps reached the solve's cap, and "
                    f"{cap['by_floe']} of its {ts['by_floe']} breaks by floes fell at one." if cap else "."))
    return L


def section(sweep, out, design):
    """The page's lines on the tows of `sweep` (runs in `out`); design(run) as level_ice_analytic's."""
    L = ["### Who breaks the sheet, solve by solve", "",
         f"Runs of `{os.path.relpath(sweep, spec.ROOT)}` finished so far: the crushing tows' first 45 s from one "
         "start, at each rung of a ladder of contact solves (dem/contact/merit.hpp: Siconos' merit, the default, "
         "and the impulse merit, each to a tolerance; cap: solver.method_iterations, the gradient steps an island "
         "may take; hand-over: the method an island left at the cap above its tolerance goes on with, "
         "solver.handover_method) and at the halved step; crushing: the contacts the crushing law acts on, the "
         "structure's, or the structure's and the held sheet's edge's (contact.crushing_contacts = "
         "\"structure_and_sheet\", docs/model/crushing.md, \"Against the level sheet\"). "
         "Who broke the sheet: the cone's crushed zone, or a floe's "
         "push on the edge (a piece pressed against it by the rubble between the edge and the cone, "
         "docs/model/breakage.md, \"The edge's bound in the solve\"); below: the breaks under "
         f"{agg.UNDERLOAD:g} of their breaking load (the smallest ratio in brackets); without a break: the longest "
         "time from one break to the next or to the run's end (the floes' breaks can clear the sheet ahead of the "
         "cone, which then meets none for a while). Loads in N, surge, over the window from 0.14 m of travel past "
         "the first contact: the cone's entry into the sheet, not the tow's steady state, so the rungs compare "
         "with each other, not with the whole tows above. At the cap: the steps whose solve reached its cap above "
         "the tolerance (an island handed over there, or left capped), of the whole run; floes' at the cap: the "
         "floes' breaks that fell at such a step.", ""]
    found = rungs(sweep, out)
    if not found:
        return L + ["No finished run yet.", ""]
    L += ["| run | mu | step s | merit | tolerance | cap | hand-over | crushing | breaks | by floes | "
          "below (smallest) | "
          "without a break s | mean | p99 | max 5 Hz | steps at the cap | floes' at the cap | iterations a step | "
          "real time (CPU) |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for x in found:
        rec = x.record
        s, sheet = rec["summary"], rec.get("sheet") or {}
        loads, _ = design(x.run)
        solver, cap = s.get("solver") or {}, sheet.get("at_cap")
        cpu = s.get("cpu_time_s")
        below = ("n/a" if sheet.get("underloaded") is None
                 else f"{sheet['underloaded']} ({fmt(sheet.get('smallest_load_ratio'), digits=2)})")
        steps = "n/a" if not cap else f"{100 * cap['steps']:.1f} %"
        floes = "n/a" if not cap or sheet.get("by_floe") is None else f"{cap['by_floe']} of {sheet['by_floe']}"
        mu = f"{loads['friction']:g}" if loads else "n/a"
        L.append(f"| {x.run.scenario} | {mu} | {x.step:g} | {x.merit} | {x.tolerance:g} | {x.cap} | {x.handover} | "
                 f"{x.crushing.replace('_', ' ')} | "
                 f"{sheet.get('breaks', 'n/a')} | {_share(sheet.get('by_floe'), sheet.get('breaks'))} | {below} | "
                 f"{fmt(sheet.get('longest_without_break_s'))} | {fmt(la._value(rec, 'mean_fx_N'))} | "
                 f"{fmt(la._value(rec, 'p99_fx_N'))} | {fmt(la._value(rec, la.LOWPASS))} | "
                 f"{steps} | {floes} | {fmt(solver.get('iterations_mean'), digits=0)} | "
                 f"{fmt(s['sim_time_s'] / cpu if cpu else None, digits=2)} |")
    told = tightest_against_default(found, design)
    if told:
        L += ["", "The default solve against the tightest at its step, merit, cap, hand-over and crushing: "
              + " ".join(told)]
    return L + [""]
