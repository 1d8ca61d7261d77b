// The State: everything that changes during a run (the Scene does not).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "dem/break_context.hpp"
#include "dem/contact_problem_export.hpp"
#include "dem/diagnostics.hpp"
#include "dem/drag_exchange.hpp"
#include "dem/flow_field.hpp"
#include "dem/joint_loads.hpp"
#include "dem/load_cell.hpp"
#include "dem/recorder.hpp"
#include "dem/world.hpp"

namespace icedem {

/// Wall time spent in each stage of step(), accumulated over the run (s).
struct StageTimes {
  double structure = 0;   // move_structure
  double water = 0;       // apply_water_forces
  double bullet = 0;      // collide, solve, integrate (Bullet)
  double load_cell = 0;   // read_load_cell
  double activation = 0;  // update_activation
  double health = 0;      // check_health
  double fracture = 0;    // check_fracture
  double coupling = 0;    // exchange_drag (coupling.mode = "probe")
};

struct State {
  std::unique_ptr<World> world;     // Bullet bodies; poses and velocities change every step
  std::unique_ptr<FlowField> flow;  // water velocity model; follows the structure
  std::unique_ptr<DragExchange> drag_exchange;  // exchanged drag (probe mode), else null
  std::unique_ptr<ProblemExport> problem_export;  // writes chosen steps' contact problems, else null

  double time = 0.0;  // s, simulated; written by step()
  long step = 0;      // completed steps; written by step()

  Eigen::Vector3d structure_position = Eigen::Vector3d::Zero();  // m, axis at the waterline
  Eigen::Vector3d structure_velocity = Eigen::Vector3d::Zero();  // m/s

  LoadReading load;    // ice load of the last step; written by read_load_cell

  int awake_floes = 0;     // floes simulated in the last step
  int contact_points = 0;  // contact points in the world after the last step
  StepDiagnostics diagnostics;   // health of the last step (speeds, energy, mass, gaps); check_health

  std::optional<double> first_contact_time;  // s, first step with ice on the structure

  std::vector<FractureEvent> fracture_events;  // breaks of the last step; written by check_fracture
  std::array<int, kFailureModes> breaks_by_mode{};           // all breaks so far, by FailureMode value
  std::array<int, kBreakMechanisms> breaks_by_mechanism{};   // all breaks so far, by BreakMechanism value
  std::vector<FloeFailureMargin> floe_margins;  // per layout floe with joints: how close they came to failing
  std::vector<JointLoads> filtered_joint_loads;  // low-passed loads per World::joints() entry
                                                 // (fracture.load_filter_time > 0)

  StageTimes stage_times;  // written by step()
};

}  // namespace icedem
