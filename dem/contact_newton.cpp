#include "dem/contact_newton.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <Eigen/SparseLU>

namespace icedem {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// the derivative of project_on_cone at x (symmetric, its eigenvalues in [0, 1])
Eigen::Matrix3d cone_projection_jacobian(const Eigen::Vector3d& x, double mu) {
  const double tangent = std::hypot(x(1), x(2));
  if (mu * tangent <= -x(0)) return Eigen::Matrix3d::Zero();  // projected to the apex
  if (tangent <= mu * x(0)) return Eigen::Matrix3d::Identity();
  // onto the cone's surface: P = (a, mu a t), a = (x_N + mu |x_T|) / (1 + mu^2), t = x_T / |x_T|
  const Eigen::Vector2d t = x.tail<2>() / tangent;
  const double k = 1.0 / (1.0 + mu * mu), a = k * (x(0) + mu * tangent);
  Eigen::Matrix3d d;
  d(0, 0) = k;
  d.block<1, 2>(0, 1) = k * mu * t.transpose();
  d.block<2, 1>(1, 0) = k * mu * t;
  d.block<2, 2>(1, 1) = k * mu * mu * t * t.transpose() +
                        (mu * a / tangent) * (Eigen::Matrix2d::Identity() - t * t.transpose());
  return d;
}

// where each entry of the contacts' blocks J_i^T D J_j lands in H's compressed values
struct ContactSlots {
  std::vector<int> index;  // 36 per block, blocks (a,a), (a,b), (b,a), (b,b) as present
};

int slot(const SparseMatrix& H, int row, int col) {
  const int* begin = H.innerIndexPtr() + H.outerIndexPtr()[col];
  const int* end = H.innerIndexPtr() + H.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - H.innerIndexPtr());
}

}  // namespace

