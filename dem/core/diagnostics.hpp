// Per-step numerical-health diagnostics: what the health check measures after
// every step, the recorder writes under /diagnostics and the summary reduces to
// its extremes. The stress suite (scripts/stress) judges a run by them, so each
// has a physical bound there.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>

namespace icedem {

struct StepDiagnostics {
  double max_angular_speed = 0;     // rad/s, fastest-turning awake floe or element
  double max_speed = 0;             // m/s, fastest awake floe or element (centre of mass)
  double kinetic_energy = 0;        // J, translation + rotation of the awake ice bodies
  double ice_mass = 0;              // kg, ice in the Bullet world with its centre inside the tank
  double max_joint_gap = 0;         // m, widest separation of an intact joint's two anchors
  double max_cone_penetration = 0;  // m, deepest ice vertex inside the structure hull (radial)
  double max_contact_penetration = 0;  // m, deepest contact point of the step's manifolds (overlap of two bodies)
  double solver_iterations = 0;     // most contact sweeps an island used (dem/world/contact_solver.hpp)
  double solver_residual = 0;       // largest residual an island ended its sweeps with
  double solver_capped = 0;         // 1 if an island reached solver.iterations above solver.tolerance
  double breaking_solves = 0;       // islands solved again for a joint near its capacity (solver.breaking_ratio)
  double breaking_decided = 0;      // of those, the ones every break of which was decided at solver.breaking_check_tolerance
  double breaking_capped = 0;       // of those, the ones that stopped at solver.breaking_iterations above their merit
  double handovers = 0;             // islands handed over at solver.method_iterations to solver.handover_method
  double runaways = 0;              // later stages' answers refused for impulses run off (dem/contact/refinement.hpp)
  double boundary_load = 0;         // N, fixed bodies' resistance to the structure's push (dem/world/boundary_load.hpp)
  double locked = 0;                // 1 if the boundaries carry kLockedShare of the surge load or more
  double held_edge_overloads = 0;   // a level sheet's joints at its held edge over their capacity (never broken)
  double sheet_holds = 0;           // the analytic sheet's loads at their breaking load where it was not cut
};

/// How a diagnostic goes into the run's summary: its largest value over the run (the health
/// section), or, for a count of what the island solve did (dem/contact/island_solve.hpp), its
/// sum (the summary's solver section, under the same name). A new count is a field above and a
/// column below marked kCount, and the island solve adding to it: the step copies it, the
/// recorder writes it and the summary sums it by this table.
enum class Reduction { kLargest, kCount };

/// One diagnostic: its dataset name under /diagnostics, unit and meaning.
struct DiagnosticColumn {
  const char* name;
  const char* unit;
  const char* description;
  double StepDiagnostics::*field;
  Reduction reduction = Reduction::kLargest;
};

inline constexpr DiagnosticColumn kDiagnosticColumns[] = {
    {"max_angular_speed", "rad/s",
     "fastest-turning awake floe or element (a growing rocking of elements shows here before a blow-up)",
     &StepDiagnostics::max_angular_speed},
    {"max_speed", "m/s", "fastest awake floe or element (centre of mass)", &StepDiagnostics::max_speed},
    {"kinetic_energy", "J", "kinetic energy (translation and rotation) of the awake ice",
     &StepDiagnostics::kinetic_energy},
    {"ice_mass", "kg", "mass of the ice in the world with its centre inside the tank", &StepDiagnostics::ice_mass},
    {"max_joint_gap", "m", "widest separation of the two anchors of an intact element joint",
     &StepDiagnostics::max_joint_gap},
    {"max_cone_penetration", "m", "deepest ice vertex inside the structure hull, radially (tunnelling shows here)",
     &StepDiagnostics::max_cone_penetration},
    {"max_contact_penetration", "m",
     "deepest contact point of any two bodies in Bullet's manifolds after the step (their overlap; the "
     "split-impulse position sweeps push it out, solver.position_iterations)",
     &StepDiagnostics::max_contact_penetration},
    {"solver_iterations", "1",
     "most PGS sweeps over the contacts any island used in the step (the cap is solver.iterations); with "
     "another solver.method, most of its iterations (cap solver.method_iterations)",
     &StepDiagnostics::solver_iterations},
    {"solver_residual", "1",
     "largest residual an island ended the step's sweeps with: the relative change of its bodies' net impulses and "
     "of its load on the structure in the last sweep over 1 - rate, an estimate of the error left "
     "(dem/world/contact_solver.hpp); with another solver.method, the largest merit (natural-map residual, "
     "docs/model/contact_problems.md)",
     &StepDiagnostics::solver_residual},
    {"solver_capped", "1",
     "1 if an island reached solver.iterations with its residual above solver.tolerance (another "
     "solver.method: solver.method_iterations with its merit above solver.merit_tolerance)",
     &StepDiagnostics::solver_capped},
    {"breaking_solves", "1",
     "islands solved again in the step, from their answer, to solver.breaking_merit_tolerance because the answer "
     "put a joint's failure ratio within 1 - solver.breaking_ratio of 1 (methods other than \"pgs\")",
     &StepDiagnostics::breaking_solves, Reduction::kCount},
    {"breaking_decided", "1",
     "of the step's breaking_solves, the islands that stopped at solver.breaking_check_tolerance with every "
     "joint's failure ratio farther than solver.breaking_check_band from 1: each break decided there",
     &StepDiagnostics::breaking_decided, Reduction::kCount},
    {"breaking_capped", "1",
     "of the step's breaking_solves, the islands that stopped at solver.breaking_iterations above "
     "solver.breaking_merit_tolerance: their joints' loads are no better known than at the joints' merit",
     &StepDiagnostics::breaking_capped, Reduction::kCount},
    {"handovers", "1",
     "islands the method left at solver.method_iterations above their merit in the step, which "
     "solver.handover_method (Newton for crushing contacts it does not take) went on with from that answer "
     "(solver_capped says whether it reached the merit)",
     &StepDiagnostics::handovers, Reduction::kCount},
    {"runaways", "1",
     "answers of a later stage in the step (the hand-over at the cap, a breaking solve's further stages) not "
     "taken because they lowered the merit by growing the island's impulses over ten times: where the "
     "solutions are unbounded (an element wedged between fixed bodies) a method can run off along them; "
     "the answer before it is kept (dem/contact/refinement.hpp)",
     &StepDiagnostics::runaways, Reduction::kCount},
    {"boundary_load", "N",
     "load the fixed bodies (walls, mother ice, frozen floes) take off the structure: their contact impulses on "
     "the ice of the islands touching the structure, along its travel, over the step (dem/world/boundary_load.hpp)",
     &StepDiagnostics::boundary_load},
    {"locked", "1",
     "1 if the fixed bodies carry half the structure's surge load or more: the pack is locked against a "
     "boundary and the load is the confinement's (docs/model/contact_problems.md, \"Locked packs\")",
     &StepDiagnostics::locked},
    {"held_edge_overloads", "1",
     "level ice: the sheet's joints between a free element and a held one that reached their capacity over the "
     "step (summed over its substeps); they do not break, the held sheet standing in for the ice around, whose "
     "clamp bends the free sheet harder than the ice would. Many: fracture.lattice_radius too small "
     "(docs/model/breakage.md, \"Level ice\")",
     &StepDiagnostics::held_edge_overloads},
    {"sheet_holds", "1",
     "level ice cut by closed forms: the sheet's loaded zones at or over their breaking load that were not cut at the "
     "end of the step (summed over its substeps): the cut would have parted the held sheet in two or left a hole in "
     "it, no ice lay within its crack, or Boost.Geometry's difference did not take the broken ice from the sheet. "
     "The sheet holds them and they crush on (docs/model/breakage.md, \"Level ice cut by closed forms\")",
     &StepDiagnostics::sheet_holds},
};
inline constexpr std::size_t kDiagnosticCount = std::size(kDiagnosticColumns);

/// The extremes of the diagnostics over a run.
struct DiagnosticExtremes {
  StepDiagnostics max;                          // largest value of each diagnostic
  double max_time[kDiagnosticCount] = {};       // s, when (kDiagnosticColumns order)
  double initial_ice_mass = -1;                 // kg, after the first step (-1: no step yet)
  double max_ice_mass_change = 0;               // largest |m - m0| / m0 (ice lost or created)

  void add(double time, const StepDiagnostics& d) {
    for (std::size_t c = 0; c < kDiagnosticCount; ++c) {
      const auto field = kDiagnosticColumns[c].field;
      if (d.*field > max.*field) {
        max.*field = d.*field;
        max_time[c] = time;
      }
    }
    if (initial_ice_mass < 0) initial_ice_mass = d.ice_mass;
    if (initial_ice_mass > 0)
      max_ice_mass_change = std::max(max_ice_mass_change, std::abs(d.ice_mass - initial_ice_mass) / initial_ice_mass);
  }
};

}  // namespace icedem
