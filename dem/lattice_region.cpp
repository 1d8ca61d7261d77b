#include "dem/lattice_region.hpp"

namespace icedem {

void update_lattice_region(const Scene& scene, State& state) {
  if (scene.fracture.lattice_radius <= 0) return;
  World& world = *state.world;
  const Eigen::Vector3d& axis = state.structure_position;
  for (DormantLattice& lattice : world.lattices()) {
    if (lattice.replaced) continue;
    const btVector3& c = world.floes()[lattice.stand_in].body->getCenterOfMassPosition();
    // the floe's nearest point is at least |centre - axis| - radius from the axis
    const double gap = std::hypot(c.x() - axis.x(), c.z() - axis.z()) - lattice.radius;
    if (gap < scene.fracture.lattice_radius) world.wake_lattice(lattice);
  }
}

}  // namespace icedem
