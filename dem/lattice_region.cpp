#include "dem/lattice_region.hpp"

#include <cmath>

#include "dem/ice_lattice.hpp"

namespace icedem {

void update_lattice_region(const Scene& scene, State& state) {
  const double radius = scene.fracture.lattice_radius;
  if (radius <= 0) return;
  World& world = *state.world;
  const Eigen::Vector3d& axis = state.structure_position;
  for (DormantLattice& lattice : world.lattices()) {
    if (lattice.broken) continue;  // pieces stay pieces
    // the floe's nearest point is at least |centre - axis| - radius from the axis
    const btVector3 c = lattice_centre(world, lattice);
    const double gap = std::hypot(c.x() - axis.x(), c.z() - axis.z()) - lattice.radius;
    if (!lattice.replaced && gap < radius) {
      wake_lattice(world, lattice);
    } else if (lattice.replaced && gap > radius + kLatticeHysteresis) {
      // left the region intact: a rigid body again; its joints' filtered loads restart
      if (make_dormant(world, lattice) && !state.filtered_joint_loads.empty())
        for (int j = 0; j < lattice.joints; ++j) state.filtered_joint_loads[lattice.first_joint + j] = JointLoads{};
    }
  }
}

}  // namespace icedem
