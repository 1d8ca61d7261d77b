// Unit tests of floe shapes (dem/world/floe_shape): mass and principal inertia of a prism against
// the closed forms, the principal frame of a turned outline, the bounding radius, the
// collision shape, and one shape per outline.
#include "dem/world/floe_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dem/core/constants.hpp"

namespace icedem {
namespace {

constexpr double kThickness = 0.033;  // m, the paper's model ice
constexpr double kDensity = 900.0;    // kg/m^3

Polygon rectangle(double a, double b, double yaw = 0.0) {
  Polygon p{{-a / 2, -b / 2}, {a / 2, -b / 2}, {a / 2, b / 2}, {-a / 2, b / 2}};
  for (Eigen::Vector2d& v : p) v = rotate(v, yaw);
  return p;
}

// A rectangular prism a (x) by h (y) by b (z): m = rho a b h and the principal moments
// m (h^2 + b^2) / 12 about x, m (a^2 + b^2) / 12 about y (vertical), m (a^2 + h^2) / 12 about z.
// Round-off only: the moments are sums of a handful of products of numbers near 1.
TEST(FloeShape, RectangularPrismHasTheClosedFormMassAndInertia) {
  const double a = 0.6, b = 0.3;
  const auto s = make_floe_shape(rectangle(a, b), kThickness, kDensity, WaterParams{});
  const double m = kDensity * a * b * kThickness;
  EXPECT_NEAR(s->mass, m, 1e-12 * m);
  const double h = kThickness;
  EXPECT_NEAR(s->inertia.x(), m * (h * h + b * b) / 12, 1e-12 * m);
  EXPECT_NEAR(s->inertia.y(), m * (a * a + b * b) / 12, 1e-12 * m);
  EXPECT_NEAR(s->inertia.z(), m * (a * a + h * h) / 12, 1e-12 * m);
  EXPECT_NEAR(s->radius, std::hypot(a / 2, b / 2), 1e-15);
  // an axis-aligned rectangle collides as a box (several contact points at once)
  EXPECT_EQ(s->collision->getShapeType(), BOX_SHAPE_PROXYTYPE);
}

// A turned rectangle: the shape's frame is its principal frame (the long side along body x),
// so its moments are those of the unturned one and the yaw undoes the turn (modulo a half
// turn, which maps a rectangle onto itself).
TEST(FloeShape, TurnedOutlineIsTurnedBackToItsPrincipalAxes) {
  const double a = 0.6, b = 0.3, turn = 0.4;
  const auto straight = make_floe_shape(rectangle(a, b), kThickness, kDensity, WaterParams{});
  const auto turned = make_floe_shape(rectangle(a, b, turn), kThickness, kDensity, WaterParams{});
  const double off = std::remainder(turned->principal_yaw - straight->principal_yaw - turn, kPi);
  EXPECT_NEAR(off, 0.0, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(turned->inertia[k], straight->inertia[k], 1e-12 * straight->inertia[k]);
  // the principal outline is the axis-aligned rectangle again: a box, not a hull
  EXPECT_EQ(turned->collision->getShapeType(), BOX_SHAPE_PROXYTYPE);
}

// A right triangle with legs a and b, centred on its centroid: area a b / 2, and about the
// vertical axis the polar moment of area (a^2 + b^2) a b / 36 (a triangle's centroidal
// moments are b h^3 / 36 about each leg's parallel).
TEST(FloeShape, TriangleHasTheClosedFormAreaAndPolarMoment) {
  const double a = 0.5, b = 0.3;
  Polygon tri{{0, 0}, {a, 0}, {0, b}};
  const Eigen::Vector2d c(a / 3, b / 3);
  for (Eigen::Vector2d& v : tri) v -= c;
  const auto s = make_floe_shape(tri, kThickness, kDensity, WaterParams{});
  const double m = kDensity * a * b / 2 * kThickness;
  EXPECT_NEAR(s->mass, m, 1e-12 * m);
  EXPECT_NEAR(s->inertia.y(), kDensity * kThickness * (a * a + b * b) * a * b / 36, 1e-12 * m);
  EXPECT_NE(s->collision->getShapeType(), BOX_SHAPE_PROXYTYPE);  // a hull
}

TEST(FloeShapes, OneShapePerOutline) {
  FloeShapes shapes(kThickness, kDensity, WaterParams{});
  const FloeShape& first = shapes.get(rectangle(0.3, 0.3));
  EXPECT_EQ(&shapes.get(rectangle(0.3, 0.3)), &first);
  EXPECT_NE(&shapes.get(rectangle(0.6, 0.3)), &first);
}

}  // namespace
}  // namespace icedem
