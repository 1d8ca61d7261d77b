#include "dem/contact_islands.hpp"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <LinearMath/btAlignedAllocator.h>

namespace icedem {

void ContactIslandManager::updateActivationState(btCollisionWorld* world, btDispatcher* dispatcher) {
  // tag dynamic bodies 0..n-1, as Bullet does (static and kinematic ones never join islands)
  btCollisionObjectArray& objects = world->getCollisionObjectArray();
  int index = 0;
  for (int i = 0; i < objects.size(); ++i) {
    btCollisionObject* object = objects[i];
    if (!object->isStaticOrKinematicObject()) object->setIslandTag(index++);
    object->setCompanionId(-1);
    object->setHitFraction(btScalar(1));
  }
  initUnionFind(index);

  // unite bodies that touch: a manifold with contact points
  for (int i = 0; i < dispatcher->getNumManifolds(); ++i) {
    const btPersistentManifold* manifold = dispatcher->getManifoldByIndexInternal(i);
    if (manifold->getNumContacts() == 0) continue;
    const btCollisionObject* a = manifold->getBody0();
    const btCollisionObject* b = manifold->getBody1();
    if (a->mergesSimulationIslands() && b->mergesSimulationIslands())
      getUnionFind().unite(a->getIslandTag(), b->getIslandTag());
  }
}

void DynamicsWorld::replace_island_manager(btSimulationIslandManager* manager) {
  if (m_ownsIslandManager) {
    // Bullet allocated its own with btAlignedAlloc + placement new
    m_islandManager->~btSimulationIslandManager();
    btAlignedFree(m_islandManager);
  }
  m_islandManager = manager;
  m_ownsIslandManager = false;
}

void DynamicsWorld::solveConstraints(btContactSolverInfo& info) {
  if (pre_solve_) pre_solve_();
  btDiscreteDynamicsWorld::solveConstraints(info);
}

}  // namespace icedem
