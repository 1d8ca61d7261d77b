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
// manifolds from the islands (dem/world.cpp).
#pragma once

#include <functional>

#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>

namespace icedem {

class ContactIslandManager : public btSimulationIslandManager {
 public:
  /// Tag bodies and unite those joined by a manifold with contact points
  /// (replaces Bullet's union over broadphase pairs).
  void updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) override;
};

/// A btDiscreteDynamicsWorld whose island manager can be replaced (Bullet keeps
/// it in a protected member with no setter), with a hook that runs after
/// collision detection and before the constraint solve of every Bullet step.
class DynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;
  /// Use `manager` (not owned; must outlive the world) instead of the built-in one.
  void replace_island_manager(btSimulationIslandManager* manager);
  /// Run `hook` before each solve: contacts are fresh, velocities not yet solved.
  void set_pre_solve_hook(std::function<void()> hook) { pre_solve_ = std::move(hook); }
  void solveConstraints(btContactSolverInfo& info) override;

 private:
  std::function<void()> pre_solve_;
};

}  // namespace icedem
