// The shape of a floe or an ice element: everything about a body that follows
// from its outline and the ice, computed once per outline and never changed.
#pragma once

#include <map>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <btBulletDynamicsCommon.h>

#include "dem/layout/polygon.hpp"
#include "dem/water/hydrostatics.hpp"
#include "dem/water/water_forces.hpp"

namespace icedem {

/// Geometry and mass of every body with the same outline and thickness.
struct FloeShape {
  Polygon outline;           // local (x, z), m, centroid at origin, principal axes along x and z
  double principal_yaw;      // rad, yaw of the principal frame relative to the input outline
  ConvexPolyhedron prism;    // body frame, for hydrostatics
  double mass;               // kg
  Eigen::Vector3d inertia;   // kg m^2, principal moments about body x, y, z
  double radius;             // m, farthest outline vertex from the centroid
  DampingCoefficients damping;
  std::unique_ptr<btCollisionShape> collision;
};

/// Yaw that turns an outline's frame into the principal frame of its area
/// moments (the long axis becomes body x), rad.
double principal_yaw(const Polygon& outline);

/// The shape of a prism of `outline` (centroid at the origin), `thickness` thick,
/// of ice of `density`, in `water`: body axes along the outline's principal axes
/// so that Bullet's diagonal inertia is right.
std::unique_ptr<FloeShape> make_floe_shape(const Polygon& outline, double thickness, double density,
                                           const WaterParams& water);

/// Shapes by outline, each made once (a field of equal floes shares one).
class FloeShapes {
 public:
  FloeShapes(double thickness, double density, const WaterParams& water);
  const FloeShape& get(const Polygon& outline);

 private:
  double thickness_, density_;
  WaterParams water_;
  std::vector<std::unique_ptr<FloeShape>> shapes_;
  std::map<std::vector<double>, FloeShape*> by_outline_;
};

}  // namespace icedem
