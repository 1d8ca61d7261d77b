#include "dem/activation/left_behind.hpp"

#include <btBulletDynamicsCommon.h>

namespace icedem {

int leave_behind(const Scene& scene, const Eigen::Vector3d& structure, World& world) {
  const double distance = scene.activation.leave_behind;
  if (distance <= 0) return 0;
  const double travel = scene.structure.speed < 0 ? -1.0 : 1.0;
  int left = 0;
  for (std::size_t i = 0; i < world.floes().size(); ++i) {
    const FloeBody& floe = world.floes()[i];
    if (floe.fragment >= 0 || floe.stand_in || floe.lattice >= 0 || floe.gone || floe.left) continue;
    const btRigidBody& body = *floe.body;
    if (!body.isInWorld()) continue;  // not reached yet: it lies where the layout put it
    btVector3 lo, hi;
    body.getCollisionShape()->getAabb(body.getWorldTransform(), lo, hi);
    // the floe's point farthest along the travel, behind the line by more than the distance
    const double front = travel > 0 ? hi.x() : -lo.x();
    if (front < travel * structure.x() - distance) {
      world.leave_run(static_cast<int>(i));
      ++left;
    }
  }
  return left;
}

}  // namespace icedem
