#include "dem/world/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <limits>
#include <optional>
#include <stdexcept>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "dem/contact/registry.hpp"
#include "dem/world/crushing_contact.hpp"
#include "dem/world/joint_springs.hpp"

namespace icedem {

// Gauss-Seidel converges linearly, e_k ~ rho^k: a sweep that changes the impulses by
// c_k leaves about c_k rho / (1 - rho) to come, with rho ~ c_k / c_{k-1}. On a long
// chain rho is close to 1 and a small change per sweep hides a large error (a row of
// 20 boxes measured 11 % low after sweeps that changed it by less than 1 %), so the
// residual is c_k / (1 - rho), rho capped at kMaxRate. The first sweep has no rate
// and counts as unconverged unless it changed nothing.
double ContactSolver::remaining_error(double change, double previous_change, int sweeps) {
  if (change == 0.0) return 0.0;
  if (sweeps < 2 || previous_change <= 0.0) return change / (1.0 - kMaxRate);
  const double rate = std::min(change / previous_change, kMaxRate);
  return change / (1.0 - rate);
}

ContactSolver::ContactSolver(const SolverSettings& settings, const ContactLaw& law)
    : settings_(settings), law_(law), island_(settings) {
  if (law_.crushing && !island_.solves())
    throw std::invalid_argument("the crushing contact law needs a contact method that takes it (solver.method = "
                                "\"apgd\", \"newton\" or \"pgs_cone\"): the sweeps over Bullet's rows do not");
}

// A manifold's place in the canonical order: the pair of bodies it joins (their user index 2:
// ice bodies by their index in World::floes(), fixed ones negative), lower first, then the
// child shapes its first point names on each (the structure's hull pieces). Bullet's own
// order follows the history of its arrays, which a world rebuilt from a checkpoint does not
// share; in this order the rows are the same in both.
namespace {
std::tuple<int, int, int, int> ordered(int a, int b, int ia, int ib) {
  return a <= b ? std::make_tuple(a, b, ia, ib) : std::make_tuple(b, a, ib, ia);
}
}  // namespace

std::tuple<int, int, int, int> ContactSolver::canonical(const btPersistentManifold* m) {
  if (!m->getNumContacts()) return ordered(m->getBody0()->getUserIndex2(), m->getBody1()->getUserIndex2(), -1, -1);
  return canonical(m->getBody0(), m->getBody1(), m->getContactPoint(0));
}

std::tuple<int, int, int, int> ContactSolver::canonical(const btCollisionObject* a, const btCollisionObject* b,
                                                        const btManifoldPoint& first) {
  return ordered(a->getUserIndex2(), b->getUserIndex2(), first.m_index0, first.m_index1);
}

const btVector3* ContactSolver::remembered_friction(const btManifoldPoint* point) const {
  const auto it = friction_current_.find(point);
  // a point Bullet has since replaced in its slot is not the one remembered
  if (it == friction_current_.end() || it->second.normal_impulse != point->m_appliedImpulse) return nullptr;
  return &it->second.tangent;
}

void ContactSolver::remember_friction(const btManifoldPoint* point, const btVector3& impulse) {
  friction_current_[point] = FrictionMemory{point->m_appliedImpulse, impulse};
}

btScalar ContactSolver::solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds,
                                   int numManifolds, btTypedConstraint** constraints, int numConstraints,
                                   const btContactSolverInfo& info, btIDebugDraw* debug, btDispatcher* dispatcher) {
  if (settings_.order != SweepOrder::kBullet)
    std::sort(bodies, bodies + numBodies, [](const btCollisionObject* a, const btCollisionObject* b) {
      return a->getUserIndex2() < b->getUserIndex2();
    });
  return btSequentialImpulseConstraintSolver::solveGroup(bodies, numBodies, manifolds, numManifolds, constraints,
                                                         numConstraints, info, debug, dispatcher);
}

void ContactSolver::set_contact_bound(ContactBound* bound) {
  if (bound && !takes_crushing(settings_.method))
    throw std::invalid_argument("a bound on contact rows needs a contact method that takes it (solver.method = "
                                "\"apgd\", \"newton\" or \"pgs_cone\"): neither the sweeps over Bullet's rows nor the "
                                "interior-point method takes it");
  bound_ = bound;
}

