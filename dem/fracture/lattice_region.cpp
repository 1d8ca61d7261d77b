#include "dem/fracture/lattice_region.hpp"

#include <cmath>

#include "dem/fracture/ice_lattice.hpp"

namespace icedem {

void update_lattice_region(const Scene& scene, const Eigen::Vector3d& structure, World& world,
                           FractureState& fracture) {
  const double radius = scene.fracture.lattice_radius;
  if (radius <= 0) return;
  for (DormantLattice& lattice : world.lattices()) {
    if (lattice.broken) continue;  // pieces stay pieces
    // the floe's nearest point is at least |centre - axis| - radius from the axis
    const btVector3 c = lattice_centre(world, lattice);
    const double gap = std::hypot(c.x() - structure.x(), c.z() - structure.z()) - lattice.radius;
    if (!lattice.replaced && gap < radius) {
      wake_lattice(world, lattice);
    } else if (lattice.replaced && gap > radius + kLatticeHysteresis) {
      // left the region intact: a rigid body again; its joints' filtered loads restart
      if (make_dormant(world, lattice) && !fracture.filtered_joint_loads.empty())
        for (int j = 0; j < lattice.joints; ++j) fracture.filtered_joint_loads[lattice.first_joint + j] = JointLoads{};
    }
  }
}

}  // namespace icedem
