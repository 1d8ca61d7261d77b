#include "dem/contact/interior_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SparseCholesky>

#include "dem/contact/contact_hessian.hpp"
#include "dem/contact/second_order_cone.hpp"

namespace icedem {
namespace {

using namespace soc;

using SparseMatrix = Eigen::SparseMatrix<double>;

}  // namespace

SolverAnswer InteriorPoint::solve(const ContactProblem& p, const MethodOptions& options) {
  refuse_crushing(p, "ipm");
  const GlobalForm g = global_form(p);
  const FoldedMassMatrix folded = folded_mass_matrix(g);  // throws if a joint row is rigid
  const int n = p.dofs(), nc = static_cast<int>(p.contacts.size()), m = 3 * nc;
  // Mt's factor, once: the merit's q (the local form's, Jc Mt^-1 ft + w, as local_q() gives it)
  // and the judge's velocities (below) both solve with it
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> mass_factor;
  if (g.Jj.rows()) mass_factor.compute(folded.Mt);
  const Merit merit(options.merit, p,
                    g.Jj.rows() ? Eigen::VectorXd(g.Jc * mass_factor.solve(folded.ft) + g.w) : local_q(g), g.mu);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> Jc = g.Jc;
  const SparseMatrix Jc_t = g.Jc.transpose();
  // D per row: (1, mu, mu) per contact
  Eigen::VectorXd scale(m);
  for (int c = 0; c < nc; ++c) scale.segment<3>(3 * c) = Eigen::Vector3d(1.0, g.mu(c), g.mu(c));
  std::vector<Eigen::Matrix<double, 6, 6>> inv_mass(p.bodies.size());
  for (std::size_t i = 0; i < p.bodies.size(); ++i) inv_mass[i] = inverse_mass(p.bodies[i]);
  const auto inverse_mass_times = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd y(x.size());
    for (std::size_t i = 0; i < inv_mass.size(); ++i) y.segment<6>(6 * i) = inv_mass[i] * x.segment<6>(6 * i);
    return y;
  };

  // H = Mt + G^T W^-2 G: its pattern once, its values every iteration
  ContactHessian hessian(p, folded.Mt);

  // the start: the warm start's impulses and the velocities they give, pushed into the cones
  const Eigen::VectorXd r0 = options.warm_start ? contact_guess(p) : Eigen::VectorXd(Eigen::VectorXd::Zero(m));
  const Eigen::VectorXd l0 =
      options.warm_start ? joint_guess(p) : Eigen::VectorXd(Eigen::VectorXd::Zero(p.joint_rows()));
  Eigen::VectorXd v = velocities(g, r0, l0);
  Eigen::VectorXd u = Jc * v + g.w;
  Eigen::VectorXd shift(nc);
  const auto y_of = [&](const Eigen::VectorXd& u_now) {
    Eigen::VectorXd y = u_now;
    for (int c = 0; c < nc; ++c) y(3 * c) += shift(c);
    return Eigen::VectorXd(y.cwiseProduct(scale));
  };
  const auto update_shift = [&] {
    for (int c = 0; c < nc; ++c) shift(c) = g.mu(c) * tangential_norm(u(3 * c + 1), u(3 * c + 2));
  };
  update_shift();
  Eigen::VectorXd z(m), s = y_of(u);
  for (int c = 0; c < nc; ++c) {
    z(3 * c) = r0(3 * c);
    for (int k = 1; k < 3; ++k) z(3 * c + k) = g.mu(c) > 0 ? r0(3 * c + k) / g.mu(c) : 0.0;
  }
  // margins: a share of the start's largest impulse and speed, or, where there is none
  // (a cold start), of the impulse that stops the largest speed through each contact's
  // effective mass
  double inverse_mass_mean = 0.0;
  for (const ProblemContact& k : p.contacts) {
    if (k.a >= 0) inverse_mass_mean += (k.ja * inv_mass[k.a] * k.ja.transpose()).trace() / 3.0;
    if (k.b >= 0) inverse_mass_mean += (k.jb * inv_mass[k.b] * k.jb.transpose()).trace() / 3.0;
  }
  inverse_mass_mean /= std::max(nc, 1);
  const auto push_all_inside = [&](double margin) {
    const double speed_now = std::max(s.lpNorm<Eigen::Infinity>(), 1e-6);
    const double impulse_now = std::max(z.lpNorm<Eigen::Infinity>(), speed_now / std::max(inverse_mass_mean, 1e-30));
    for (int c = 0; c < nc; ++c) {
      Eigen::Vector3d zc = z.segment<3>(3 * c), sc = s.segment<3>(3 * c);
      push_inside(zc, margin * impulse_now);
      push_inside(sc, margin * speed_now);
      z.segment<3>(3 * c) = zc;
      s.segment<3>(3 * c) = sc;
    }
  };
  push_all_inside(settings_.start_margin);
  double first_gap = -1;  // the gap s . z / contacts of the first iteration