void ContactSolver::prepareSolve(int numBodies, int numManifolds) {
  btSequentialImpulseConstraintSolver::prepareSolve(numBodies, numManifolds);
  if (bound_) bound_->begin_step();
  std::swap(friction_previous_, friction_current_);
  friction_current_.clear();
  friction_current_.reserve(friction_previous_.size());
  crushed_.next_step();
}

void ContactSolver::convertContacts(btPersistentManifold** manifolds, int numManifolds,
                                    const btContactSolverInfo& info) {
  structure_rows_.clear();
  normal_caps_.clear();
  bound_rows_.clear();
  crushing_manifolds_.clear();
  two_directions_ = info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS;
  sorted_manifolds_.assign(manifolds, manifolds + numManifolds);
  if (settings_.order != SweepOrder::kBullet)
    std::sort(sorted_manifolds_.begin(), sorted_manifolds_.end(),
              [](const btPersistentManifold* a, const btPersistentManifold* b) { return canonical(a) < canonical(b); });
  if (bound_) bound_->prepare(sorted_manifolds_.data(), static_cast<int>(sorted_manifolds_.size()), info.m_timeStep);
  for (btPersistentManifold* m : sorted_manifolds_) {
    btPersistentManifold& manifold = *m;
    const int first = m_tmpSolverContactConstraintPool.size();
    convertContact(&manifold, info);  // Bullet's own set-up of the rows, normal impulses warm-started
    const int end = m_tmpSolverContactConstraintPool.size();
    const bool on_structure = structure_ && (manifold.getBody0() == structure_ || manifold.getBody1() == structure_);
    if (law_.static_friction.any()) stick_or_slip(manifold, first, on_structure);
    if (settings_.friction_warm_start) warm_start_friction(first, info);
    // crushing: the pair's normal force is at most crushing_force, shared by its points
    if (law_.crushing_force > 0 && end > first)
      for (int r = first; r < end; ++r)
        m_tmpSolverContactConstraintPool[r].m_upperLimit = law_.crushing_force * info.m_timeStep / (end - first);
    // crushing: each row carries at most its share of what the overlap bears, and the crushed
    // ice stays: the position pass pushes out only the overlap beyond it (crushing_contact.hpp)
    if (law_.crushing) {
      normal_caps_.resize(end, std::numeric_limits<double>::infinity());
      if (const auto cap = crushing_cap(manifold, *law_.crushing, info.m_timeStep, law_.crushing_scope)) {
        const double crushed = crushed_.depth(manifold);
        for (int r = first; r < end; ++r) {
          normal_caps_[r] = *cap;
          push_beyond(m_tmpSolverContactConstraintPool[r], crushed, info);
        }
        crushing_manifolds_.push_back({&manifold, first, end});
      }
    }
    // a stage's bound on its rows (contact_bound.hpp): the lower of it and the law's
    if (bound_ && end > first) {
      normal_caps_.resize(end, kUnbounded);
      for (int r = first; r < end; ++r) {
        const std::optional<double> cap = bound_->cap(*bound_point(r));
        if (!cap) continue;
        normal_caps_[r] = std::min(normal_caps_[r], *cap);
        bound_rows_.push_back(r);
      }
    }
    if (on_structure) {
      const double sign = manifold.getBody0() == structure_ ? 1.0 : -1.0;
      for (int r = first; r < end; ++r) structure_rows_.push_back({r, sign});
    }
  }
}

