// The crushing contact law (dem/contact/crushing.hpp) and its nominal contact area
// (dem/contact/contact_area.hpp) against the closed forms of docs/model/crushing.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "dem/contact/contact_area.hpp"
#include "dem/contact/crushing.hpp"
#include "dem/contact/problem.hpp"
#include "dem/contact/projection_jacobian.hpp"
#include "dem/world/cone_geometry.hpp"
#include "tests/support/boost_section.hpp"

using namespace icedem;

namespace {

constexpr double kThickness = 0.033;    // m, the paper's model ice
constexpr double kStrength = 145.6e3;   // Pa, its compressive strength (the paper's Table 3)

// the eight corners of a box of half sizes `half`, turned by `yaw` about the vertical (y) and
// placed at `centre`
std::vector<Eigen::Vector3d> box(const Eigen::Vector3d& half, double yaw, const Eigen::Vector3d& centre) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 8; ++i)
    v.push_back(centre + turn * Eigen::Vector3d((i & 1 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(),
                                                (i & 4 ? 1 : -1) * half.z()));
  return v;
}

// a square floe of side `side` whose corner points along +x (yaw 45 degrees), and the plane
// of a face whose normal is `beta` from the horizontal, pressed `delta` into the corner's
// first point
struct CornerCase {
  std::vector<Eigen::Vector3d> floe;
  Plane face;
};
CornerCase corner(double side, double beta, double delta) {
  CornerCase c{box({side / 2, kThickness / 2, side / 2}, M_PI / 4, Eigen::Vector3d::Zero()), {}};
  const Eigen::Vector3d n(std::cos(beta), std::sin(beta), 0.0);  // out of the floe, into the face
  double first = -1e9;
  for (const auto& v : c.floe) first = std::max(first, n.dot(v));
  c.face = Plane{n * (first - delta), n};
  return c;
}

}  // namespace

// Daley's wedge: a corner of opening angle phi pressed delta into a face whose normal is beta
// from the horizontal has the nominal area delta^2 tan(phi/2) / (sin beta cos^2 beta): 2.8284
// delta^2 for the square floe's corner on the 45-degree cone. The section is exact geometry:
// to round-off while the cut stays within the thickness (delta <= h sin beta = 23 mm)
TEST(ContactArea, ASquareCornerOnTheConesFaceIsDaleysWedge) {
  const double beta = M_PI / 4;
  for (double delta : {1e-3, 2e-3, 5e-3, 20e-3}) {
    const CornerCase c = corner(0.6, beta, delta);
    const double daley = delta * delta * std::tan(M_PI / 4) / (std::sin(beta) * std::pow(std::cos(beta), 2));
    EXPECT_NEAR(section_area(c.floe, c.face), daley, 1e-12) << "delta " << delta;
  }
}

// A straight edge of width w pressed flat into the face: w delta / (sin beta cos beta) until the
// whole thickness touches, then w h / cos beta
TEST(ContactArea, AStraightEdgeGrowsLinearlyUntilTheThicknessIsInContact) {
  const double beta = M_PI / 4, w = 0.3;
  const auto floe = box({w / 2, kThickness / 2, w / 2}, 0.0, Eigen::Vector3d::Zero());
  const Eigen::Vector3d n(std::cos(beta), std::sin(beta), 0.0);
  double first = -1e9;
  for (const auto& v : floe) first = std::max(first, n.dot(v));
  for (double delta : {5e-3, 20e-3}) {
    const double expected = w * delta / (std::sin(beta) * std::cos(beta));
    EXPECT_NEAR(section_area(floe, Plane{n * (first - delta), n}), expected, 1e-12) << "delta " << delta;
  }
  const double full = w * kThickness / std::cos(beta);
  EXPECT_NEAR(section_area(floe, Plane{n * (first - 0.030), n}), full, 1e-12);
  EXPECT_EQ(section_area(floe, Plane{n * (first + 1e-3), n}), 0.0) << "a plane that misses the floe";
}

// Two floes overlapping edge to edge: their common section is the shorter edge's width times
// the thickness (the vertical faces' contact, A = w h)
TEST(ContactArea, TwoFloesPressedEdgeToEdgeShareTheShorterEdge) {
  const auto a = box({0.15, kThickness / 2, 0.15}, 0.0, Eigen::Vector3d(-0.149, 0, 0));
  const auto b = box({0.15, kThickness / 2, 0.10}, 0.0, Eigen::Vector3d(0.149, 0, 0.05));
  const double common = common_section_area(a, b, Plane{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()});
  EXPECT_NEAR(common, 0.20 * kThickness, 1e-12);
}

