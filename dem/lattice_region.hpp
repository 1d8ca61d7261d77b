// The lattice region (fracture.lattice_radius): a breakable floe far from the
// structure cannot break, so it is simulated as one rigid body (its stand-in)
// and becomes its lattice of elements and joints only when some part of it comes
// within lattice_radius of the structure axis. Far from the cone this saves the
// joint rows, which are most of the solver's work in a breakable scene; the cost
// is that a floe never breaks before it reaches the region (scripts/
// fracture_remedy.sh measures where breaks happen with lattices everywhere).
#pragma once

#include "dem/scene.hpp"
#include "dem/state.hpp"

namespace icedem {

/// Replace every stand-in that has come within fracture.lattice_radius of the
/// structure axis (horizontal distance to its nearest possible point) by its
/// element lattice. Does nothing when the radius is 0.
void update_lattice_region(const Scene& scene, State& state);

}  // namespace icedem