// A spring joint's row (dem/world/joint_springs.hpp): Bullet wrote it as
//   rhs = (erp e / h - J v_free) jacDiagABInv,  cfm = the constraint's stop CFM,
// the row solved when J v = erp e / h - (cfm / jacDiagABInv) l. The spring K asks for
//   J v = e / h - l / (h^2 K):
// the error read back through the joint's erp, the compliance 1 / (h^2 K) written as
// cfm = jacDiagABInv / (h^2 K). J v_free is computed as Bullet does (convertJoint).
void ContactSolver::convertJoints(btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info) {
  sorted_joints_.assign(constraints, constraints + numConstraints);
  if (settings_.order != SweepOrder::kBullet)
    std::sort(sorted_joints_.begin(), sorted_joints_.end(), [](const btTypedConstraint* a, const btTypedConstraint* b) {
      return a->getUserConstraintId() < b->getUserConstraintId();
    });
  btSequentialImpulseConstraintSolver::convertJoints(sorted_joints_.data(), numConstraints, info);
  const double h = info.m_timeStep;
  for (int r = 0; r < m_tmpSolverNonContactConstraintPool.size(); ++r) {
    btSolverConstraint& row = m_tmpSolverNonContactConstraintPool[r];
    const auto* joint = dynamic_cast<const SpringJoint*>(static_cast<btTypedConstraint*>(row.m_originalContactPoint));
    if (!joint || row.m_jacDiagABInv == 0) continue;
    const btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
    const btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
    // which of A's axes the row acts along (linear rows) or about (angular rows: no linear part)
    const bool angular = row.m_contactNormal1.length2() == 0;
    const btVector3 world_axis = angular ? row.m_relpos1CrossNormal : row.m_contactNormal1;
    const btVector3 local = joint->getRigidBodyA().getWorldTransform().getBasis().transpose() * world_axis;
    const int axis = local.absolute().maxAxis();
    const double K = joint->springs()(angular ? 3 + axis : axis);
    auto free = [](const btSolverBody& s, const btVector3& n, const btVector3& rn) {
      if (!s.m_originalBody) return 0.0;
      return double(n.dot(s.m_linearVelocity + s.m_externalForceImpulse) +
                    rn.dot(s.m_angularVelocity + s.m_externalTorqueImpulse));
    };
    const double jv_free = free(a, row.m_contactNormal1, row.m_relpos1CrossNormal) +
                           free(b, row.m_contactNormal2, row.m_relpos2CrossNormal);
    const double error_rate = (row.m_rhs / row.m_jacDiagABInv + jv_free) / joint->erp();  // e / h
    row.m_rhs = (error_rate - jv_free) * row.m_jacDiagABInv;
    row.m_cfm = row.m_jacDiagABInv / (h * h * K);
  }
}

// Static friction: each contact row of the manifold (from `first_row`) and its friction rows
// get the static coefficient if the contact sticks (dem/world/static_friction.hpp). Bullet set
// them all to the point's combined (kinetic) coefficient; the friction warm start, the sweeps,
// the crushing limit and the captured problem all read the rows.
void ContactSolver::stick_or_slip(const btPersistentManifold& manifold, int first_row, bool on_structure) {
  const int per_contact = two_directions_ ? 2 : 1;
  for (int r = first_row; r < m_tmpSolverContactConstraintPool.size(); ++r) {
    btSolverConstraint& contact = m_tmpSolverContactConstraintPool[r];
    const auto& point = *static_cast<const btManifoldPoint*>(contact.m_originalContactPoint);
    const double slip = slip_speed(*manifold.getBody0(), *manifold.getBody1(), point);
    const btScalar mu = contact_friction(law_.static_friction, contact.m_friction, on_structure, slip);
    contact.m_friction = mu;
    for (int k = 0; k < per_contact; ++k) m_tmpSolverContactFrictionConstraintPool[contact.m_frictionIndex + k].m_friction = mu;
  }
}

