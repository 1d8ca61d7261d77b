#include "dem/world/static_friction.hpp"

#include <algorithm>

#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

namespace icedem {
namespace {

// the velocity of the material point of `body` at `at` (world frame); fixed bodies have none
btVector3 point_velocity(const btCollisionObject& body, const btVector3& at) {
  const btRigidBody* rigid = btRigidBody::upcast(&body);
  if (!rigid) return btVector3(0, 0, 0);
  return rigid->getVelocityInLocalPoint(at - rigid->getCenterOfMassPosition());
}

}  // namespace

double slip_speed(const btCollisionObject& a, const btCollisionObject& b, const btManifoldPoint& point) {
  const btVector3 relative = point_velocity(a, point.getPositionWorldOnA()) - point_velocity(b, point.getPositionWorldOnB());
  const btVector3& n = point.m_normalWorldOnB;
  return (relative - n * relative.dot(n)).length();
}

double contact_friction(const StaticFriction& law, double kinetic, bool on_structure, double slip) {
  const double stat = on_structure ? law.ice_structure : law.ice_ice;
  if (stat <= 0 || slip >= law.stick_speed) return kinetic;
  return std::max(kinetic, stat);
}

}  // namespace icedem
