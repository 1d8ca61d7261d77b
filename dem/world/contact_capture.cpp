// The contact problem of the island Bullet is about to solve, read off the
// solver's rows (dem/contact/problem.hpp defines the problem).
//
// Bullet's sequential-impulse rows hold each constraint as a Jacobian (linear and
// angular part on bodies A and B), a right-hand side rhs, a diagonal jacDiagABInv
// and a softness cfm; a sweep updates a row's impulse l by
//   dl = rhs - cfm l - jacDiagABInv (J dv),
// dv being the velocity change the impulses made so far. A row is solved when dl
// = 0, i.e. J dv + (cfm / jacDiagABInv) l = rhs / jacDiagABInv. Bullet builds rhs
// from the body velocities before contact, v_free = v + h M^-1 f (its
// "external impulse"), and what the row asks of the velocity (a gap to close, an
// error to correct), so with v = v_free + dv the row reads
//   J v + b + C l = 0,  b = -(J v_free + rhs / jacDiagABInv),  C = cfm / jacDiagABInv:
// b is the problem's w for a contact row (u = J v + w) and its bias for a joint row.
// Only the rows of bodies with finite mass count in J v_free: a fixed or kinematic
// body's velocity is already inside rhs.
//
// Contact rows: one normal row and two friction rows per contact point
// (SOLVER_USE_2_FRICTION_DIRECTIONS), the friction rows along Bullet's tangent
// directions, the friction coefficient on the normal row. Bullet bounds each
// friction row by +-mu l_N on its own (a square, not Coulomb's disc):
// box_friction says so. With split impulse, the penetration correction is a
// separate pseudo-velocity pass and not part of this problem.
// Joint rows: btFixedConstraint's six locked axes, unbounded; a joint row with
// finite bounds is not an equality and is refused.
#include <cmath>
#include <stdexcept>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>

#include "dem/world/bullet_eigen.hpp"
#include "dem/world/contact_solver.hpp"

namespace icedem {
namespace {

// the problem body of a solver body, -1 for a body without unknown velocity
int dof_index(const btSolverBody& body, const std::vector<int>& index_of, int solver_index) {
  return body.m_originalBody && body.m_originalBody->getInvMass() > 0 ? index_of[solver_index] : -1;
}

RowJacobian row_on_a(const btSolverConstraint& c) {
  RowJacobian j;
  j << c.m_contactNormal1.x(), c.m_contactNormal1.y(), c.m_contactNormal1.z(), c.m_relpos1CrossNormal.x(),
      c.m_relpos1CrossNormal.y(), c.m_relpos1CrossNormal.z();
  return j;
}

RowJacobian row_on_b(const btSolverConstraint& c) {
  RowJacobian j;
  j << c.m_contactNormal2.x(), c.m_contactNormal2.y(), c.m_contactNormal2.z(), c.m_relpos2CrossNormal.x(),
      c.m_relpos2CrossNormal.y(), c.m_relpos2CrossNormal.z();
  return j;
}

}  // namespace

ContactProblem ContactSolver::capture_problem(const btContactSolverInfo& info) const {
  if (!two_directions_ && m_tmpSolverContactConstraintPool.size() > 0)
    throw std::logic_error("capture_problem: needs two friction directions per contact");
  if (m_tmpSolverContactRollingFrictionConstraintPool.size() > 0)
    throw std::logic_error("capture_problem: rolling friction rows are not part of the problem");

  ContactProblem p;
  p.dt = info.m_timeStep;
  p.box_friction = true;

  // bodies with finite mass, in solver order
  std::vector<int> index_of(m_tmpSolverBodyPool.size(), -1);
  p.bodies.reserve(m_tmpSolverBodyPool.size());
  for (int s = 0; s < m_tmpSolverBodyPool.size(); ++s) {
    const btSolverBody& body = m_tmpSolverBodyPool[s];
    const btRigidBody* rb = body.m_originalBody;
    if (!rb || rb->getInvMass() <= 0) continue;
    // a body's linear and angular factors scale its response along the world's axes: the water's
    // added mass (dem/water/added_mass.hpp), a larger mass along those axes. A factor of 0 (motion
    // locked along an axis) has no mass to stand for it
    const btVector3 lf = rb->getLinearFactor(), af = rb->getAngularFactor();
    if (lf.x() <= 0 || lf.y() <= 0 || lf.z() <= 0 || af.x() <= 0 || af.y() <= 0 || af.z() <= 0)
      throw std::logic_error("capture_problem: a body with motion locked along an axis has no place in the problem");
    index_of[s] = static_cast<int>(p.bodies.size());
    ProblemBody b;
    b.mass = 1.0 / rb->getInvMass();
    b.added_mass = Eigen::Vector3d(b.mass / lf.x() - b.mass, b.mass / lf.y() - b.mass, b.mass / lf.z() - b.mass);
    const btMatrix3x3& inv = rb->getInvInertiaTensorWorld();
    Eigen::Matrix3d inv_inertia;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) inv_inertia(i, j) = inv[i][j];
    // Bullet's solver scales I^-1 tau by the angular factor, axis by axis; the problem's inertia is
    // that map's inverse, symmetrised (it is symmetric already for a flat floe with equal roll and
    // pitch factors, whose yaw leaves them alone)
    if (af == btVector3(1, 1, 1)) {
      b.inertia = inv_inertia.inverse();  // as it was: symmetrising would move the last bits of every run
    } else {
      const Eigen::Matrix3d scaled = Eigen::Vector3d(af.x(), af.y(), af.z()).asDiagonal() * inv_inertia;
      b.inertia = (0.5 * (scaled + scaled.transpose())).inverse();
    }
    b.free_velocity << to_eigen(body.m_linearVelocity + body.m_externalForceImpulse),
        to_eigen(body.m_angularVelocity + body.m_externalTorqueImpulse);
    b.id = rb->getUserIndex2();
    p.bodies.push_back(b);
  }