// Bullet sets a contact's friction rows up from zero every step, along directions
// it recomputes from the relative velocity. In a pack at rest or creeping, friction
// carries much of the load, and starting it from zero every step means the sweeps
// of every step must first rebuild it. Here the friction impulse vector the point
// ended the last step with is projected onto the new directions, scaled like the
// normal impulse (warm-starting factor) and kept inside the friction cone.
void ContactSolver::warm_start_friction(int first_row, const btContactSolverInfo& info) {
  const bool two = two_directions_;
  for (int r = first_row; r < m_tmpSolverContactConstraintPool.size(); ++r) {
    const btSolverConstraint& contact = m_tmpSolverContactConstraintPool[r];
    const auto* point = static_cast<const btManifoldPoint*>(contact.m_originalContactPoint);
    const auto it = friction_previous_.find(point);
    // a point Bullet refreshed keeps its normal impulse exactly; anything else is another point
    if (it == friction_previous_.end() || it->second.normal_impulse != point->m_appliedImpulse) continue;
    const btVector3 t = it->second.tangent * info.m_warmstartingFactor;
    btScalar l1 = t.dot(point->m_lateralFrictionDir1);
    btScalar l2 = two ? t.dot(point->m_lateralFrictionDir2) : btScalar(0);
    const btScalar limit = contact.m_friction * contact.m_appliedImpulse;  // the warm normal impulse
    const btScalar size = std::sqrt(l1 * l1 + l2 * l2);
    if (size > limit) {
      const btScalar s = size > 0 ? limit / size : btScalar(0);
      l1 *= s;
      l2 *= s;
    }
    for (int k = 0; k < (two ? 2 : 1); ++k) {
      btSolverConstraint& f = m_tmpSolverContactFrictionConstraintPool[contact.m_frictionIndex + k];
      f.m_appliedImpulse = k == 0 ? l1 : l2;
      btSolverBody& a = m_tmpSolverBodyPool[f.m_solverBodyIdA];
      btSolverBody& b = m_tmpSolverBodyPool[f.m_solverBodyIdB];
      if (a.m_originalBody)
        a.internalApplyImpulse(f.m_contactNormal1 * a.internalGetInvMass(), f.m_angularComponentA, f.m_appliedImpulse);
      if (b.m_originalBody)
        b.internalApplyImpulse(f.m_contactNormal2 * b.internalGetInvMass(), f.m_angularComponentB, f.m_appliedImpulse);
    }
  }
}

// Bullet's row corrects the point's whole overlap, in the position pass (split impulse) or in the
// velocity row (Baumgarte), at the rate erp: here only the overlap deeper than `crushed`
void ContactSolver::push_beyond(btSolverConstraint& row, double crushed, const btContactSolverInfo& info) {
  const auto& point = *static_cast<const btManifoldPoint*>(row.m_originalContactPoint);
  const double penetration = point.getDistance() + info.m_linearSlop;
  if (penetration >= 0) return;  // no overlap: Bullet's row has no position term
  const bool split = info.m_splitImpulse && penetration <= info.m_splitImpulsePenetrationThreshold;
  const double rate = (split ? info.m_erp2 : info.m_erp) / info.m_timeStep * row.m_jacDiagABInv;
  const double whole = -penetration * rate, beyond = std::max(0.0, -penetration - crushed) * rate;
  if (split)
    row.m_rhsPenetration = beyond;
  else
    row.m_rhs += beyond - whole;
}

void ContactSolver::build_order(bool from_structure) {
  const int n = m_tmpSolverContactConstraintPool.size();
  order_.resize(n);
  std::iota(order_.begin(), order_.end(), 0);
  if (!from_structure || !structure_) return;
  // horizontal distance of each contact point from the structure axis
  const btVector3 axis = structure_->getWorldTransform().getOrigin();
  std::vector<double> distance(n);
  for (int r = 0; r < n; ++r) {
    const auto* p = static_cast<const btManifoldPoint*>(m_tmpSolverContactConstraintPool[r].m_originalContactPoint);
    const btVector3 d = p->getPositionWorldOnB() - axis;
    distance[r] = d.x() * d.x() + d.z() * d.z();
  }
  std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) { return distance[a] < distance[b]; });
}

btVector3 ContactSolver::structure_impulse() const {
  btVector3 p(0, 0, 0);
  for (const StructureRow& s : structure_rows_) p += row_impulse(s.row) * s.sign;
  return p;
}

