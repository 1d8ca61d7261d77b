// The structure's geometry from its profile: Table 2 dimensions, the faceted
// hull keeps the cross-section areas, and the STL is a closed outward surface.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <Eigen/Geometry>

#include "dem/core/constants.hpp"
#include "dem/world/cone_geometry.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;

namespace {
const std::vector<ProfileStation> kTable2 = icedem::testing::scene_from("").structure.profile;
}

TEST(ConeGeometry, DefaultProfileHasTable2Dimensions) {
  // Table 2: waterline breadth 1.228 m, maximum breadth 1.472 m, draft 0.443 m, depth 0.565 m
  EXPECT_NEAR(2 * profile_radius(kTable2, 0.0), 1.228, 1e-12);
  EXPECT_NEAR(2 * kTable2.back().radius, 1.472, 1e-12);
  EXPECT_NEAR(-kTable2.front().y, 0.443, 1e-12);
  EXPECT_NEAR(kTable2.back().y - kTable2.front().y, 0.565, 1e-12);
  // 45 degrees from the horizontal above the waterline (docs/model/validation_targets.md §4a)
  const double slope = (kTable2[2].radius - kTable2[1].radius) / (kTable2[2].y - kTable2[1].y);
  EXPECT_NEAR(std::atan(slope) * 180 / kPi, 45.0, 1e-9);
}

TEST(ConeGeometry, RadiusIsZeroOutsideTheProfile) {
  EXPECT_EQ(profile_radius(kTable2, -0.5), 0.0);
  EXPECT_EQ(profile_radius(kTable2, 0.2), 0.0);
  EXPECT_NEAR(profile_radius(kTable2, -0.2215), (0.171 + 0.614) / 2, 1e-12);
}

TEST(ConeGeometry, StraightConeIsOneConvexPiece) {
  EXPECT_EQ(hull_pieces(kTable2, 48).size(), 1u);
  // a cone topped by a cylinder has a kink: two pieces
  const std::vector<ProfileStation> kinked{{-0.4, 0.2}, {0.0, 0.6}, {0.3, 0.6}};
  EXPECT_EQ(hull_pieces(kinked, 48).size(), 2u);
}

TEST(ConeGeometry, FacetedHullKeepsTheFrustumVolume) {
  // equal-area polygons make every section's area exact, so the faceted
  // frustum's volume equals the round one's: pi h/3 (R^2 + R r + r^2)
  const TriangleMesh mesh = hull_surface(kTable2, 48);
  double exact = 0;
  for (std::size_t i = 1; i < kTable2.size(); ++i) {
    const double h = kTable2[i].y - kTable2[i - 1].y, r = kTable2[i - 1].radius, R = kTable2[i].radius;
    exact += kPi * h / 3 * (R * R + R * r + r * r);
  }
  EXPECT_NEAR(mesh_volume(mesh), exact, 1e-9 * exact);
}

TEST(ConeGeometry, SurfaceIsClosedAndOutward) {
  const TriangleMesh mesh = hull_surface(kTable2, 24);
  // closed: every directed edge appears once and its reverse once
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u);
  }
  // outward: side faces point away from the axis, caps up at the top and down at the bottom
  const double mid_y = (kTable2.front().y + kTable2.back().y) / 2;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const Eigen::Vector3d centre = (a + b + c) / 3;
    const bool cap = std::abs(n.y()) > 0.999 * n.norm();
    if (cap)
      EXPECT_GT(n.y() * (centre.y() - mid_y), 0);
    else
      EXPECT_GT(n.dot(Eigen::Vector3d(centre.x(), 0, centre.z())), 0);
  }
}

TEST(ConeGeometry, StlHasOneFacetPerTriangle) {
  const TriangleMesh mesh = hull_surface(kTable2, 16);
  const std::string path = std::string(ICEDEM_TEST_TMP) + "/hull.stl";
  write_stl(mesh, path, "cone", Eigen::Vector3d(2.0, 0, 0));
  std::ifstream in(path);
  std::string line;
  int facets = 0, vertices = 0;
  double min_x = 1e9;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "facet") ++facets;
    if (word == "vertex") {
      double x;
      s >> x;
      min_x = std::min(min_x, x);
      ++vertices;
    }
  }
  EXPECT_EQ(facets, static_cast<int>(mesh.triangles.size()));
  EXPECT_EQ(vertices, 3 * facets);
  // translated by the offset: the hull spans x = 2 -+ max radius
  EXPECT_NEAR(min_x, 2.0 - equal_area_vertex_radius(0.736, 16), 1e-6);
}

// hull_depth measures tunnelling in the stress suite: zero on the faceted hull's
// surface (at its vertices and at its face middles), the inscribed radius on
// the axis, negative outside (radially, above the deck, below the keel)
TEST(ConeGeometry, HullDepthIsZeroOnTheFacetedSurfaceAndPositiveInside) {
  const int n = 48;
  const double y = -0.1;
  const double vertex_r = equal_area_vertex_radius(profile_radius(kTable2, y), n);
  const double face_r = vertex_r * std::cos(kPi / n);
  EXPECT_NEAR(hull_depth(kTable2, n, {0.0, y, 0.0}), face_r, 1e-12);
  for (int k : {0, 5, 47}) {
    const double a = 2 * kPi * k / n;  // vertex k (the first on +x)
    EXPECT_NEAR(hull_depth(kTable2, n, {vertex_r * std::cos(a), y, vertex_r * std::sin(a)}), 0.0, 1e-12) << k;
    const double m = a + kPi / n;  // middle of the face after vertex k
    EXPECT_NEAR(hull_depth(kTable2, n, {face_r * std::cos(m), y, face_r * std::sin(m)}), 0.0, 1e-12) << k;
    const double out = face_r + 0.001;  // a millimetre outside, normal to the face
    EXPECT_NEAR(hull_depth(kTable2, n, {out * std::cos(m), y, out * std::sin(m)}), -0.001, 1e-12) << k;
  }
  EXPECT_LT(hull_depth(kTable2, n, {0.0, kTable2.front().y - 0.01, 0.0}), 0.0);  // below the keel
  EXPECT_LT(hull_depth(kTable2, n, {0.0, kTable2.back().y + 0.01, 0.0}), 0.0);   // above the deck
}
