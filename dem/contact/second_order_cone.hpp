// The algebra of the second-order cone Q = {x_0 >= |(x_1, x_2)|} that the interior-point
// contact method (dem/contact/interior_point.hpp) works in: the Jordan product, the step to
// the cone's boundary and the Nesterov-Todd scaling (Vandenberghe, "The CVXOPT linear and
// quadratic cone program solvers", 2010, section 4). e = (1, 0, 0), J = diag(1, -1, -1).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "dem/contact/problem.hpp"

namespace icedem::soc {

// det x = x_0^2 - |x_T|^2: positive inside Q, zero on its boundary
inline double cone_det(const Eigen::Vector3d& x) { return x(0) * x(0) - x(1) * x(1) - x(2) * x(2); }

// x o y, the Jordan product: (x . y, x_0 y_1 + y_0 x_1)
inline Eigen::Vector3d jordan(const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  return {x.dot(y), x(0) * y(1) + y(0) * x(1), x(0) * y(2) + y(0) * x(2)};
}

// the x with l o x = b, l interior
inline Eigen::Vector3d jordan_solve(const Eigen::Vector3d& l, const Eigen::Vector3d& b) {
  const double x0 = (l(0) * b(0) - l(1) * b(1) - l(2) * b(2)) / cone_det(l);
  return {x0, (b(1) - x0 * l(1)) / l(0), (b(2) - x0 * l(2)) / l(0)};
}

// The largest a with x + a d in Q (x interior), infinity if every a >= 0 keeps it there:
// the first positive root of det(x + a d) = c + 2 b a + q a^2.
inline double step_to_boundary(const Eigen::Vector3d& x, const Eigen::Vector3d& d) {
  const double q = cone_det(d), b = x(0) * d(0) - x(1) * d(1) - x(2) * d(2), c = cone_det(x);
  const double inf = std::numeric_limits<double>::infinity();
  if (q == 0) return b < 0 ? -c / (2 * b) : inf;
  const double disc = b * b - q * c;
  // q > 0 and no real root: det stays positive, and x + a d stays in Q (it cannot reach -Q);
  // a double root (d along x's axis, round-off either side of zero) is where x + a d passes
  // through the apex into -Q
  if (disc <= 1e-12 * b * b) return b < 0 ? -b / q : inf;
  // the roots, without cancellation: k / q and c / k
  const double k = -(b + std::copysign(std::sqrt(disc), b));
  double best = inf;
  for (double root : {k / q, k != 0 ? c / k : inf})
    if (root > 0) best = std::min(best, root);
  return best;
}

// The Nesterov-Todd scaling of one cone at (s, z), symmetric, with W z = W^-1 s = lambda:
// W = eta [[w_0, w_T^T], [w_T, I + w_T w_T^T / (1 + w_0)]], a hyperbolic rotation scaled by
// eta = (det s / det z)^(1/4), and W^-1 = J W J / eta^2 (Domahidi, Chu and Boyd, "ECOS: an
// SOCP solver for embedded systems", 2013, section 5; a test checks both identities)
struct Scaling {
  Eigen::Matrix3d W, W_inv;
  Eigen::Vector3d lambda;
};
inline Scaling nesterov_todd(const Eigen::Vector3d& s, const Eigen::Vector3d& z) {
  const double ds = std::sqrt(cone_det(s)), dz = std::sqrt(cone_det(z));
  const Eigen::Vector3d sn = s / ds, zn = z / dz;
  const double gamma = std::sqrt(0.5 * (1.0 + sn.dot(zn)));
  const Eigen::Vector3d w = (sn + Eigen::Vector3d(zn(0), -zn(1), -zn(2))) / (2.0 * gamma);
  const double eta = std::sqrt(ds / dz);
  const Eigen::Vector2d wt = w.tail<2>();
  Scaling sc;
  sc.W(0, 0) = w(0);
  sc.W.block<1, 2>(0, 1) = wt.transpose();
  sc.W.block<2, 1>(1, 0) = wt;
  sc.W.block<2, 2>(1, 1) = Eigen::Matrix2d::Identity() + wt * wt.transpose() / (1.0 + w(0));
  const Eigen::Matrix3d J = Eigen::Vector3d(1, -1, -1).asDiagonal();
  sc.W_inv = J * sc.W * J / eta;
  sc.W *= eta;
  sc.lambda = sc.W * z;
  return sc;
}

// pushes x into Q until its smaller eigenvalue x_0 - |x_T| is at least `margin`
inline void push_inside(Eigen::Vector3d& x, double margin) {
  const double smallest = x(0) - tangential_norm(x(1), x(2));
  if (smallest < margin) x(0) += margin - smallest;
}

}  // namespace icedem::soc
