#include "dem/world/boundary_load.hpp"

#include <algorithm>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "dem/world/bullet_eigen.hpp"
#include "dem/world/contact_solver.hpp"

namespace icedem {
namespace {

bool fixed(const btCollisionObject* o, const btRigidBody* structure) {
  const btRigidBody* body = btRigidBody::upcast(o);
  return o != structure && (!body || body->getInvMass() <= 0);
}

}  // namespace

void BoundaryLoad::accumulate(const btDispatcher& dispatcher, const btRigidBody* structure, double travel) {
  auto& d = const_cast<btDispatcher&>(dispatcher);
  const int n = d.getNumManifolds();
  // the islands the structure touches (Bullet's island tags of this step)
  std::vector<int> islands;
  for (int i = 0; i < n; ++i) {
    const btPersistentManifold* m = d.getManifoldByIndexInternal(i);
    if (m->getBody0() != structure && m->getBody1() != structure) continue;
    const btCollisionObject* ice = m->getBody0() == structure ? m->getBody1() : m->getBody0();
    if (m->getNumContacts() > 0 && ice->getIslandTag() >= 0) islands.push_back(ice->getIslandTag());
  }
  if (islands.empty()) return;
  std::sort(islands.begin(), islands.end());
  // the manifolds between those islands' ice and fixed bodies, added in the solver's canonical
  // order (the sum does not depend on the order of Bullet's arrays)
  std::vector<const btPersistentManifold*> boundary;
  for (int i = 0; i < n; ++i) {
    const btPersistentManifold* m = d.getManifoldByIndexInternal(i);
    const bool wall0 = fixed(m->getBody0(), structure), wall1 = fixed(m->getBody1(), structure);
    if (wall0 == wall1) continue;  // ice on ice, or two fixed bodies
    const btCollisionObject* ice = wall0 ? m->getBody1() : m->getBody0();
    if (ice == structure || !std::binary_search(islands.begin(), islands.end(), ice->getIslandTag())) continue;
    boundary.push_back(m);
  }
  std::sort(boundary.begin(), boundary.end(), [](const btPersistentManifold* a, const btPersistentManifold* b) {
    return ContactSolver::canonical(a) < ContactSolver::canonical(b);
  });
  for (const btPersistentManifold* m : boundary) {
    const bool wall0 = fixed(m->getBody0(), structure);
    // impulses act on body 0: the ice gets +j when it is body 0, -j when it is body 1
    const double sign = wall0 ? -1.0 : 1.0;
    for (int k = 0; k < m->getNumContacts(); ++k)
      impulse_ -= travel * sign * contact_impulse(m->getContactPoint(k)).x();
  }
}

double BoundaryLoad::finish(double dt) {
  const double load = impulse_ / dt;
  impulse_ = 0;
  return load;
}

}  // namespace icedem