void ContactSolver::measure_bodies() {
  const int n = m_tmpSolverBodyPool.size();
  bodies_.resize(n);
  for (int b = 0; b < n; ++b) {
    const btRigidBody* rb = m_tmpSolverBodyPool[b].m_originalBody;
    BodyScale& s = bodies_[b];
    s.mass = rb && rb->getInvMass() > 0 ? 1.0 / rb->getInvMass() : 0.0;  // 0: fixed or kinematic
    s.radius = 0.0;
    if (s.mass > 0) {
      btVector3 centre;
      btScalar radius;
      rb->getCollisionShape()->getBoundingSphere(centre, radius);
      s.radius = radius;
    }
  }
}

void ContactSolver::remember_velocities() {
  for (int b = 0; b < m_tmpSolverBodyPool.size(); ++b) {
    bodies_[b].linear = m_tmpSolverBodyPool[b].internalGetDeltaLinearVelocity();
    bodies_[b].angular = m_tmpSolverBodyPool[b].internalGetDeltaAngularVelocity();
  }
}

// the net impulse a sweep added to a body, as m (|dv| + r |dw|): its velocity change at
// its rim times its mass. Unlike single contact impulses, which drift between the
// redundant points of a face without changing anything, it is unique at convergence
double ContactSolver::largest_body_impulse_change() const {
  double largest = 0.0;
  for (int b = 0; b < m_tmpSolverBodyPool.size(); ++b) {
    const BodyScale& s = bodies_[b];
    if (s.mass == 0) continue;
    const btSolverBody& body = m_tmpSolverBodyPool[b];
    const double dv = (body.m_deltaLinearVelocity - s.linear).length();
    const double dw = (body.m_deltaAngularVelocity - s.angular).length();
    largest = std::max(largest, s.mass * (dv + s.radius * dw));
  }
  return largest;
}

double ContactSolver::sweep(int iteration, bool contacts, bool reverse) {
  // joints, as Bullet sweeps them: each row its own count (m_overrideNumSolverIterations)
  for (int j = 0; j < m_tmpSolverNonContactConstraintPool.size(); ++j) {
    btSolverConstraint& c = m_tmpSolverNonContactConstraintPool[m_orderNonContactConstraintPool[j]];
    if (iteration < c.m_overrideNumSolverIterations)
      resolveSingleConstraintRowGeneric(m_tmpSolverBodyPool[c.m_solverBodyIdA], m_tmpSolverBodyPool[c.m_solverBodyIdB], c);
  }
  if (!contacts) return 0.0;
  // (Bullet also calls btTypedConstraint::solveConstraintObsolete here, a no-op for every
  // constraint icedem uses)
  const int n = static_cast<int>(order_.size());
  double change = 0.0;  // largest change of a row's impulse: zero only if nothing moved
  // normal rows first, then friction rows, as Bullet does without SOLVER_INTERLEAVE_...
  for (int k = 0; k < n; ++k) {
    btSolverConstraint& c = m_tmpSolverContactConstraintPool[order_[reverse ? n - 1 - k : k]];
    const btScalar before = c.m_appliedImpulse;
    if (law_.crushing_force > 0)  // Bullet's contact row clamps only below
      resolveSingleConstraintRowGeneric(m_tmpSolverBodyPool[c.m_solverBodyIdA], m_tmpSolverBodyPool[c.m_solverBodyIdB], c);
    else
      resolveSingleConstraintRowLowerLimit(m_tmpSolverBodyPool[c.m_solverBodyIdA], m_tmpSolverBodyPool[c.m_solverBodyIdB], c);
    change = std::max(change, double(std::abs(c.m_appliedImpulse - before)));
  }
  const int per_contact = two_directions_ ? 2 : 1;
  for (int k = 0; k < n; ++k) {
    const btSolverConstraint& contact = m_tmpSolverContactConstraintPool[order_[reverse ? n - 1 - k : k]];
    const btScalar normal = contact.m_appliedImpulse;
    for (int d = 0; d < per_contact; ++d) {
      btSolverConstraint& f = m_tmpSolverContactFrictionConstraintPool[contact.m_frictionIndex + d];
      // Bullet leaves a row alone while its contact carries no load; a warm-started
      // friction impulse must then be taken back (Coulomb: no normal force, no friction)
      if (normal <= 0 && !settings_.friction_warm_start) continue;
      const btScalar before = f.m_appliedImpulse;
      f.m_lowerLimit = -(f.m_friction * std::max(normal, btScalar(0)));
      f.m_upperLimit = f.m_friction * std::max(normal, btScalar(0));
      resolveSingleConstraintRowGeneric(m_tmpSolverBodyPool[f.m_solverBodyIdA], m_tmpSolverBodyPool[f.m_solverBodyIdB], f);
      change = std::max(change, double(std::abs(f.m_appliedImpulse - before)));
    }
  }
  return change;
}

