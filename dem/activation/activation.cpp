#include "dem/activation/activation.hpp"

#include <btBulletDynamicsCommon.h>

namespace icedem {
namespace {

bool in_region(const Scene& scene, const Eigen::Vector3d& structure, const btRigidBody& body) {
  const double x = body.getCenterOfMassPosition().x();
  const double xs = structure.x();
  return x >= xs - scene.activation.region_behind && x <= xs + scene.activation.region_ahead;
}

// velocity of a body at a world point (zero for static bodies)
btVector3 velocity_at(const btCollisionObject* object, const btVector3& point) {
  const btRigidBody* body = btRigidBody::upcast(object);
  if (!body || body->getInvMass() == 0) return btVector3(0, 0, 0);
  return body->getVelocityInLocalPoint(point - body->getCenterOfMassPosition());
}

// Runs after collision detection, before the solve: release every frozen floe
// that an awake body is about to strike faster than the wake speed, so the
// solver treats the collision with the floe's real mass and momentum is
// exchanged as it should be. Slower contact (a jam creeping against frozen
// floes) leaves them fixed: that is the approximation freezing makes.
void release_struck(World& world, double v_wake, double dt) {
  btDispatcher& dispatcher = *world.dynamics().getDispatcher();
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
    const btCollisionObject* a = m->getBody0();
    const btCollisionObject* b = m->getBody1();
    if (!a->isStaticObject() && !b->isStaticObject()) continue;  // frozen floes are static
    FloeBody* frozen_a = world.frozen_floe(a);
    FloeBody* frozen_b = world.frozen_floe(b);
    if ((frozen_a != nullptr) == (frozen_b != nullptr)) continue;  // both frozen (stale contact) or neither
    FloeBody* frozen = frozen_a ? frozen_a : frozen_b;
    for (int k = 0; k < m->getNumContacts(); ++k) {
      const btManifoldPoint& p = m->getContactPoint(k);
      // the normal on B points from B to A: the closing speed is -(v_A - v_B) . n
      const double closing = -(velocity_at(a, p.getPositionWorldOnA()) - velocity_at(b, p.getPositionWorldOnB()))
                                  .dot(p.m_normalWorldOnB);
      // a strike: closing fast, and touching within this step
      if (closing > v_wake && p.getDistance() < closing * dt) {
        world.unfreeze(*frozen);
        break;
      }
    }
  }
}

}  // namespace

void install_activation(const Scene& scene, World& world) {
  const ActivationSettings& a = scene.activation;
  const double v_wake = a.linear_threshold, dt = scene.time.dt / scene.time.substeps;
  if (a.sleeping && a.freeze_outside_region)
    world.dynamics().set_islands_hook([&world, v_wake, dt] { release_struck(world, v_wake, dt); });
}

void update_activation(const Scene& scene, const Eigen::Vector3d& structure, World& world) {
  if (!scene.activation.sleeping || !scene.activation.freeze_outside_region) return;
  for (FloeBody& floe : world.floes()) {
    const bool inside = in_region(scene, structure, *floe.body);
    if (floe.frozen) {
      if (inside) world.unfreeze(floe);
    } else if (!inside) {
      // resting: slow for activation.time (Bullet's per-body deactivation clock)
      const int s = floe.body->getActivationState();
      if (s == WANTS_DEACTIVATION || s == ISLAND_SLEEPING) world.freeze(floe);
    }
  }
}

}  // namespace icedem
