#include "dem/world/floe_shape.hpp"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "dem/core/constants.hpp"
#include "dem/world/bullet_eigen.hpp"

namespace icedem {
namespace {

// an axis-aligned rectangle centred at the origin: its half extents, else none
bool rectangle_half_extents(const Polygon& p, double& hx, double& hz) {
  if (p.size() != 4) return false;
  hx = std::abs(p[0].x());
  hz = std::abs(p[0].y());
  const double tol = 1e-9 * (hx + hz);
  for (const Eigen::Vector2d& v : p)
    if (std::abs(std::abs(v.x()) - hx) > tol || std::abs(std::abs(v.y()) - hz) > tol) return false;
  return hx > 0 && hz > 0;
}

}  // namespace

double principal_yaw(const Polygon& outline) {
  const CentroidalMoments m = centroidal_moments(outline);
  const double scale = m.ixx + m.izz;
  if (std::abs(m.ixz) <= 1e-12 * scale && std::abs(m.ixx - m.izz) <= 1e-12 * scale) return 0.0;
  Eigen::Matrix2d tensor;
  tensor << m.ixx, m.ixz, m.ixz, m.izz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(tensor);
  const Eigen::Vector2d e1 = eig.eigenvectors().col(1);  // the long axis becomes body x
  return std::atan2(-e1.y(), e1.x());  // body +x maps to (cos, -sin) under yaw (polygon.hpp)
}

std::unique_ptr<FloeShape> make_floe_shape(const Polygon& outline, double h, double density,
                                           const WaterParams& water) {
  auto s = std::make_unique<FloeShape>();
  s->principal_yaw = principal_yaw(outline);
  for (const Eigen::Vector2d& v : outline) s->outline.push_back(rotate(v, -s->principal_yaw));
  s->prism = make_prism(s->outline, h);
  s->radius = bounding_radius(s->outline);

  // about the centroid, which is the body origin (the outline is centred on it)
  const CentroidalMoments m = centroidal_moments(s->outline);
  s->mass = density * m.area * h;
  const double rho_h = density * h;
  const double plate = s->mass * h * h / 12;  // thickness contribution about horizontal axes
  s->inertia = {rho_h * m.izz + plate, rho_h * (m.ixx + m.izz), rho_h * m.ixx + plate};

  s->damping = damping_coefficients(s->prism, s->mass, std::min(s->inertia.x(), s->inertia.z()), water);

  // boxes keep their outer size under a margin and collide box-box (several points at
  // once); other convex outlines become hulls (the margin adds 1 mm around them)
  double hx, hz;
  if (rectangle_half_extents(s->outline, hx, hz)) {
    s->collision = std::make_unique<btBoxShape>(btVector3(hx, h / 2, hz));
  } else {
    auto hull = std::make_unique<btConvexHullShape>();
    for (const Eigen::Vector3d& p : s->prism.vertices) hull->addPoint(to_bt(p), false);
    hull->recalcLocalAabb();
    s->collision = std::move(hull);
  }
  s->collision->setMargin(kDefaultCollisionMargin);
  return s;
}

FloeShapes::FloeShapes(double thickness, double density, const WaterParams& water)
    : thickness_(thickness), density_(density), water_(water) {}

const FloeShape& FloeShapes::get(const Polygon& outline) {
  std::vector<double> key;
  for (const Eigen::Vector2d& v : outline) key.insert(key.end(), {v.x(), v.y()});
  if (auto it = by_outline_.find(key); it != by_outline_.end()) return *it->second;
  shapes_.push_back(make_floe_shape(outline, thickness_, density_, water_));
  return *(by_outline_[key] = shapes_.back().get());
}

}  // namespace icedem
