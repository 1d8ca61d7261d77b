#include "dem/world/load_cell.hpp"

#include <algorithm>

#include "dem/world/bullet_eigen.hpp"
#include "dem/world/contact_solver.hpp"

namespace icedem {
void structure_manifolds(const btDispatcher& dispatcher, const btRigidBody* structure,
                         std::vector<const btPersistentManifold*>& out) {
  out.clear();
  const int n = dispatcher.getNumManifolds();
  for (int i = 0; i < n; ++i) {
    const btPersistentManifold* m = const_cast<btDispatcher&>(dispatcher).getManifoldByIndexInternal(i);
    if (m->getBody0() == structure || m->getBody1() == structure) out.push_back(m);
  }
  std::sort(out.begin(), out.end(), [](const btPersistentManifold* a, const btPersistentManifold* b) {
    return ContactSolver::canonical(a) < ContactSolver::canonical(b);
  });
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> LoadCell::accumulate(const btDispatcher& dispatcher,
                                                                 const btRigidBody* structure,
                                                                 const Eigen::Vector3d& reference) {
  contacts_ = 0;
  Eigen::Vector3d step_impulse = Eigen::Vector3d::Zero(), step_angular = Eigen::Vector3d::Zero();
  structure_manifolds(dispatcher, structure, touching_);
  for (const btPersistentManifold* m : touching_) {
    const bool is_body0 = m->getBody0() == structure;
    // impulses act on body 0; the structure feels the opposite when it is body 1
    const double sign = is_body0 ? 1.0 : -1.0;
    for (int k = 0; k < m->getNumContacts(); ++k) {
      const btManifoldPoint& p = m->getContactPoint(k);
      const btVector3 j = contact_impulse(p);
      if (j.isZero()) continue;
      const Eigen::Vector3d impulse = sign * to_eigen(j);
      const Eigen::Vector3d at = to_eigen(is_body0 ? p.getPositionWorldOnA() : p.getPositionWorldOnB());
      const Eigen::Vector3d angular = (at - reference).cross(impulse);
      impulse_ += impulse;  // point by point, as the step's own sum would round otherwise
      angular_impulse_ += angular;
      step_impulse += impulse;
      step_angular += angular;
      ++contacts_;
    }
  }
  return {step_impulse, step_angular};
}

LoadReading LoadCell::finish(double dt) {
  LoadReading r{impulse_ / dt, angular_impulse_ / dt, contacts_};
  impulse_.setZero();
  angular_impulse_.setZero();
  contacts_ = 0;
  return r;
}

}  // namespace icedem
