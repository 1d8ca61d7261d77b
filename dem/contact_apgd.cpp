#include "dem/contact_apgd.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace icedem {
namespace {

// steps between two evaluations of the merit (it costs about as much as a step's
// products; on the problem library every 4th step took 20 % less CPU than every step)
constexpr int kCheckEvery = 4;

// R rows of J on their one or two bodies (-1: none), and M^-1 J^T on each: a contact's
// three rows (R = 3) or one joint row (R = 1)
template <int R>
struct Blocks {
  int a, b;
  Eigen::Matrix<double, R, 6> ja, jb;
  Eigen::Matrix<double, 6, R> ma = Eigen::Matrix<double, 6, R>::Zero(), mb = Eigen::Matrix<double, 6, R>::Zero();

  Blocks(int a_, int b_, const Eigen::Matrix<double, R, 6>& ja_, const Eigen::Matrix<double, R, 6>& jb_,
         const std::vector<Eigen::Matrix<double, 6, 6>>& inv_mass)
      : a(a_), b(b_), ja(ja_), jb(jb_) {
    if (a >= 0) ma = inv_mass[a] * ja.transpose();
    if (b >= 0) mb = inv_mass[b] * jb.transpose();
  }
  // the diagonal of these rows' block of J M^-1 J^T
  Eigen::Matrix<double, R, 1> diagonal() const { return (ja * ma + jb * mb).diagonal(); }
};

// body += M^-1 J^T x over the blocks, whose rows start at `first` in x
template <int R>
void add_body_impulses(const std::vector<Blocks<R>>& blocks, int first, const Eigen::VectorXd& x,
                       Eigen::VectorXd& body) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Blocks<R>& k = blocks[i];
    const Eigen::Matrix<double, R, 1> xi = x.segment<R>(first + R * static_cast<int>(i));
    if (k.a >= 0) body.segment<6>(6 * k.a) += k.ma * xi;
    if (k.b >= 0) body.segment<6>(6 * k.b) += k.mb * xi;
  }
}

// rows += J v over the blocks, whose rows start at `first` in rows; v stacked per body
template <int R>
void add_row_products(const std::vector<Blocks<R>>& blocks, int first, const Eigen::VectorXd& v,
                      Eigen::VectorXd& rows) {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Blocks<R>& k = blocks[i];
    const int at = first + R * static_cast<int>(i);
    if (k.a >= 0) rows.segment<R>(at) += k.ja * v.segment<6>(6 * k.a);
    if (k.b >= 0) rows.segment<R>(at) += k.jb * v.segment<6>(6 * k.b);
  }
}

// The problem's operators on the stacked impulses x = (contacts' r, joint rows' l).
class DualProblem {
 public:
  explicit DualProblem(const ContactProblem& p)
      : nb_(static_cast<int>(p.bodies.size())), nc_(static_cast<int>(p.contacts.size())), nj_(p.joint_rows()) {
    std::vector<Eigen::Matrix<double, 6, 6>> inv_mass(nb_);
    for (int i = 0; i < nb_; ++i) inv_mass[i] = inverse_mass(p.bodies[i]);
    // J and M^-1 J^T kept as each contact's 3x6 blocks (each joint row's 1x6) on its
    // one or two bodies (Blocks): the products are fixed-size, and this set-up, paid on
    // every island of every step, is a copy
    Eigen::VectorXd diagonal(size());
    contacts_.reserve(nc_);
    rows_free_.resize(size());
    mu_.resize(nc_);
    for (int c = 0; c < nc_; ++c) {
      const ProblemContact& from = p.contacts[c];
      contacts_.emplace_back(from.a, from.b, from.ja, from.jb, inv_mass);
      diagonal.segment<3>(3 * c) = contacts_.back().diagonal();
      rows_free_.segment<3>(3 * c) = from.w;
      mu_(c) = from.mu;
    }
    joints_.reserve(nj_);
    compliance_ = Eigen::VectorXd::Zero(size());
    for (int r = 0; r < nj_; ++r) {
      const ProblemJointRow& from = p.joints[r];
      joints_.emplace_back(from.a, from.b, from.ja, from.jb, inv_mass);
      diagonal(3 * nc_ + r) = joints_.back().diagonal()(0) + from.compliance;
      rows_free_(3 * nc_ + r) = from.bias;
      compliance_(3 * nc_ + r) = from.compliance;
    }
    // the rows' velocities at x = 0
    Eigen::VectorXd v_free(6 * nb_);
    for (int i = 0; i < nb_; ++i) v_free.segment<6>(6 * i) = p.bodies[i].free_velocity;
    add_all_row_products(v_free, rows_free_);
    // the merit's scale |q|: without joints q is the contacts' free velocity; with them
    // the joints must be folded (a sparse factorisation, only for lattices)
    q_norm_ = nj_ ? local_q_norm(global_form(p)) : rows_free_.norm();

    // D: 1 / the diagonal of J M^-1 J^T + C, one value per contact (the mean of its three
    // rows, so that the cone is unchanged by it)
    scale_.resize(size());
    for (int c = 0; c < nc_; ++c) scale_.segment<3>(3 * c).setConstant(3.0 / diagonal.segment<3>(3 * c).sum());
    for (int r = 0; r < nj_; ++r) scale_(3 * nc_ + r) = 1.0 / diagonal(3 * nc_ + r);
    body_velocity_.resize(6 * nb_);
  }