SolverAnswer PrimalNewton::solve(const ContactProblem& p, const MethodOptions& options) {
  const int nb = static_cast<int>(p.bodies.size()), nc = static_cast<int>(p.contacts.size());
  const int n = 6 * nb, m = 3 * nc;
  const GlobalForm g = global_form(p);
  for (int r = 0; r < g.compliance.size(); ++r)
    if (!(g.compliance(r) > 0)) throw std::invalid_argument("primal Newton: joint rows must be soft");
  const Eigen::VectorXd c_inv = g.compliance.cwiseInverse();
  const SparseMatrix Jj_t = g.Jj.transpose();
  const SparseMatrix Hc = g.M + Jj_t * c_inv.asDiagonal() * g.Jj;  // constant part of the Hessian
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Jc = g.Jc;
  const SparseMatrix Jc_t = g.Jc.transpose();

  // each contact's weight: a fraction of its effective inverse mass J M^-1 J^T
  std::vector<Matrix6d> inv_mass(nb);
  for (int i = 0; i < nb; ++i) inv_mass[i] = inverse_mass(p.bodies[i]);
  Eigen::VectorXd rho(nc);
  for (int c = 0; c < nc; ++c) {
    const ProblemContact& k = p.contacts[c];
    double trace = 0.0;
    if (k.a >= 0) trace += (k.ja * inv_mass[k.a] * k.ja.transpose()).trace();
    if (k.b >= 0) trace += (k.jb * inv_mass[k.b] * k.jb.transpose()).trace();
    rho(c) = settings_.rho_fraction * trace / 3.0;
  }

  // the Hessian's pattern: Hc and every contact's body blocks, analysed once
  std::vector<Eigen::Triplet<double>> t;
  for (int col = 0; col < Hc.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(Hc, col); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  for (const ProblemContact& k : p.contacts)
    for (int i : {k.a, k.b})
      for (int j : {k.a, k.b})
        if (i >= 0 && j >= 0)
          for (int r = 0; r < 6; ++r)
            for (int s = 0; s < 6; ++s) t.emplace_back(6 * i + r, 6 * j + s, 0.0);
  SparseMatrix H(n, n);
  H.setFromTriplets(t.begin(), t.end());
  H.makeCompressed();
  const Eigen::VectorXd base = Eigen::Map<const Eigen::VectorXd>(H.valuePtr(), H.nonZeros());
  std::vector<ContactSlots> slots(nc);
  for (int c = 0; c < nc; ++c) {
    const ProblemContact& k = p.contacts[c];
    for (int i : {k.a, k.b})
      for (int j : {k.a, k.b})
        if (i >= 0 && j >= 0)
          for (int r = 0; r < 6; ++r)
            for (int s = 0; s < 6; ++s) slots[c].index.push_back(slot(H, 6 * i + r, 6 * j + s));
  }

  const double q_norm = local_q_norm(p);
  const Eigen::VectorXd& mu = g.mu;

  // start: the warm start's impulses, the velocities they give
  Eigen::VectorXd r_centre = options.warm_start ? contact_guess(p) : Eigen::VectorXd(Eigen::VectorXd::Zero(m));
  const Eigen::VectorXd l_start =
      options.warm_start ? joint_guess(p) : Eigen::VectorXd(Eigen::VectorXd::Zero(p.joint_rows()));
  Eigen::VectorXd v = velocities(g, r_centre, l_start);
  auto shift_of = [&](const Eigen::VectorXd& u) {
    Eigen::VectorXd s = Eigen::VectorXd::Zero(m);
    for (int c = 0; c < nc; ++c) s(3 * c) = mu(c) * std::hypot(u(3 * c + 1), u(3 * c + 2));
    return s;
  };
  Eigen::VectorXd u(m);  // the contact velocities of v, set with each residual

  // the contacts' impulses r_c = P_K(rb_c - y_c / rho_c) for y = Jc v + w + s (+ a step)
  auto impulses = [&](const Eigen::VectorXd& y, Eigen::VectorXd& r) {
    for (int c = 0; c < nc; ++c)
      r.segment<3>(3 * c) = project_on_cone(r_centre.segment<3>(3 * c) - y.segment<3>(3 * c) / rho(c), mu(c));
  };

  SolverAnswer answer;
  Eigen::VectorXd r(m), grad(n), dv(n), v_try(n), r_try(m);
  // G(v) = M (v - v_free) - Jj^T l(v) - Jc^T r(v), with the shift inside r(v)
  auto residual = [&](const Eigen::VectorXd& vel, Eigen::VectorXd& rr, Eigen::VectorXd& uu) {
    uu = Jc * vel + g.w;
    impulses(uu + shift_of(uu), rr);
    return Eigen::VectorXd(g.M * (vel - g.v_free) + Jj_t * c_inv.cwiseProduct(g.Jj * vel + g.b) - Jc_t * rr);
  };
  // |G|^2 in M^-1's metric (M is block diagonal)
  auto size = [&](const Eigen::VectorXd& G) {
    double total = 0.0;
    for (int i = 0; i < nb; ++i) total += G.segment<6>(6 * i).dot(inv_mass[i] * G.segment<6>(6 * i));
    return total;
  };
  Eigen::SparseLU<SparseMatrix> lu;
  lu.analyzePattern(H);
  int steps = 0;
  answer.residual = std::numeric_limits<double>::infinity();
  Eigen::VectorXd u_try(m);
  for (int outer = 0; steps < options.max_iterations; ++outer) {
    grad = residual(v, r, u);
    double psi = size(grad);
    const double scale = std::max(v.dot(g.M * v), 1e-300);
    for (int inner = 0; inner < settings_.inner_iterations && steps < options.max_iterations; ++inner) {
      if (psi <= 1e-24 * scale) break;
      // the semismooth Jacobian Hc + Jc^T B Jc, B_c = dP_K (I + dS_c) / rho_c
      Eigen::Map<Eigen::VectorXd>(H.valuePtr(), H.nonZeros()) = base;
      for (int c = 0; c < nc; ++c) {
        const ProblemContact& k = p.contacts[c];
        const Eigen::Vector3d uc = u.segment<3>(3 * c);
        const double ut = std::hypot(uc(1), uc(2));
        Eigen::Vector3d shifted = uc;
        shifted(0) += mu(c) * ut;
        const Eigen::Matrix3d dP =
            cone_projection_jacobian(r_centre.segment<3>(3 * c) - shifted / rho(c), mu(c));
        if (dP.isZero()) continue;
        // d(u + s)/du: the shift mu |u_T| moves the normal with the tangential velocity
        Eigen::Matrix3d d_shifted = Eigen::Matrix3d::Identity();
        if (ut > 0) d_shifted.block<1, 2>(0, 1) = mu(c) * uc.tail<2>().transpose() / ut;
        const Eigen::Matrix3d B = dP * d_shifted / rho(c);
        int at = 0;
        for (int i : {k.a, k.b})
          for (int j : {k.a, k.b}) {
            if (i < 0 || j < 0) continue;
            const ContactJacobian& Ji = i == k.a ? k.ja : k.jb;
            const ContactJacobian& Jk = j == k.a ? k.ja : k.jb;
            const Matrix6d block = Ji.transpose() * B * Jk;
            for (int rr = 0; rr < 6; ++rr)
              for (int ss = 0; ss < 6; ++ss) H.valuePtr()[slots[c].index[at++]] += block(rr, ss);
          }
      }
      lu.factorize(H);
      dv = -lu.solve(grad);
      ++steps;
      // backtracking on |G|^2 (Armijo): the Newton step decreases it near a solution
      double a = 1.0;
      bool accepted = false;
      for (int k = 0; k < 30; ++k, a *= 0.5) {
        v_try = v + a * dv;
        const Eigen::VectorXd G = residual(v_try, r_try, u_try);
        const double psi_try = size(G);
        if (psi_try <= (1.0 - 1e-4 * a) * psi) {
          v = v_try, r = r_try, u = u_try, grad = G, psi = psi_try, accepted = true;
          break;
        }
      }
      if (!accepted) break;
    }
    // outer: the impulses become the proximal centre
    r_centre = r;
    answer.residual = natural_map_residual(r, u, mu, q_norm);
    if (answer.residual <= options.tolerance) break;
  }
  answer.sweeps = steps;
  answer.capped = answer.residual > options.tolerance;
  answer.r = r_centre;
  answer.l = -c_inv.cwiseProduct(g.Jj * v + g.b);
  return answer;
}

}  // namespace icedem