  // J v_free over the bodies with unknown velocity, and the row's b (see above)
  auto offset = [&](const btSolverConstraint& c, int a, int b) {
    double jv = 0.0;
    if (a >= 0) jv += row_on_a(c).dot(p.bodies[a].free_velocity);
    if (b >= 0) jv += row_on_b(c).dot(p.bodies[b].free_velocity);
    return -(jv + c.m_rhs / c.m_jacDiagABInv);
  };

  p.contacts.reserve(m_tmpSolverContactConstraintPool.size());
  for (int r = 0; r < m_tmpSolverContactConstraintPool.size(); ++r) {
    const btSolverConstraint& normal = m_tmpSolverContactConstraintPool[r];
    ProblemContact c;
    c.a = dof_index(m_tmpSolverBodyPool[normal.m_solverBodyIdA], index_of, normal.m_solverBodyIdA);
    c.b = dof_index(m_tmpSolverBodyPool[normal.m_solverBodyIdB], index_of, normal.m_solverBodyIdB);
    c.mu = normal.m_friction;
    const btSolverConstraint* rows[3] = {&normal, &m_tmpSolverContactFrictionConstraintPool[normal.m_frictionIndex],
                                         &m_tmpSolverContactFrictionConstraintPool[normal.m_frictionIndex + 1]};
    for (int k = 0; k < 3; ++k) {
      if (c.a >= 0) c.ja.row(k) = row_on_a(*rows[k]);
      if (c.b >= 0) c.jb.row(k) = row_on_b(*rows[k]);
      c.w(k) = offset(*rows[k], c.a, c.b);
      c.guess(k) = rows[k]->m_appliedImpulse;
      if (rows[k]->m_cfm != 0.0) throw std::logic_error("capture_problem: soft contact rows are not supported");
    }
    const btRigidBody* body_a = m_tmpSolverBodyPool[normal.m_solverBodyIdA].m_originalBody;
    const btRigidBody* body_b = m_tmpSolverBodyPool[normal.m_solverBodyIdB].m_originalBody;
    c.on_structure = structure_ && (body_a == structure_ || body_b == structure_);
    if (r < static_cast<int>(normal_caps_.size())) c.normal_cap = normal_caps_[r];
    p.contacts.push_back(c);
  }

  p.joints.reserve(m_tmpSolverNonContactConstraintPool.size());
  for (int r = 0; r < m_tmpSolverNonContactConstraintPool.size(); ++r) {
    const btSolverConstraint& row = m_tmpSolverNonContactConstraintPool[r];
    // Bullet's unbounded is SIMD_INFINITY (DBL_MAX in double precision)
    if (row.m_lowerLimit > -SIMD_INFINITY || row.m_upperLimit < SIMD_INFINITY)
      throw std::logic_error("capture_problem: a joint row with bounds is not an equality");
    ProblemJointRow j;
    j.a = dof_index(m_tmpSolverBodyPool[row.m_solverBodyIdA], index_of, row.m_solverBodyIdA);
    j.b = dof_index(m_tmpSolverBodyPool[row.m_solverBodyIdB], index_of, row.m_solverBodyIdB);
    if (j.a >= 0) j.ja = row_on_a(row);
    if (j.b >= 0) j.jb = row_on_b(row);
    j.bias = offset(row, j.a, j.b);
    j.compliance = row.m_cfm / row.m_jacDiagABInv;
    j.guess = row.m_appliedImpulse;
    const auto* constraint = static_cast<const btTypedConstraint*>(row.m_originalContactPoint);
    j.joint = constraint ? constraint->getUserConstraintId() : -1;
    p.joints.push_back(j);
  }
  return p;
}

}  // namespace icedem
