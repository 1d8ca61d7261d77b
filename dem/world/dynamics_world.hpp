// Bullet's step in the stages step() names and times (dem/step/step.cpp): collision detection,
// islands, the contact solve, integration. They are btDiscreteDynamicsWorld::stepSimulation(h, 0)
// taken apart, in its order and with its arithmetic, so a run stepped stage by stage is bit
// for bit one stepped by stepSimulation (tests/physics/test_dynamics_world.cpp); Bullet's
// island manager can also be replaced (Bullet keeps it in a protected member with no setter).
#pragma once

#include <functional>

#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>

namespace icedem {

class DynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

  /// Use `manager` (not owned; must outlive the world) instead of the built-in one.
  void replace_island_manager(btSimulationIslandManager* manager);

  /// Run `hook` once the islands of a Bullet step are known, before its solve: contacts are
  /// fresh, velocities not yet solved (dem/activation/activation.hpp releases struck frozen floes there).
  void set_islands_hook(std::function<void()> hook) { islands_hook_ = std::move(hook); }

  /// Collision detection of a Bullet step of `h`: the kinematic structure's velocity from its
  /// target, gravity, the bodies' unconstrained motion predicted, then the broadphase and the
  /// contact points of every touching pair (Bullet's manifolds).
  void detect_collisions(btScalar h);

  /// The islands of bodies joined by contact points (dem/world/contact_islands.hpp), then the hook.
  void find_islands();

  /// The contact solve of every island: contacts and joints (the world's constraint solver,
  /// dem/world/contact_solver.hpp), leaving the bodies' new velocities.
  void solve_contacts(btScalar h);

  /// Integration: positions from the solved velocities, actions, sleeping, the motion states;
  /// then the applied forces are cleared, as at the end of stepSimulation.
  void integrate(btScalar h);

 protected:
  void calculateSimulationIslands() override;

 private:
  std::function<void()> islands_hook_;
};

}  // namespace icedem
