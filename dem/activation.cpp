#include "dem/activation.hpp"

#include <btBulletDynamicsCommon.h>

namespace icedem {
namespace {

bool in_region(const Scene& scene, const State& state, const btRigidBody& body) {
  const double x = body.getCenterOfMassPosition().x();
  const double xs = state.structure_position.x();
  return x >= xs - scene.activation.region_behind && x <= xs + scene.activation.region_ahead;
}

// Release frozen floes that were struck: the contact impulse on a frozen floe
// in the last step would have moved it, were it free, faster than the wake
// speed (J / m > activation.linear_threshold). The impulse measures the strike
// because the solve has already stopped the striker by the time we look.
//
// The solve treated the frozen floe as immovable, so the striker gave up all
// its momentum. On release that impulse is shared as a perfectly inelastic
// collision of the two masses would have shared it (restitution 0): the floe
// gets m_s / (m_s + m_f) of it and the striker m_f / (m_s + m_f) back, so
// momentum is conserved and the strike is not lost.
void release_struck(const Scene& scene, State& state) {
  World& world = *state.world;
  btDispatcher& dispatcher = *world.dynamics().getDispatcher();
  const double v_wake = scene.activation.linear_threshold;
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
    if (m->getNumContacts() == 0) continue;
    FloeBody* frozen_a = world.frozen_floe(m->getBody0());
    FloeBody* frozen_b = world.frozen_floe(m->getBody1());
    if ((frozen_a != nullptr) == (frozen_b != nullptr)) continue;  // both or neither frozen
    FloeBody& frozen = frozen_a ? *frozen_a : *frozen_b;
    double normal_impulse = 0;  // N s, summed over the points
    for (int k = 0; k < m->getNumContacts(); ++k) normal_impulse += m->getContactPoint(k).m_appliedImpulse;
    const double m_frozen = frozen.shape->mass;
    if (normal_impulse <= m_frozen * v_wake) continue;

    world.unfreeze(frozen);
    btRigidBody* striker = btRigidBody::upcast(const_cast<btCollisionObject*>(frozen_a ? m->getBody1() : m->getBody0()));
    const double inv_m_striker = striker ? striker->getInvMass() : 0.0;
    // shares of the impulse: frozen floe m_s/(m_s+m_f) = 1/(1 + m_f/m_s), striker the rest
    const double to_frozen = 1.0 / (1.0 + m_frozen * inv_m_striker);
    const double sign = frozen_a ? 1.0 : -1.0;  // Bullet's contact impulses act on body 0
    for (int k = 0; k < m->getNumContacts(); ++k) {
      const btManifoldPoint& p = m->getContactPoint(k);
      const btVector3 j = sign * (p.m_normalWorldOnB * p.m_appliedImpulse +
                                  p.m_lateralFrictionDir1 * p.m_appliedImpulseLateral1 +
                                  p.m_lateralFrictionDir2 * p.m_appliedImpulseLateral2);
      const btVector3 at = frozen_a ? p.getPositionWorldOnA() : p.getPositionWorldOnB();
      frozen.body->applyImpulse(j * to_frozen, at - frozen.body->getCenterOfMassPosition());
      if (striker && inv_m_striker > 0)
        striker->applyImpulse(j * (1.0 - to_frozen), at - striker->getCenterOfMassPosition());
    }
  }
}

}  // namespace

void update_activation(const Scene& scene, State& state) {
  if (!scene.activation.sleeping || !scene.activation.freeze_outside_region) return;
  release_struck(scene, state);
  for (FloeBody& floe : state.world->floes()) {
    const bool inside = in_region(scene, state, *floe.body);
    if (floe.frozen) {
      if (inside) state.world->unfreeze(floe);
    } else if (!inside) {
      // resting: slow for activation.time (Bullet's per-body deactivation clock)
      const int s = floe.body->getActivationState();
      if (s == WANTS_DEACTIVATION || s == ISLAND_SLEEPING) state.world->freeze(floe);
    }
  }
}

}  // namespace icedem