void ContactSolver::solveGroupCacheFriendlySplitImpulseIterations(btCollisionObject**, int, btPersistentManifold**,
                                                                   int, btTypedConstraint**, int,
                                                                   const btContactSolverInfo& info, btIDebugDraw*) {
  if (!info.m_splitImpulse) return;
  const int n = static_cast<int>(order_.size());
  // the position pass: pseudo-impulses that remove penetration, swept like the contacts
  double previous = 0.0;
  for (int iteration = 0; iteration < settings_.position_iterations; ++iteration) {
    const bool reverse = settings_.order == SweepOrder::kFromStructure && iteration % 2 == 1;
    double change = 0.0, largest = 0.0;
    for (int k = 0; k < n; ++k) {
      btSolverConstraint& c = m_tmpSolverContactConstraintPool[order_[reverse ? n - 1 - k : k]];
      const btScalar before = c.m_appliedPushImpulse;
      resolveSplitPenetrationImpulse(m_tmpSolverBodyPool[c.m_solverBodyIdA], m_tmpSolverBodyPool[c.m_solverBodyIdB], c);
      change = std::max(change, double(std::abs(c.m_appliedPushImpulse - before)));
      largest = std::max(largest, double(c.m_appliedPushImpulse));
    }
    // Bullet stops when nothing changed; with a tolerance, when the error left is small
    const double relative = change / std::max(largest, kImpulseFloor);
    if (change == 0.0 || remaining_error(relative, previous, iteration + 1) <= settings_.tolerance) break;
    previous = relative;
  }
}

btScalar ContactSolver::solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                                          btPersistentManifold** manifolds, int numManifolds,
                                                          btTypedConstraint** constraints, int numConstraints,
                                                          const btContactSolverInfo& info, btIDebugDraw* debug) {
  const bool from_structure = settings_.order == SweepOrder::kFromStructure;
  build_order(from_structure);
  measure_bodies();
  solveGroupCacheFriendlySplitImpulseIterations(bodies, numBodies, manifolds, numManifolds, constraints,
                                                numConstraints, info, debug);

  // the method solves an island's contacts and joints together; a lattice alone too
  if (island_.solves() && (!order_.empty() || m_tmpSolverNonContactConstraintPool.size() > 0)) {
    solve_with_method(info);
    return 0.f;
  }

  int joint_sweeps = 0;
  for (int j = 0; j < m_tmpSolverNonContactConstraintPool.size(); ++j)
    joint_sweeps = std::max(joint_sweeps, m_tmpSolverNonContactConstraintPool[j].m_overrideNumSolverIterations);
  const int cap = info.m_numIterations;
  const bool has_contacts = !order_.empty();
  std::optional<ContactProblem> problem;
  if (observer_ && has_contacts && observer_->wants_problems()) {
    problem = capture_problem(info);
    problem->island = report_.islands;
  }

  int contact_sweeps = 0;
  double residual = 0.0, previous_change = 0.0;
  bool contacts_done = !has_contacts;
  btVector3 load = structure_impulse();
  for (int iteration = 0; !contacts_done || iteration < joint_sweeps; ++iteration) {
    const bool contacts = !contacts_done;
    // without a tolerance only the last two sweeps are measured: the residual reported
    // is the last one's (and its rate needs the one before)
    const bool measure = contacts && (settings_.tolerance > 0 || contact_sweeps + 2 >= cap);
    if (measure) remember_velocities();
    const double impulse_change = sweep(iteration, contacts, from_structure && iteration % 2 == 1);
    if (!contacts) continue;
    ++contact_sweeps;
    const btVector3 now = structure_impulse();
    if (measure) {
      // the relative change of this sweep, and from it and the last one the error left
      double largest_normal = 0.0;
      for (int r : order_) largest_normal = std::max(largest_normal, double(m_tmpSolverContactConstraintPool[r].m_appliedImpulse));
      const double change = std::max((now - load).length() / std::max(double(now.length()), kImpulseFloor),
                                     largest_body_impulse_change() / std::max(largest_normal, kImpulseFloor));
      residual = remaining_error(change, previous_change, contact_sweeps);
      previous_change = change;
    }
    load = now;
    if (impulse_change == 0.0 || (measure && residual <= settings_.tolerance) || contact_sweeps >= cap)
      contacts_done = true;
  }
  if (has_contacts) {
    const bool capped = residual > settings_.tolerance && contact_sweeps >= cap;
    report_.add_island(contact_sweeps, residual, capped);
    if (problem) {
      SolverAnswer answer = row_impulses();
      answer.sweeps = contact_sweeps;
      answer.residual = residual;
      answer.capped = capped;
      observer_->solved(*problem, answer);
    }
  }
  return 0.f;
}