  std::vector<Scaling> scalings(nc);
  Eigen::VectorXd rx(n), rz(m), dx(n), ds(m), dz(m), dsa(m), dza(m), target(m);
  SolverAnswer best;
  best.residual = std::numeric_limits<double>::infinity();
  // judged as the local form judges any method: the impulses r = D z, the velocities they
  // give with the joints folded, v_r = Mt^-1 (Jc^T r + ft), and the joints' impulses at v_r
  // (so that the joint rows hold exactly what the run applies), one solve with Mt's factor
  const auto judge = [&] {
    const Eigen::VectorXd r = z.cwiseProduct(scale);
    const Eigen::VectorXd f = Jc_t * r + folded.ft;
    const Eigen::VectorXd v_r = g.Jj.rows() ? Eigen::VectorXd(mass_factor.solve(f)) : inverse_mass_times(f);
    const double residual = merit(r, Jc * v_r + g.w);
    if (residual < best.residual) {
      best.residual = residual;
      best.r = r;
      best.l = g.Jj.rows() ? Eigen::VectorXd(-g.compliance.cwiseInverse().cwiseProduct(g.Jj * v_r + g.b))
                           : Eigen::VectorXd();
    }
  };
  // Newton's direction for the cones' right-hand side d (W dz + W^-1 ds = d per cone)
  const auto direction = [&](const Eigen::VectorXd& d) {
    Eigen::VectorXd t(m);  // W^-1 d + W^-2 rz, per cone
    for (int c = 0; c < nc; ++c) {
      const Scaling& sc = scalings[c];
      t.segment<3>(3 * c) = sc.W_inv * (d.segment<3>(3 * c) + sc.W_inv * rz.segment<3>(3 * c));
    }
    dx = -rx + Jc_t * t.cwiseProduct(scale);
    hessian.solve(dx);
    const Eigen::VectorXd gdx = (Jc * dx).cwiseProduct(scale);
    ds = gdx - rz;
    for (int c = 0; c < nc; ++c) {
      const Scaling& sc = scalings[c];
      dz.segment<3>(3 * c) = t.segment<3>(3 * c) - sc.W_inv * (sc.W_inv * gdx.segment<3>(3 * c));
    }
  };
  const auto longest_step = [&] {
    double a = std::numeric_limits<double>::infinity();
    for (int c = 0; c < nc; ++c)
      a = std::min({a, step_to_boundary(s.segment<3>(3 * c), ds.segment<3>(3 * c)),
                    step_to_boundary(z.segment<3>(3 * c), dz.segment<3>(3 * c))});
    return a;
  };

  int iteration = 0;
  for (;; ++iteration) {
    // the residuals at the current point and shift (Mt v - ft - G^T z; s - (G v + h))
    rx = folded.Mt * v - folded.ft - Jc_t * z.cwiseProduct(scale);
    rz = s - y_of(u);
    judge();
    if (best.residual <= options.tolerance || iteration >= options.max_iterations) break;
    // the scaling and H = Mt + G^T W^-2 G
    double mu_gap = 0.0;
    hessian.reset();
    bool interior = true;
    for (int c = 0; c < nc && interior; ++c) {
      const Eigen::Vector3d sc = s.segment<3>(3 * c), zc = z.segment<3>(3 * c);
      interior = cone_det(sc) > 0 && cone_det(zc) > 0 && sc(0) > 0 && zc(0) > 0;
      if (!interior) break;
      scalings[c] = nesterov_todd(sc, zc);
      mu_gap += sc.dot(zc);
      const Eigen::Vector3d d = scale.segment<3>(3 * c);
      const Eigen::Matrix3d B = d.asDiagonal() * (scalings[c].W_inv * scalings[c].W_inv) * d.asDiagonal();
      hessian.add(c, B);
    }
    if (!interior) break;  // round-off put a point on a cone's boundary: keep the best answer
    mu_gap /= std::max(nc, 1);
    if (!hessian.factorise()) break;  // H is positive definite unless a mass matrix is not

    // predictor: the affine direction (d = -lambda)
    for (int c = 0; c < nc; ++c) target.segment<3>(3 * c) = -scalings[c].lambda;
    direction(target);
    const double a_affine = std::min(1.0, longest_step());
    const double gap = s.dot(z), gap_affine = (s + a_affine * ds).dot(z + a_affine * dz);
    const double sigma = std::clamp(std::pow(std::max(gap_affine, 0.0) / gap, 3), 0.0, 1.0);
    // corrector: d = -lambda + lambda^-1 o (sigma mu e - (W^-1 ds_a) o (W dz_a))
    dsa = ds, dza = dz;
    for (int c = 0; c < nc; ++c) {
      const Scaling& sc = scalings[c];
      Eigen::Vector3d rhs = -jordan(sc.W_inv * dsa.segment<3>(3 * c), sc.W * dza.segment<3>(3 * c));
      rhs(0) += sigma * mu_gap;
      target.segment<3>(3 * c) = -sc.lambda + jordan_solve(sc.lambda, rhs);
    }
    direction(target);
    const double a = std::min(1.0, settings_.step_fraction * longest_step());
    v += a * dx;
    s += a * ds;
    z += a * dz;
    u = Jc * v + g.w;
    // stalled on the cones' boundary once the gap has closed (the shift asks for a change that
    // the centred path no longer allows; steps then shrink to nothing, 1e-3 and below): start
    // again from here, pushed back into the cones by a smaller margin than the start's
    if (first_gap < 0) first_gap = mu_gap;
    if (a < settings_.restart_step && mu_gap < settings_.restart_gap * first_gap) {
      update_shift();
      s = y_of(u);
      push_all_inside(settings_.restart_margin);
      continue;
    }
    update_shift();
  }
  if (!best.r.size()) {  // no merit was a number (a blow-up): no impulses
    best.r = Eigen::VectorXd::Zero(m);
    best.l = Eigen::VectorXd::Zero(p.joint_rows());
  }
  best.sweeps = iteration;
  best.capped = best.residual > options.tolerance;
  return best;
}

}  // namespace icedem
