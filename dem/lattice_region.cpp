#include "dem/lattice_region.hpp"

#include <cmath>

namespace icedem {

void update_lattice_region(const Scene& scene, State& state) {
  const double radius = scene.fracture.lattice_radius;
  if (radius <= 0) return;
  World& world = *state.world;
  const Eigen::Vector3d& axis = state.structure_position;
  for (DormantLattice& lattice : world.lattices()) {
    if (lattice.broken) continue;  // pieces stay pieces
    // the floe's nearest point is at least |centre - axis| - radius from the axis
    const btVector3 c = world.lattice_centre(lattice);
    const double gap = std::hypot(c.x() - axis.x(), c.z() - axis.z()) - lattice.radius;
    if (!lattice.replaced && gap < radius) {
      world.wake_lattice(lattice);
    } else if (lattice.replaced && gap > radius + kLatticeHysteresis) {
      // left the region intact: a rigid body again; its joints' filtered loads restart
      if (world.make_dormant(lattice) && !state.filtered_joint_loads.empty())
        for (int j = 0; j < lattice.joints; ++j) state.filtered_joint_loads[lattice.first_joint + j] = JointLoads{};
    }
  }
}

}  // namespace icedem
