// One time step of the simulation, as a list of stages.
#pragma once

#include "dem/point_loads.hpp"
#include "dem/scene.hpp"
#include "dem/state.hpp"

namespace icedem {

/// Advance the state by scene.time.dt: put the lattices of floes near the
/// structure in place of their stand-ins; exchange the drag with the OpenFOAM
/// partner when one is due (coupling.mode = "probe"); per Bullet substep, move the
/// structure, apply water forces, let Bullet collide/solve/integrate, read the
/// load cell and check the joints for fracture; then average the load over the
/// step, update sleeping/freezing and check for blow-ups. `loads` (a validation case's, a
/// test's) are applied before every Bullet step, in the point-load stage.
/// Throws NumericalError on a blow-up, CouplingError if the partner fails.
void step(const Scene& scene, State& state, const PointLoads* loads = nullptr);

/// The water stage: buoyancy, drag and damping on every awake floe (Bullet
/// clears applied forces after each of its steps, so call it before each).
void apply_water_forces(const Scene& scene, State& state);

/// Where the structure's reference point is at time t (prescribed carriage motion).
Eigen::Vector3d structure_position_at(const Scene& scene, double t);

}  // namespace icedem
