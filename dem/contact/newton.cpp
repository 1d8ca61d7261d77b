#include "dem/contact/newton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>


#include "dem/contact/contact_hessian.hpp"
#include "dem/contact/projection_jacobian.hpp"

namespace icedem {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// The inner problem's data and its function, gradient and Hessian pieces.
class InnerProblem {
 public:
  InnerProblem(const ContactProblem& p, double rho_fraction)
      : g_(global_form(p)),
        nb_(static_cast<int>(p.bodies.size())),
        nc_(static_cast<int>(p.contacts.size())),
        // the part of the Hessian that does not change: the mass with the soft joints folded
        // in (throws if a joint row is rigid), and every contact's body blocks
        hessian_(p, folded_mass_matrix(g_).Mt),
        cap_(normal_caps(p)) {
    c_inv_ = g_.compliance.cwiseInverse();
    Jj_t_ = g_.Jj.transpose();
    Jc_ = g_.Jc;
    Jc_t_ = g_.Jc.transpose();

    // each contact's weight: a fraction of its effective inverse mass J M^-1 J^T
    inv_mass_.resize(nb_);
    for (int i = 0; i < nb_; ++i) inv_mass_[i] = inverse_mass(p.bodies[i]);
    rho_.resize(nc_);
    for (int c = 0; c < nc_; ++c) {
      const ProblemContact& k = p.contacts[c];
      double trace = 0.0;
      if (k.a >= 0) trace += (k.ja * inv_mass_[k.a] * k.ja.transpose()).trace();
      if (k.b >= 0) trace += (k.jb * inv_mass_[k.b] * k.jb.transpose()).trace();
      rho_(c) = rho_fraction * trace / 3.0;
    }
  }

  const GlobalForm& global() const { return g_; }
  int contacts() const { return nc_; }
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& Jc() const { return Jc_; }

  // z_c = rb_c - (u_c + s_c) / rho_c, whose projection is the contact's impulse
  Eigen::Vector3d argument(int c, const Eigen::VectorXd& rb, const Eigen::Vector3d& uc, const Eigen::VectorXd& s) const {
    Eigen::Vector3d z = rb.segment<3>(3 * c) - uc / rho_(c);
    z(0) -= s(c) / rho_(c);
    return z;
  }

  // the impulses r(v) and the gradient G(v) = M (v - v_free) + Jj^T C^-1 (Jj v + b) - Jc^T r
  void gradient(const Eigen::VectorXd& v, const Eigen::VectorXd& u, const Eigen::VectorXd& rb,
                const Eigen::VectorXd& s, Eigen::VectorXd& r, Eigen::VectorXd& G) const {
    for (int c = 0; c < nc_; ++c)
      r.segment<3>(3 * c) = project_on_contact(argument(c, rb, u.segment<3>(3 * c), s), g_.mu(c), cap_(c));
    G = g_.M * (v - g_.v_free) - Jc_t_ * r;
    if (g_.Jj.rows()) G += Jj_t_ * c_inv_.cwiseProduct(g_.Jj * v + g_.b);
  }

  // where each contact's argument goes under the projection (contact_projection_jacobian's kinds)
  void kinds(const Eigen::VectorXd& rb, const Eigen::VectorXd& u, const Eigen::VectorXd& s,
             std::vector<int>& out) const {
    out.resize(nc_);
    double tangent;
    for (int c = 0; c < nc_; ++c)
      out[c] = contact_region(argument(c, rb, u.segment<3>(3 * c), s), g_.mu(c), cap_(c), tangent);
  }

  // H = Hc + Jc^T diag(dP_c / rho_c) Jc at the current arguments; `kinds` gets where each went
  ContactHessian& hessian(const Eigen::VectorXd& rb, const Eigen::VectorXd& u, const Eigen::VectorXd& s,
                          std::vector<int>& kinds) {
    hessian_.reset();
    kinds.resize(nc_);
    for (int c = 0; c < nc_; ++c) {
      const Eigen::Matrix3d B =
          contact_projection_jacobian(argument(c, rb, u.segment<3>(3 * c), s), g_.mu(c), cap_(c), kinds[c]) / rho_(c);
      if (kinds[c] != 0) hessian_.add(c, B);
    }
    return hessian_;
  }

  // The derivative of f along d at step a: phi'(a) = G(v + a d) . d, from the pieces
  // that do not depend on a (so a trial costs O(contacts + joint rows)).
  struct Line {
    double md_v = 0, md_d = 0;       // d^T M (v - v_free), d^T M d
    Eigen::VectorXd jj_v, jj_d;      // C^-1 (Jj v + b) and Jj d
    Eigen::VectorXd u, ud;           // Jc v + w, Jc d
  };
  Line line(const Eigen::VectorXd& v, const Eigen::VectorXd& u, const Eigen::VectorXd& d) const {
    Line l;
    const Eigen::VectorXd Md = g_.M * d;
    l.md_v = Md.dot(v - g_.v_free);
    l.md_d = Md.dot(d);
    if (g_.Jj.rows()) {
      l.jj_v = g_.Jj * v + g_.b;
      l.jj_d = g_.Jj * d;
    }
    l.u = u;
    l.ud = Jc_ * d;
    return l;
  }
  double slope(const Line& l, double a, const Eigen::VectorXd& rb, const Eigen::VectorXd& s) const {
    double total = l.md_v + a * l.md_d;
    if (l.jj_d.size()) total += l.jj_d.dot(c_inv_.cwiseProduct(l.jj_v + a * l.jj_d));
    for (int c = 0; c < nc_; ++c) {
      const Eigen::Vector3d uc = l.u.segment<3>(3 * c) + a * l.ud.segment<3>(3 * c);
      total -= l.ud.segment<3>(3 * c).dot(project_on_contact(argument(c, rb, uc, s), g_.mu(c), cap_(c)));
    }
    return total;
  }

