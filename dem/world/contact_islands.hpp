// Sleeping islands built from touching contacts.
//
// Bullet decides which bodies may sleep per "island", and builds islands from
// broadphase pairs, i.e. from overlapping bounding boxes enlarged by the contact
// threshold. At 75 % ice concentration neighbouring floes' boxes overlap, so the
// whole field is one island and one moving floe keeps all ~1000 awake
// (docs/model/bullet.md: 936 of 960 awake). Here two bodies share an island only if
// their contact manifold holds at least one contact point, i.e. they touch or
// are about to. Floes that merely sit near each other sleep independently, and
// a sleeping floe is woken when an awake one touches it. Every solved contact
// still joins its bodies, provided the solver never sees a manifold without
// points: Bullet would give its bodies solver bodies in the solve of body 0's
// island, and a body solved in two islands gets its applied forces twice. The
// world therefore sets m_deterministicOverlappingPairs, which drops empty
// manifolds from the islands (dem/world/world.cpp).
#pragma once

#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>

namespace icedem {

class ContactIslandManager : public btSimulationIslandManager {
 public:
  /// Tag bodies and unite those joined by a manifold with contact points
  /// (replaces Bullet's union over broadphase pairs).
  void updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) override;
};

}  // namespace icedem