// icedem's own hull and clipping against Boost.Geometry's on floes turned, tilted and
// overlapping every way: the sections to round-off; the common part the same whichever
// section clips the other (to round-off), and Boost.Geometry's to 1e-7 m^2 (0.015 N of
// crushing force): its intersection rescales the points to integers over the polygons'
// extent for its robustness, which leaves its areas good to a few 1e-9 m^2 (measured: at
// most 6e-9 on these trials)
TEST(ContactArea, OwnHullAndClippingAreBoostGeometrys) {
  std::srand(7);
  auto uniform = [](double lo, double hi) { return lo + (hi - lo) * std::rand() / double(RAND_MAX); };
  int cut = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(uniform(-0.3, 0.3), Eigen::Vector3d::UnitX()) *
                                  Eigen::AngleAxisd(uniform(-0.3, 0.3), Eigen::Vector3d::UnitZ()))
                                     .toRotationMatrix();
    auto a = box({uniform(0.05, 0.3), kThickness / 2, uniform(0.05, 0.3)}, uniform(0, M_PI), Eigen::Vector3d::Zero());
    auto b = box({uniform(0.05, 0.3), kThickness / 2, uniform(0.05, 0.3)}, uniform(0, M_PI),
                 Eigen::Vector3d(uniform(-0.3, 0.3), uniform(-0.02, 0.02), uniform(-0.3, 0.3)));
    for (auto& v : a) v = tilt * v;
    const Eigen::Vector3d n = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
    const Plane plane{Eigen::Vector3d(uniform(-0.1, 0.1), uniform(-0.01, 0.01), uniform(-0.1, 0.1)), n};
    const double own = section_area(a, plane), reference = icedem::testing::boost_section_area(a, plane);
    EXPECT_NEAR(own, reference, 1e-12 + 1e-10 * reference) << "trial " << trial;
    const double common = common_section_area(a, b, plane);
    EXPECT_NEAR(common, common_section_area(b, a, plane), 1e-14 + 1e-12 * common) << "trial " << trial;
    EXPECT_NEAR(common, icedem::testing::boost_common_section_area(a, b, plane), 1e-7) << "trial " << trial;
    cut += common > 0;
  }
  EXPECT_GT(cut, 100) << "the trials must overlap often enough to test the clipping";
}

// The force of the law at constant pressure on the corner: F = sigma_c A = 4.118e5 delta^2 N
// (0.412, 1.647, 10.30 N at 1, 2 and 5 mm); with Daley's exponent the pressure is sigma_c at
// the reference area h^2 and falls with the area
TEST(CrushingLaw, ForceIsThePressureOverTheNominalArea) {
  const CrushingLaw law{kStrength, 0.0, kThickness * kThickness};
  const double K = kStrength / 0.35355339059327373;
  for (double delta : {1e-3, 2e-3, 5e-3}) {
    const double area = section_area(corner(0.6, M_PI / 4, delta).floe, corner(0.6, M_PI / 4, delta).face);
    EXPECT_NEAR(crushing_force(law, area), K * delta * delta, 1e-9 * K * delta * delta);
  }
  EXPECT_NEAR(K * 1e-6, 0.412, 0.001);
  const CrushingLaw daley{kStrength, -0.1, kThickness * kThickness};
  EXPECT_DOUBLE_EQ(crushing_pressure(daley, kThickness * kThickness), kStrength);
  EXPECT_GT(crushing_pressure(daley, 1e-4), kStrength);
  EXPECT_EQ(crushing_force(law, 0.0), 0.0);
}

// The projection onto a crushing contact's set, the friction cone cut at r_N = cap, is the
// nearest point of that set: checked against the nearest of a fine grid of its points, for
// points inside, below the cut, above it and in the polar cone
TEST(CrushingLaw, ProjectionOntoTheCutConeIsTheNearestPoint) {
  const double mu = 0.3, cap = 1.0;
  const std::vector<Eigen::Vector3d> points = {{0.5, 0.1, 0.0},  {0.5, 0.4, -0.2}, {2.0, 0.1, 0.05},
                                               {1.5, 0.9, -0.6}, {-1.0, 0.1, 0.0}, {0.2, 3.0, 1.0},
                                               {1.1, 0.2, 0.3},  {3.0, 5.0, 0.0}};
  for (const Eigen::Vector3d& x : points) {
    const Eigen::Vector3d p = project_on_contact(x, mu, cap);
    EXPECT_LE(p(0), cap + 1e-15);
    EXPECT_LE(std::hypot(p(1), p(2)), mu * p(0) + 1e-12);
    double nearest = 1e9;
    const int n = 200;
    for (int i = 0; i <= n; ++i) {
      const double normal = cap * i / n;
      for (int j = 0; j <= 40; ++j)
        for (int k = 0; k < 72; ++k) {
          const double radius = mu * normal * j / 40, angle = 2 * M_PI * k / 72;
          nearest = std::min(nearest, (x - Eigen::Vector3d(normal, radius * std::cos(angle), radius * std::sin(angle))).norm());
        }
    }
    EXPECT_LE((x - p).norm(), nearest + 1e-12) << "x = " << x.transpose();
    EXPECT_NEAR((x - p).norm(), nearest, 0.01) << "x = " << x.transpose() << ": the grid's spacing";
  }
}

