// Activation: which floes the solver works on.
//
// Inside the activation region around the structure (activation.region_behind
// to activation.region_ahead along x, the full channel width) floes follow
// Bullet's sleeping rules with contact islands (dem/world/contact_islands.hpp).
// Outside it, a floe that has been slow for activation.time is frozen: it
// becomes a fixed obstacle (zero inverse mass, no gravity, no water forces,
// no integration), so a jammed field far ahead of the structure costs nothing
// even though its contacts connect it to the moving rubble. That is the one
// approximation: a frozen floe does not creep. A frozen floe is released when
// the region reaches it, or when an awake body is about to strike it faster
// than activation.linear_threshold: that check runs inside each Bullet step,
// after collision detection and before the solve, so the solver handles the
// strike with the floe's real mass.
#pragma once

#include <Eigen/Core>

#include "dem/input/scene.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// Hook the strike check into the world's Bullet steps (once, after building it).
void install_activation(const Scene& scene, World& world);

/// Freeze resting floes outside the activation region around the structure's reference point
/// `structure` and release frozen floes that the region reached or that were struck. Call after
/// each step.
void update_activation(const Scene& scene, const Eigen::Vector3d& structure, World& world);

}  // namespace icedem