  // M^-1 x, body by body
  Eigen::VectorXd inverse_mass_times(const Eigen::VectorXd& x) const {
    Eigen::VectorXd y(x.size());
    for (int i = 0; i < nb_; ++i) y.segment<6>(6 * i) = inv_mass_[i] * x.segment<6>(6 * i);
    return y;
  }

  Eigen::VectorXd joint_impulses(const Eigen::VectorXd& v) const {
    if (!g_.Jj.rows()) return Eigen::VectorXd();
    return -c_inv_.cwiseProduct(g_.Jj * v + g_.b);
  }

 private:
  GlobalForm g_;
  int nb_, nc_;
  Eigen::VectorXd c_inv_, rho_;
  SparseMatrix Jj_t_, Jc_t_;
  Eigen::SparseMatrix<double, Eigen::RowMajor> Jc_;
  std::vector<Matrix6d> inv_mass_;
  ContactHessian hessian_;
  Eigen::VectorXd cap_;  // each contact's normal cap (normal_caps: infinite where it is rigid)
};

// The step length a > 0 where phi'(a) = 0 (phi convex: phi' nondecreasing, phi'(0) < 0),
// to within a tenth of |phi'(0)| (the strong Wolfe condition): expand from a = 1 until
// phi' changes sign, then regula falsi (Illinois) on the bracket.
template <class Slope>
double exact_line_search(Slope&& slope, double slope0) {
  const double enough = 0.1 * std::abs(slope0);
  double lo = 0.0, f_lo = slope0, hi = 1.0, f_hi = slope(1.0);
  if (std::abs(f_hi) <= enough) return 1.0;
  for (int k = 0; f_hi < 0 && k < 30; ++k) lo = hi, f_lo = f_hi, hi *= 2.0, f_hi = slope(hi);
  if (f_hi < 0) return hi;
  int side = 0;
  double a = hi;
  for (int k = 0; k < 60; ++k) {
    a = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    const double f = slope(a);
    if (std::abs(f) <= enough) break;
    if (f < 0) {
      lo = a, f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = a, f_hi = f;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
  return a;
}

}  // namespace

SolverAnswer PrimalNewton::solve(const ContactProblem& p, const MethodOptions& options) {
  InnerProblem inner(p, settings_.rho_fraction);
  const GlobalForm& g = inner.global();
  const int n = p.dofs(), m = p.contact_rows(), nc = inner.contacts();
  const Merit merit(options.merit, p, local_q(g), g.mu);

  // start: the warm start's impulses and the velocities they give
  Eigen::VectorXd rb = options.warm_start ? contact_guess(p) : Eigen::VectorXd(Eigen::VectorXd::Zero(m));
  const Eigen::VectorXd l0 =
      options.warm_start ? joint_guess(p) : Eigen::VectorXd(Eigen::VectorXd::Zero(p.joint_rows()));
  Eigen::VectorXd v = velocities(g, rb, l0);
  Eigen::VectorXd u = inner.Jc() * v + g.w;
  Eigen::VectorXd s(nc);
  auto update_shift = [&] {
    for (int c = 0; c < nc; ++c) s(c) = g.mu(c) * tangential_norm(u(3 * c + 1), u(3 * c + 2));
  };
  update_shift();

  std::vector<int> kinds, kinds_after;
  Eigen::VectorXd r(m), G(n), d(n);
  SolverAnswer answer;
  answer.residual = std::numeric_limits<double>::infinity();
  int steps = 0;
  bool failed = false;
  while (steps < options.max_iterations && !failed) {
    // inner: Newton on f for this centre and shift
    for (int k = 0; k < settings_.inner_iterations && steps < options.max_iterations; ++k) {
      inner.gradient(v, u, rb, s, r, G);
      ContactHessian& H = inner.hessian(rb, u, s, kinds);
      // H is positive definite unless a body's mass matrix is not: nothing more to do
      if (!H.factorise()) {
        failed = true;
        break;
      }
      d = -G;
      H.solve(d);
      ++steps;
      const double slope0 = G.dot(d);
      if (!(slope0 < 0)) break;  // at the minimum to round-off
      const InnerProblem::Line line = inner.line(v, u, d);
      const double a = exact_line_search([&](double x) { return inner.slope(line, x, rb, s); }, slope0);
      v += a * d;
      u += a * line.ud;
      // a full step that kept every contact where it was has reached the exact minimum of
      // this piecewise quadratic (up to the cone's curvature): the inner problem is solved
      inner.kinds(rb, u, s, kinds_after);
      if (std::abs(a - 1.0) < 1e-3 && kinds_after == kinds) break;
    }
    // judged on what the answer is: the impulses r (and the joints' l at v) and the
    // velocities they give, v - M^-1 G, not on v itself (the inner loop may stop short)
    inner.gradient(v, u, rb, s, r, G);
    const Eigen::VectorXd u_r = inner.Jc() * (v - inner.inverse_mass_times(G)) + g.w;
    answer.residual = merit(r, u_r);
    if (answer.residual <= options.tolerance) break;
    // outer: the impulses become the proximal centre, the sliding speeds the shift
    rb = r;
    update_shift();
  }
  answer.sweeps = steps;
  answer.capped = answer.residual > options.tolerance;
  answer.r = r;
  answer.l = inner.joint_impulses(v);
  return answer;
}

}  // namespace icedem
