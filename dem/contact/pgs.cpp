// Projected Gauss-Seidel on a ContactProblem: the row updates of Bullet's
// sequential-impulse solver (btSequentialImpulseConstraintSolver), written on the
// problem's rows so that it can be measured beside the other methods on the same
// files.
//
// A sweep updates the joint rows, then every contact's normal row, then the
// friction rows, each against the velocities the rows before it left:
//   joint row:   dl = -(J v + b + C l) / A
//   normal row:  dl = -(J v + w) / A,   0 <= l <= cap (the normal cap of a crushing contact,
//                dem/contact/crushing.hpp; infinite where it is rigid)
//   friction:    dl = -(J v + w) / A,   then "pgs_square": each direction in [-mu l_N, mu l_N]
//                (Bullet's square), "pgs_cone": the pair projected onto |l_T| <= mu l_N
// with A = J M^-1 J^T the row's effective inverse mass. The iterations stop when
// the merit (natural_map_residual) is below the tolerance; it is measured every
// kCheckEvery sweeps.
#include "dem/contact/pgs.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace icedem {
namespace {

constexpr int kCheckEvery = 4;

// one row of the problem, as the sweep needs it
struct Row {
  int a, b;
  RowJacobian ja, jb;
  Vector6d ma, mb;  // M^-1 J^T on each body
  double inv_a;     // 1 / (J M^-1 J^T)
};

}  // namespace

SolverAnswer ProjectedGaussSeidel::solve(const ContactProblem& p, const MethodOptions& options) {
  const int nb = static_cast<int>(p.bodies.size()), nc = static_cast<int>(p.contacts.size()), nj = p.joint_rows();
  std::vector<Eigen::Matrix<double, 6, 6>> inv_mass(nb);
  for (int i = 0; i < nb; ++i) inv_mass[i] = inverse_mass(p.bodies[i]);
  auto make_row = [&](int a, int b, const RowJacobian& ja, const RowJacobian& jb) {
    Row r{a, b, ja, jb, Vector6d::Zero(), Vector6d::Zero(), 0.0};
    double eff = 0.0;
    if (a >= 0) r.ma = inv_mass[a] * ja.transpose(), eff += ja.dot(r.ma);
    if (b >= 0) r.mb = inv_mass[b] * jb.transpose(), eff += jb.dot(r.mb);
    r.inv_a = eff > 0 ? 1.0 / eff : 0.0;
    return r;
  };
  std::vector<Row> rows;  // 3 per contact, then the joint rows
  rows.reserve(3 * nc + nj);
  for (const ProblemContact& c : p.contacts)
    for (int k = 0; k < 3; ++k) rows.push_back(make_row(c.a, c.b, c.ja.row(k), c.jb.row(k)));
  for (const ProblemJointRow& j : p.joints) rows.push_back(make_row(j.a, j.b, j.ja, j.jb));

  Eigen::VectorXd v(6 * nb);
  for (int i = 0; i < nb; ++i) v.segment<6>(6 * i) = p.bodies[i].free_velocity;
  Eigen::VectorXd l = Eigen::VectorXd::Zero(3 * nc + nj);
  auto velocity = [&](const Row& r) {
    double jv = 0.0;
    if (r.a >= 0) jv += r.ja.dot(v.segment<6>(6 * r.a));
    if (r.b >= 0) jv += r.jb.dot(v.segment<6>(6 * r.b));
    return jv;
  };
  auto apply = [&](const Row& r, double dl) {
    if (r.a >= 0) v.segment<6>(6 * r.a) += r.ma * dl;
    if (r.b >= 0) v.segment<6>(6 * r.b) += r.mb * dl;
  };
  if (options.warm_start) {
    for (int c = 0; c < nc; ++c)
      for (int k = 0; k < 3; ++k) l(3 * c + k) = p.contacts[c].guess(k), apply(rows[3 * c + k], l(3 * c + k));
    for (int j = 0; j < nj; ++j) l(3 * nc + j) = p.joints[j].guess, apply(rows[3 * nc + j], l(3 * nc + j));
  }

  const Eigen::VectorXd mu = [&] {
    Eigen::VectorXd m(nc);
    for (int c = 0; c < nc; ++c) m(c) = p.contacts[c].mu;
    return m;
  }();
  const Merit measure(options.merit, p, local_q(global_form(p)), mu);
  auto merit = [&] {
    Eigen::VectorXd u(3 * nc);
    for (int c = 0; c < nc; ++c)
      for (int k = 0; k < 3; ++k) u(3 * c + k) = velocity(rows[3 * c + k]) + p.contacts[c].w(k);
    return measure(l.head(3 * nc), u);
  };

  SolverAnswer answer;
  answer.residual = merit();
  int sweep = 0;
  while (answer.residual > options.tolerance && sweep < options.max_iterations) {
    for (int j = 0; j < nj; ++j) {
      const Row& r = rows[3 * nc + j];
      double& lj = l(3 * nc + j);
      const double dl = -(velocity(r) + p.joints[j].bias + p.joints[j].compliance * lj) * r.inv_a;
      lj += dl;
      apply(r, dl);
    }
    for (int c = 0; c < nc; ++c) {
      const Row& r = rows[3 * c];
      double& ln = l(3 * c);
      const double next = std::clamp(ln - (velocity(r) + p.contacts[c].w(0)) * r.inv_a, 0.0, p.contacts[c].normal_cap);
      apply(r, next - ln);
      ln = next;
    }
    for (int c = 0; c < nc; ++c) {
      const double limit = p.contacts[c].mu * l(3 * c);
      Eigen::Vector2d next;
      for (int k = 1; k <= 2; ++k) {
        const Row& r = rows[3 * c + k];
        next(k - 1) = l(3 * c + k) - (velocity(r) + p.contacts[c].w(k)) * r.inv_a;
        if (!cone_) {  // Bullet: each direction on its own, against the other's new impulse
          next(k - 1) = std::clamp(next(k - 1), -limit, limit);
          apply(r, next(k - 1) - l(3 * c + k));
          l(3 * c + k) = next(k - 1);
        }
      }
      if (cone_) {
        const double size = next.norm();
        if (size > limit) next *= size > 0 ? limit / size : 0.0;
        for (int k = 1; k <= 2; ++k) apply(rows[3 * c + k], next(k - 1) - l(3 * c + k)), l(3 * c + k) = next(k - 1);
      }
    }
    ++sweep;
    if (sweep % kCheckEvery == 0 || sweep == options.max_iterations) answer.residual = merit();
  }
  answer.sweeps = sweep;
  answer.capped = answer.residual > options.tolerance;
  answer.r = l.head(3 * nc);
  answer.l = l.tail(nj);
  return answer;
}

}  // namespace icedem