// The Newton method's Hessian takes each contact's projection derivative
// (dem/contact/projection_jacobian.hpp): against central differences of project_on_contact in
// each of its five regions (apex, inside, the cone's surface, the cut's disc, its rim), away
// from the regions' borders where it is not differentiable. 1e-6: the differences' truncation
// error at a step of 1e-6 on a surface whose curvature is of order 1
TEST(CrushingLaw, ProjectionDerivativeIsTheProjectionsInEachRegion) {
  const double mu = 0.3, cap = 1.0;
  const std::vector<std::pair<Eigen::Vector3d, int>> points = {
      {{-1.0, 0.1, 0.05}, 0}, {{0.5, 0.1, -0.05}, 1}, {{0.5, 0.4, -0.2}, 2},
      {{2.0, 0.1, 0.05}, 3},  {{1.5, 0.9, -0.6}, 4},  {{0.3, 0.6, 0.2}, 2}};
  for (const auto& [x, region] : points) {
    int kind = -1;
    const Eigen::Matrix3d d = contact_projection_jacobian(x, mu, cap, kind);
    EXPECT_EQ(kind, region) << "x = " << x.transpose();
    const double step = 1e-6;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(k) * step;
      const Eigen::Vector3d column = (project_on_contact(x + e, mu, cap) - project_on_contact(x - e, mu, cap)) / (2 * step);
      EXPECT_LT((d.col(k) - column).norm(), 1e-6) << "x = " << x.transpose() << ", column " << k;
    }
    // and a rigid contact (cap infinite) is the cone's: the cut never reached
    double tangent = 0.0;
    EXPECT_LE(contact_region(x, mu, std::numeric_limits<double>::infinity(), tangent), 2);
  }
}

// Ice pressed into a curved hull crushes over the overlap seen along the contact normal, not
// over its whole section by the tangent plane: a floe's straight side laid flat on a facet of
// a faceted vertical cylinder (the structure's hull pieces, dem/world/cone_geometry.hpp, 48
// facets of the paper's waterline radius) and pressed delta into it overlaps the hull over
// the facet's chord plus, on either side, the strip where the plane delta deep cuts the
// neighbouring facets, delta / tan(2 pi / 48) wide: (chord + 2 delta / tan(2 pi / 48)) h,
// exactly while that strip stays on the neighbours (delta < 5 mm), against 0.6 h for the
// tangent plane's section (the area before 2026-11-29, 7 times larger)
TEST(ContactArea, AStraightSideOnTheFacetedHullCrushesOverTheFacetsWidth) {
  const int segments = 48;
  const double radius = 0.614, side = 0.6;
  const std::vector<ProfileStation> profile = {{-0.1, radius}, {0.1, radius}};
  const std::vector<Eigen::Vector3d> hull = hull_pieces(profile, segments).front();
  // the facet between the first two vertices (on +x and 7.5 degrees on): its outward normal and
  // the distance of its plane from the axis
  const double half_angle = M_PI / segments, vertex_radius = equal_area_vertex_radius(radius, segments);
  const Eigen::Vector3d normal(std::cos(half_angle), 0.0, std::sin(half_angle));
  const double apothem = vertex_radius * std::cos(half_angle), chord = 2 * vertex_radius * std::sin(half_angle);
  for (double delta : {0.5e-3, 2e-3, 4e-3}) {
    // the floe level at the waterline, its side parallel to the facet, delta inside it
    const double yaw = -half_angle;  // turns the floe's +x side onto the facet's normal
    const Eigen::Vector3d centre = normal * (apothem + side / 2 - delta);
    const std::vector<Eigen::Vector3d> floe = box({side / 2, kThickness / 2, side / 2}, yaw, centre);
    const Plane surface{normal * apothem, normal}, deepest{normal * (apothem - delta), normal};
    const double expected = (chord + 2 * delta / std::tan(2 * half_angle)) * kThickness;
    EXPECT_NEAR(common_section_area(floe, surface, hull, deepest), expected, 1e-9) << "delta " << delta;
    EXPECT_NEAR(section_area(floe, surface), side * kThickness, 1e-9);
  }
}
