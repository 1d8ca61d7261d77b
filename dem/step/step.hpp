// One time step of the simulation, as a list of stages.
#pragma once

#include "dem/input/scene.hpp"
#include "dem/step/state.hpp"
#include "dem/world/point_loads.hpp"

namespace icedem {

/// Advance the state by scene.time.dt: put the lattices of floes near the
/// structure in place of their stand-ins; exchange the drag with the OpenFOAM
/// partner when one is due (coupling.mode = "probe"); per Bullet substep, move the
/// structure, apply water forces, detect collisions, find the islands, solve each
/// island's contacts, integrate, read the load cell and check the joints for
/// fracture; then average the load over the step, update sleeping/freezing and
/// check for blow-ups. `loads` (a validation case's, a
/// test's) are applied before every Bullet step, in the point-load stage.
/// Throws NumericalError on a blow-up, CouplingError if the partner fails.
void step(const Scene& scene, State& state, const PointLoads* loads = nullptr);

/// What a run can attach to its steps (a validation case, dem/validation/case.hpp): the
/// forces it prescribes for the coming step, and a measurement after each step.
class StepCase {
 public:
  virtual ~StepCase() = default;
  /// The forces the case prescribes for the coming step (the point-load stage).
  const PointLoads& loads() const { return loads_; }
  /// Measures after a step, and sets the loads of the next.
  virtual void after_step(const Scene& scene, State& state) = 0;

 protected:
  PointLoads loads_;
};

/// One step of a run, the one every run takes: step() with the case's point loads, then the
/// case's measurement (`attached` null: none).
void advance(const Scene& scene, State& state, StepCase* attached);

/// The water stage: buoyancy, drag and damping on every awake floe (Bullet
/// clears applied forces after each of its steps, so call it before each).
void apply_water_forces(const Scene& scene, State& state);

/// Where the structure's reference point is at time t (prescribed carriage motion).
Eigen::Vector3d structure_position_at(const Scene& scene, double t);

}  // namespace icedem