  int contacts() const { return nc_; }
  int size() const { return 3 * nc_ + nj_; }
  double q_norm() const { return q_norm_; }
  const Eigen::VectorXd& scale() const { return scale_; }

  // the rows' velocities J v(x) + (w, b), v(x) = v_free + M^-1 J^T x: the contacts' u,
  // then the joint rows' J v + b
  void row_velocities(const Eigen::VectorXd& x, Eigen::VectorXd& rows) const {
    body_velocity_.setZero();  // M^-1 J^T x
    add_body_impulses(contacts_, 0, x, body_velocity_);
    add_body_impulses(joints_, 3 * nc_, x, body_velocity_);
    rows = rows_free_;
    add_all_row_products(body_velocity_, rows);
  }

  // De Saxce's shift at the rows' velocities: mu |u_T|, one per contact
  void shift(const Eigen::VectorXd& rows, Eigen::VectorXd& s) const {
    for (int c = 0; c < nc_; ++c) s(c) = mu_(c) * tangential_norm(rows(3 * c + 1), rows(3 * c + 2));
  }

  // gradient of f for a fixed shift s: J v(x) + (w, b) + C x + (s on the normals)
  void gradient(const Eigen::VectorXd& x, const Eigen::VectorXd& rows, const Eigen::VectorXd& s,
                Eigen::VectorXd& grad) const {
    grad = rows + compliance_.cwiseProduct(x);
    for (int c = 0; c < nc_; ++c) grad(3 * c) += s(c);
  }
  // f(x) = 1/2 x^T N x + x^T (rows_free + s), N = J M^-1 J^T + C, from the gradient at x
  double objective(const Eigen::VectorXd& x, const Eigen::VectorXd& grad, const Eigen::VectorXd& s) const {
    double linear = x.dot(rows_free_);
    for (int c = 0; c < nc_; ++c) linear += x(3 * c) * s(c);
    return 0.5 * (x.dot(grad) + linear);
  }

  // each contact onto its cone; joint rows unchanged
  void project(Eigen::VectorXd& x) const {
    for (int c = 0; c < nc_; ++c) x.segment<3>(3 * c) = project_on_cone(x.segment<3>(3 * c), mu_(c));
  }

  // the merit of impulses x with row velocities `rows`: the contacts' natural map and the
  // joint rows' equation J v + b + C l = 0, normalised as natural_map_residual is
  double merit(const Eigen::VectorXd& x, const Eigen::VectorXd& rows, double q_norm) const {
    const double contacts = natural_map_residual(x.head(3 * nc_), rows.head(3 * nc_), mu_, q_norm);
    if (!nj_) return contacts;
    const double scale = std::max({q_norm, x.head(3 * nc_).norm(), rows.head(3 * nc_).norm()});
    const double joints = (rows.tail(nj_) + compliance_.tail(nj_).cwiseProduct(x.tail(nj_))).norm() /
                          (scale > std::numeric_limits<double>::epsilon() ? scale : 1.0);
    return std::hypot(contacts, joints);
  }

