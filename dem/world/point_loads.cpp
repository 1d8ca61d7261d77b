// Prescribed point loads (dem/world/point_loads.hpp).
#include "dem/world/point_loads.hpp"

#include <btBulletDynamicsCommon.h>

#include "dem/world/world.hpp"

namespace icedem {

void PointLoads::apply(World& world) const {
  for (const auto& [body, f] : forces) {
    btRigidBody& b = *world.floes()[body].body;
    b.activate(true);
    b.applyCentralForce(btVector3(f.x(), f.y(), f.z()));
  }
}

}  // namespace icedem
