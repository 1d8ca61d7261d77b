// The lattice region (fracture.lattice_radius): a breakable floe is simulated
// as one rigid body (its stand-in) while it is far from the structure, and as
// its lattice of elements and joints while some part of it is within
// lattice_radius of the structure axis; an intact lattice that has moved
// kLatticeHysteresis beyond the radius becomes a rigid body again, a broken
// one stays a lattice. This saves the joint rows, most of the solver's work in a
// breakable scene; the price is that ice outside the region cannot break
// (scripts/fracture_remedy.sh measures where breaks happen with lattices
// everywhere; docs/model/physics.md, "Breakable ice").
#pragma once

#include <Eigen/Core>

#include "dem/fracture/fracture_state.hpp"
#include "dem/input/scene.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// m: how far beyond fracture.lattice_radius an intact lattice must be before it
/// becomes a rigid body again (so that a floe at the edge does not switch every step).
constexpr double kLatticeHysteresis = 0.5;

/// Replace every stand-in that has come within fracture.lattice_radius of the
/// structure axis at `structure` (horizontal distance to its nearest possible point) by its
/// element lattice, and every intact lattice beyond the radius plus the
/// hysteresis by its stand-in (its joints' low-passed loads in `fracture` reset).
/// Does nothing when the radius is 0.
void update_lattice_region(const Scene& scene, const Eigen::Vector3d& structure, World& world,
                           FractureState& fracture);

}  // namespace icedem
