// The State: everything that changes during a run (the Scene does not).
//
// It is declared once. StateValues holds every value the stages change from step to step; a
// checkpoint (dem/output/checkpoint.hpp) copies it whole and writes and reads it field by field
// through visit_fields(), and a test fails when a field is declared here but not listed there.
// The world's bodies, lattices and contact points are kept by dem/output/world_state.hpp, which a
// checkpoint takes the same way. Outputs (the recorder, the contact problems a run exports)
// belong to the run loop, not to the State.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "dem/core/diagnostics.hpp"
#include "dem/fracture/analytic_sheet.hpp"
#include "dem/fracture/fracture_state.hpp"
#include "dem/mooring/floating_structure.hpp"
#include "dem/mooring/structure_motion.hpp"
#include "dem/water/drag_exchange.hpp"
#include "dem/water/flow_field.hpp"
#include "dem/world/load_cell.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// Wall time spent in each stage of step(), accumulated over the run (s).
struct StageTimes {
  double structure = 0;   // move_structure
  double water = 0;       // apply_water_forces
  double collision = 0;   // Bullet's collision detection: predicted motion, broadphase, contact points
  double islands = 0;     // islands of touching bodies, frozen floes struck released
  double solve = 0;       // the contact solve of every island (dem/world/contact_solver.hpp)
  double integrate = 0;   // positions, sleeping, Bullet's forces cleared
  double load_cell = 0;   // read_load_cell
  double activation = 0;  // update_activation
  double health = 0;      // check_health
  double fracture = 0;    // check_fracture
  double coupling = 0;    // exchange_drag (coupling.mode = "probe")

  /// Bullet's step as a whole: collision, islands, solve and integration.
  double bullet() const { return collision + islands + solve + integrate; }
};

/// Every value of a run that its stages change, but the world's bodies.
struct StateValues {
  double time = 0.0;  // s, simulated; written by step()
  long step = 0;      // completed steps; written by step()

  Eigen::Vector3d structure_position = Eigen::Vector3d::Zero();  // m, axis at the waterline
  Eigen::Vector3d structure_velocity = Eigen::Vector3d::Zero();  // m/s, of the reference point
  StructureMotionState structure_motion;  // a moored structure's rotation, velocities, last loads (else zeros)

  LoadReading load;  // ice load of the last step; written by read_load_cell

  int awake_floes = 0;          // floes simulated in the last step
  int contact_points = 0;       // contact points in the world after the last step
  StepDiagnostics diagnostics;  // health of the last step (speeds, energy, mass, gaps); check_health

  std::optional<double> first_contact_time;  // s, first step with ice on the structure

  FractureState fracture;  // breaks, their counts, failure margins, filtered joint loads; the fracture stages

  StageTimes stage_times;  // written by step()
};

/// Calls `visit(name, field)` for every field of `v` in declaration order: the one list by which
/// a checkpoint writes and reads the values (dem/output/checkpoint.cpp). A field added to StateValues
/// and not here fails tests/unit/test_state_fields.cpp (field_count, dem/core/field_count.hpp).
template <typename Values, typename Visit>  // Values: StateValues or const StateValues
std::enable_if_t<std::is_same_v<std::remove_const_t<Values>, StateValues>> visit_fields(Values& v, Visit&& visit) {
  visit("time", v.time);
  visit("step", v.step);
  visit("structure_position", v.structure_position);
  visit("structure_velocity", v.structure_velocity);
  visit("structure_motion", v.structure_motion);
  visit("load", v.load);
  visit("awake_floes", v.awake_floes);
  visit("contact_points", v.contact_points);
  visit("diagnostics", v.diagnostics);
  visit("first_contact_time", v.first_contact_time);
  visit("fracture", v.fracture);
  visit("stage_times", v.stage_times);
}

/// The values with the objects that hold the rest of what changes: the Bullet world (poses and
/// velocities change every step), the water's velocity model (it follows the structure) and
/// the drag an OpenFOAM partner exchanges (coupling.mode = "probe"), else null.
struct State : StateValues {
  std::unique_ptr<World> world;
  std::unique_ptr<FlowField> flow;
  std::unique_ptr<DragExchange> drag_exchange;
  std::shared_ptr<const FloatingStructure> floating;  // structure.motion = "moored": the body and its mooring
  std::unique_ptr<AnalyticSheet> sheet;  // level ice cut by closed forms (analytic_level_ice), else null
};

}  // namespace icedem