void ContactSolver::solve_with_method(const btContactSolverInfo& info) {
  ContactProblem problem = capture_problem(info);
  problem.island = report_.islands;
  SolverAnswer answer = island_.solve(problem, report_);
  apply_impulses(answer);
  // a stage's bound on sums of rows (contact_bound.hpp): their caps lowered to the rows' shares, the island solved
  // again from the answer (each pass holds the sums it lowered; kBoundPasses solves in all)
  for (int pass = 1; !bound_rows_.empty() && pass < kBoundPasses && bound_->tighten(bounded_impulses()); ++pass) {
    for (int r : bound_rows_) normal_caps_[r] = std::min(normal_caps_[r], *bound_->cap(*bound_point(r)));
    problem = capture_problem(info);
    problem.island = report_.islands;
    answer = island_.solve(problem, report_);
    apply_impulses(answer);
  }
  if (observer_ && observer_->wants_problems()) observer_->solved(problem, answer);
}

const btManifoldPoint* ContactSolver::bound_point(int row) const {
  return static_cast<const btManifoldPoint*>(m_tmpSolverContactConstraintPool[row].m_originalContactPoint);
}

std::vector<BoundedImpulse> ContactSolver::bounded_impulses() const {
  std::vector<BoundedImpulse> out;
  out.reserve(bound_rows_.size());
  for (int r : bound_rows_)
    out.push_back({bound_point(r), m_tmpSolverContactConstraintPool[r].m_appliedImpulse, row_impulse(r)});
  return out;
}

// the normal's impulse, then each friction direction's added to it: the order the structure's load has always been
// summed in, so that it stays the same to the last bit
btVector3 ContactSolver::row_impulse(int r) const {
  const btSolverConstraint& c = m_tmpSolverContactConstraintPool[r];
  const auto* point = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
  const auto& friction = m_tmpSolverContactFrictionConstraintPool;
  btVector3 sum = point->m_normalWorldOnB * c.m_appliedImpulse;
  sum += point->m_lateralFrictionDir1 * friction[c.m_frictionIndex].m_appliedImpulse;
  if (two_directions_) sum += point->m_lateralFrictionDir2 * friction[c.m_frictionIndex + 1].m_appliedImpulse;
  return sum;
}

btVector3 ContactSolver::friction_impulse(int r) const {
  const btSolverConstraint& c = m_tmpSolverContactConstraintPool[r];
  const auto* point = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
  const auto& friction = m_tmpSolverContactFrictionConstraintPool;
  btVector3 t = point->m_lateralFrictionDir1 * friction[c.m_frictionIndex].m_appliedImpulse;
  if (two_directions_) t += point->m_lateralFrictionDir2 * friction[c.m_frictionIndex + 1].m_appliedImpulse;
  return t;
}

