#include "dem/world/contact_islands.hpp"

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

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

}  // namespace icedem