 private:
  // rows += J v, v stacked per body
  void add_all_row_products(const Eigen::VectorXd& v, Eigen::VectorXd& rows) const {
    add_row_products(contacts_, 0, v, rows);
    add_row_products(joints_, 3 * nc_, v, rows);
  }

  int nb_, nc_, nj_;
  std::vector<Blocks<3>> contacts_;
  std::vector<Blocks<1>> joints_;
  Eigen::VectorXd compliance_, scale_, rows_free_, mu_;
  double q_norm_ = 0;
  mutable Eigen::VectorXd body_velocity_;  // M^-1 J^T x, scratch of row_velocities
};

}  // namespace

SolverAnswer AcceleratedProjectedGradient::solve(const ContactProblem& p, const MethodOptions& options) {
  const DualProblem dual(p);
  const int n = dual.size(), nc = dual.contacts();
  const double q_norm = dual.q_norm();
  const Eigen::VectorXd& D = dual.scale();

  Eigen::VectorXd x(n);
  if (options.warm_start)
    x << contact_guess(p), joint_guess(p);
  else
    x.setZero();
  dual.project(x);

  SolverAnswer answer;
  Eigen::VectorXd rows(n);
  dual.row_velocities(x, rows);
  answer.residual = dual.merit(x, rows, q_norm);
  Eigen::VectorXd best = x;
  // Lipschitz estimate of the scaled gradient: with D it is of order 1 (1 for a single
  // row); the backtracking corrects it
  double L = 1.0, theta = 1.0;
  // y, the extrapolated point, and the rows' velocities there: they are affine in the
  // impulses, so the extrapolation carries them along without a product
  Eigen::VectorXd y = x, rows_y = rows;
  Eigen::VectorXd s(nc), grad_y(n), next(n), rows_next(n), grad_next(n);
  int steps = 0, iteration = 0;
  while (answer.residual > options.tolerance && steps < options.max_iterations) {
    dual.shift(rows_y, s);
    dual.gradient(y, rows_y, s, grad_y);
    const double f_y = dual.objective(y, grad_y, s);
    // backtracking: the quadratic model with L must lie above f at the new point
    for (int trial = 0; trial < 30; ++trial) {
      next = y - (1.0 / L) * D.cwiseProduct(grad_y);
      dual.project(next);
      dual.row_velocities(next, rows_next);
      ++steps;
      dual.gradient(next, rows_next, s, grad_next);
      const double f_next = dual.objective(next, grad_next, s);
      const double model = grad_y.dot(next - y) + 0.5 * L * (next - y).cwiseAbs2().cwiseQuotient(D).sum();
      if (f_next <= f_y + model + 1e-14 * std::abs(f_y)) break;
      L *= 2.0;
    }
    if (++iteration % kCheckEvery == 0 || steps >= options.max_iterations) {
      const double merit = dual.merit(next, rows_next, q_norm);
      if (merit < answer.residual) answer.residual = merit, best = next;
    }

    // Nesterov's extrapolation, restarted when the step went uphill on the gradient
    // (taken with the shift at the new point)
    const double theta_next = 0.5 * (-theta * theta + theta * std::sqrt(theta * theta + 4.0));
    const double beta = theta * (1.0 - theta) / (theta * theta + theta_next);
    dual.shift(rows_next, s);
    dual.gradient(next, rows_next, s, grad_next);
    if (grad_next.dot(next - x) > 0) {
      y = next, rows_y = rows_next;
      theta = 1.0;
    } else {
      y = next + beta * (next - x);
      rows_y = rows_next + beta * (rows_next - rows);
      theta = theta_next;
    }
    x.swap(next), rows.swap(rows_next);
    L *= 0.9;  // let the step grow again where the problem allows it
  }
  answer.sweeps = steps;
  answer.capped = answer.residual > options.tolerance;
  answer.r = best.head(3 * nc);
  answer.l = best.tail(n - 3 * nc);
  return answer;
}

}  // namespace icedem