void ContactSolver::apply_impulses(const SolverAnswer& answer) {
  auto set = [&](btSolverConstraint& c, double impulse) {
    const btScalar change = impulse - c.m_appliedImpulse;
    btSolverBody& a = m_tmpSolverBodyPool[c.m_solverBodyIdA];
    btSolverBody& b = m_tmpSolverBodyPool[c.m_solverBodyIdB];
    a.internalApplyImpulse(c.m_contactNormal1 * a.internalGetInvMass(), c.m_angularComponentA, change);
    b.internalApplyImpulse(c.m_contactNormal2 * b.internalGetInvMass(), c.m_angularComponentB, change);
    c.m_appliedImpulse = impulse;
  };
  for (int c = 0; c < m_tmpSolverContactConstraintPool.size(); ++c) {
    btSolverConstraint& normal = m_tmpSolverContactConstraintPool[c];
    set(normal, answer.r(3 * c));
    for (int k = 0; k < 2; ++k)
      set(m_tmpSolverContactFrictionConstraintPool[normal.m_frictionIndex + k], answer.r(3 * c + 1 + k));
  }
  for (int j = 0; j < m_tmpSolverNonContactConstraintPool.size(); ++j)
    set(m_tmpSolverNonContactConstraintPool[j], answer.l(j));
}

SolverAnswer ContactSolver::row_impulses() const {
  SolverAnswer a;
  const int contacts = m_tmpSolverContactConstraintPool.size();
  a.r.resize(3 * contacts);
  for (int c = 0; c < contacts; ++c) {
    const btSolverConstraint& normal = m_tmpSolverContactConstraintPool[c];
    a.r(3 * c) = normal.m_appliedImpulse;
    for (int k = 0; k < 2; ++k)
      a.r(3 * c + 1 + k) =
          two_directions_ || k == 0 ? m_tmpSolverContactFrictionConstraintPool[normal.m_frictionIndex + k].m_appliedImpulse : 0.0;
  }
  a.l.resize(m_tmpSolverNonContactConstraintPool.size());
  for (int j = 0; j < m_tmpSolverNonContactConstraintPool.size(); ++j)
    a.l(j) = m_tmpSolverNonContactConstraintPool[j].m_appliedImpulse;
  return a;
}

void ContactSolver::convertBodies(btCollisionObject** bodies, int numBodies, const btContactSolverInfo& info) {
  btSequentialImpulseConstraintSolver::convertBodies(bodies, numBodies, info);
  // A row's linear part is its direction times the solver body's inverse mass, which Bullet scales
  // by the linear factor, and its angular part I^-1 tau scaled by the angular factor; applying an
  // impulse then scales both by the factors again. Factors of 0 and 1 (all Bullet's users set) do
  // not mind; the water's added mass (dem/water/added_mass.hpp) sets others, so the solver bodies'
  // own factors are made 1 and each factor acts once, as it does on forces
  for (int b = 0; b < m_tmpSolverBodyPool.size(); ++b) {
    btSolverBody& body = m_tmpSolverBodyPool[b];
    body.m_linearFactor = btVector3(1, 1, 1);
    body.m_angularFactor = btVector3(1, 1, 1);
  }
}

btScalar ContactSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int numBodies,
                                                      const btContactSolverInfo& info) {
  // which crushing manifolds crushed: a row at its bound (within the merit's relative tolerance, to
  // which the method solves) closes, and the overlap it reaches over the step is crushed ice
  for (const CrushingRows& m : crushing_manifolds_) {
    bool crushing = false;
    for (int r = m.first; r < m.end && !crushing; ++r)
      crushing = m_tmpSolverContactConstraintPool[r].m_appliedImpulse >= (1.0 - kAtBound) * normal_caps_[r];
    crushed_.set_crushing(*m.manifold, crushing);
  }
  // remember each point's friction impulse as a world vector for the next step
  if (settings_.friction_warm_start) {
    for (int r = 0; r < m_tmpSolverContactConstraintPool.size(); ++r) {
      const btSolverConstraint& c = m_tmpSolverContactConstraintPool[r];
      const auto* point = static_cast<const btManifoldPoint*>(c.m_originalContactPoint);
      friction_current_[point] = FrictionMemory{c.m_appliedImpulse, friction_impulse(r)};
    }
  }
  return btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, numBodies, info);
}

}  // namespace icedem
