// The derivative of a contact's projection (project_on_contact, dem/contact/problem.hpp):
// the generalised Jacobian the primal Newton method (dem/contact/newton.cpp) puts in its
// Hessian, region by region of the friction cone cut at the normal cap.
#pragma once

#include <Eigen/Core>

#include "dem/contact/problem.hpp"

namespace icedem {

// Where project_on_contact takes x (the cone, cut at x_N = cap where the contact crushes):
// 0 to the apex, 1 inside (x itself), 2 onto the cone's surface, 3 onto the cut's disc,
// 4 onto the disc's rim; `tangent` gets |x_T|. A rigid contact's cap is infinite: 0-2 only.
inline int contact_region(const Eigen::Vector3d& x, double mu, double cap, double& tangent) {
  tangent = tangential_norm(x(1), x(2));
  const int cone = mu * tangent <= -x(0) ? 0 : tangent <= mu * x(0) ? 1 : 2;
  const double normal = cone == 0 ? 0.0 : cone == 1 ? x(0) : (x(0) + mu * tangent) / (1.0 + mu * mu);
  if (normal <= cap) return cone;
  return tangent <= mu * cap ? 3 : 4;
}

// The derivative of project_on_contact at x (symmetric, its eigenvalues in [0, 1]) in
// `kind`, the contact_region of x.
inline Eigen::Matrix3d contact_projection_jacobian(const Eigen::Vector3d& x, double mu, double cap, int& kind) {
  double tangent;
  kind = contact_region(x, mu, cap, tangent);
  if (kind == 0) return Eigen::Matrix3d::Zero();
  if (kind == 1) return Eigen::Matrix3d::Identity();
  Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
  if (kind == 3) {  // onto the disc: the normal held at the cap, the tangent free
    d(1, 1) = d(2, 2) = 1.0;
    return d;
  }
  const Eigen::Vector2d t = x.tail<2>() / tangent;
  if (kind == 4) {  // onto the rim (cap, mu cap t): only t turns with x_T
    d.block<2, 2>(1, 1) = (mu * cap / tangent) * (Eigen::Matrix2d::Identity() - t * t.transpose());
    return d;
  }
  // onto the surface: P = (a, mu a t), a = (x_N + mu |x_T|) / (1 + mu^2), t = x_T / |x_T|
  const double k = 1.0 / (1.0 + mu * mu), a = k * (x(0) + mu * tangent);
  d(0, 0) = k;
  d.block<1, 2>(0, 1) = k * mu * t.transpose();
  d.block<2, 1>(1, 0) = k * mu * t;
  d.block<2, 2>(1, 1) =
      k * mu * mu * t * t.transpose() + (mu * a / tangent) * (Eigen::Matrix2d::Identity() - t * t.transpose());
  return d;
}

}  // namespace icedem
