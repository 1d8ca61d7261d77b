#include "dem/world/dynamics_world.hpp"

#include <BulletCollision/CollisionDispatch/btSimulationIslandManager.h>
#include <LinearMath/btAlignedAllocator.h>

namespace icedem {

void DynamicsWorld::replace_island_manager(btSimulationIslandManager* manager) {
  if (m_ownsIslandManager) {
    // Bullet allocated its own with btAlignedAlloc + placement new
    m_islandManager->~btSimulationIslandManager();
    btAlignedFree(m_islandManager);
  }
  m_islandManager = manager;
  m_ownsIslandManager = false;
}

// The four stages below are stepSimulation(h, 0) of Bullet 3.24 with its one internal step
// (internalSingleStepSimulation) inlined, statement for statement; only the profiler's calls
// and the debug drawer's switch of sleeping are left out (neither touches the bodies).

void DynamicsWorld::detect_collisions(btScalar h) {
  // stepSimulation with a variable step: one internal step of h
  m_localTime = m_latencyMotionStateInterpolation ? 0 : h;
  m_fixedTimeStep = 0;
  saveKinematicState(h);
  applyGravity();
  if (m_internalPreTickCallback) (*m_internalPreTickCallback)(this, h);
  predictUnconstraintMotion(h);
  btDispatcherInfo& dispatch = getDispatchInfo();
  dispatch.m_timeStep = h;
  dispatch.m_stepCount = 0;
  dispatch.m_debugDraw = getDebugDrawer();
  createPredictiveContacts(h);
  performDiscreteCollisionDetection();
}

void DynamicsWorld::find_islands() { calculateSimulationIslands(); }

void DynamicsWorld::calculateSimulationIslands() {
  btDiscreteDynamicsWorld::calculateSimulationIslands();
  if (islands_hook_) islands_hook_();
}

void DynamicsWorld::solve_contacts(btScalar h) {
  getSolverInfo().m_timeStep = h;
  solveConstraints(getSolverInfo());
}

void DynamicsWorld::integrate(btScalar h) {
  integrateTransforms(h);
  updateActions(h);
  updateActivationState(h);
  if (m_internalTickCallback) (*m_internalTickCallback)(this, h);
  synchronizeMotionStates();
  clearForces();
}

}  // namespace icedem
