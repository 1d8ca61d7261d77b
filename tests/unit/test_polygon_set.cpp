// Regions of any shape (dem/layout/polygon_set.hpp) and their convex parts (dem/layout/convex_partition.hpp):
// the Boolean operations keep area, a cut that would leave a hole is refused, and a non-convex outline splits
// into convex parts of the same total area.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dem/layout/convex_partition.hpp"
#include "dem/layout/polygon_set.hpp"
#include "tests/support/outline_file.hpp"

namespace icedem {
namespace {

Polygon rectangle(double x0, double z0, double x1, double z1) {
  return make_ccw({{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}});
}

double total_area(const std::vector<Polygon>& parts) {
  double a = 0;
  for (const Polygon& p : parts) a += area(p);
  return a;
}

// Overlapping rectangles: the intersection and the difference are rectangles whose areas add up to the
// first's (round-off: 1e-12 of the area), and both come back ccw
TEST(PolygonSet, IntersectionAndDifferenceShareTheArea) {
  const Polygon a = rectangle(0, 0, 4, 2), b = rectangle(3, -1, 6, 1);
  const std::vector<Polygon> in = intersect(a, b), out = subtract(a, b);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_NEAR(area(in[0]), 1.0, 1e-12);
  EXPECT_NEAR(total_area(in) + total_area(out), area(a), 1e-12 * area(a));
  for (const Polygon& p : out) EXPECT_GT(signed_area(p), 0);
  EXPECT_TRUE(intersect(a, rectangle(5, 5, 6, 6)).empty());
}

// A disc of n segments has the inscribed polygon's area, n/2 sin(2 pi / n) r^2
TEST(PolygonSet, ADiscIsItsInscribedPolygon) {
  const Polygon d = disc({1, 2}, 0.5, 64);
  EXPECT_EQ(d.size(), 64u);
  EXPECT_NEAR(area(d), 32 * std::sin(2 * M_PI / 64) * 0.25, 1e-12);
  EXPECT_TRUE(contains(d, {1, 2}));
  EXPECT_FALSE(contains(d, {1.6, 2}));
}

// Cutting a disc out of the middle of a region would leave a hole: refused, not dropped
TEST(PolygonSet, AHoleIsRefused) {
  EXPECT_THROW(subtract(rectangle(0, 0, 4, 4), disc({2, 2}, 0.5, 32)), std::logic_error);
}

// A cut across a strip leaves two parts
TEST(PolygonSet, ACutAcrossLeavesTwoParts) {
  const std::vector<Polygon> parts = subtract(rectangle(0, 0, 4, 1), rectangle(1.9, -1, 2.1, 2));
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_NEAR(total_area(parts), 3.8, 1e-12);
}

// The half-plane keeps the points on its normal's side
TEST(PolygonSet, AHalfPlaneKeepsItsSide) {
  const std::vector<Polygon> right = intersect(rectangle(0, 0, 2, 2), half_plane({0.5, 1}, {1, 0}, 10));
  ASSERT_EQ(right.size(), 1u);
  EXPECT_NEAR(area(right[0]), 3.0, 1e-12);
}

// An opening keeps what is wider than its width where it was (a square's corners and edges to round-off, 1e-12) and
// takes away a tongue narrower than it: a square with a 5 mm x 0.3 m tongue (0.0015 m^2) opened at 33 mm loses the
// tongue but for the stub at its root that the disc's cap reaches into (0.2 mm deep: 1e-5 m^2 bounds it), and
// the mitres of the stub's corners reach outside the region by no more than 1e-6 m^2 (5e-7 here: a thousandth
// of the ice's thickness squared); a corner of 60 degrees with long sides keeps its tip
TEST(PolygonSet, AnOpeningTakesTheTongueNarrowerThanItsWidth) {
  const Polygon square = make_ccw({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const std::vector<Polygon> same = opening(square, 0.033);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_NEAR(area(same[0]), 1.0, 1e-12);
  for (const Eigen::Vector2d& v : square) {
    double nearest = 1.0;
    for (const Eigen::Vector2d& w : same[0]) nearest = std::min(nearest, (v - w).norm());
    EXPECT_LT(nearest, 1e-12) << "corner " << v.transpose();
  }
  const Polygon tongued = make_ccw({{0, 0}, {1, 0}, {1, 0.5}, {1.3, 0.5}, {1.3, 0.505}, {1, 0.505}, {1, 1}, {0, 1}});
  const std::vector<Polygon> opened = opening(tongued, 0.033);
  ASSERT_EQ(opened.size(), 1u);
  EXPECT_GE(area(opened[0]), 1.0 - 1e-12);
  EXPECT_LT(area(opened[0]), 1.0 + 1e-5);
  double within = 0;
  for (const Polygon& p : intersect(opened[0], tongued)) within += area(p);
  EXPECT_NEAR(within, area(opened[0]), 1e-6);
  const double half = M_PI / 6;
  const Polygon corner = make_ccw({{0, 0}, {2 * std::cos(half), -2 * std::sin(half)}, {2 * std::cos(half), 2 * std::sin(half)}});
  const std::vector<Polygon> kept = opening(corner, 0.033);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NEAR(area(kept[0]), area(corner), 1e-12 * area(corner));
}

// A part of the sheet recorded from the level tow at dt 0.01 s (tests/unit/data/sheet_part_150s_dt001.txt): Boost's
// buffer shrinks it by 16.5 mm to three parts, 72.898 m^2 (less the band along its 76.2 m perimeter; necks narrower
// than 33 mm part off two small parts at its lower left), and growing the three back together answered 1e-8 m^2: the
// sheet was cut down to a speck and the run stopped. An opening holds what it shrank to, so the answer has at least
// that area (to round-off) and no more than the region's (to the mitres' hair, 1e-9 of it); here the region as it was.
TEST(PolygonSet, AnOpeningKeepsAtLeastWhatItShrankTo) {
  const Polygon part = testing::read_outline("sheet_part_150s_dt001.txt");
  ASSERT_EQ(part.size(), 130u);
  ASSERT_TRUE(is_simple(part));
  const std::vector<Polygon> opened = opening(part, 0.033);
  EXPECT_GE(total_area(opened), 72.898);
  EXPECT_LE(total_area(opened), area(part) * (1 + 1e-9));
}

// A notched outline (an L) is not convex: its parts are convex, cover its area, and are as few as can be (2)
TEST(ConvexPartition, AnLSplitsIntoTwoConvexParts) {
  const Polygon l = make_ccw({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  ASSERT_FALSE(is_convex(l));
  const std::vector<Polygon> parts = convex_parts(l);
  EXPECT_EQ(parts.size(), 2u);
  for (const Polygon& p : parts) {
    EXPECT_TRUE(is_convex(p));
    EXPECT_GT(signed_area(p), 0);
  }
  EXPECT_NEAR(total_area(parts), 3.0, 1e-12);
}

// A crescent (a disc less a disc that overlaps it) of many vertices: convex parts of the same area; a convex
// outline comes back whole
TEST(ConvexPartition, ACrescentSplitsIntoConvexPartsOfItsArea) {
  const std::vector<Polygon> crescent = subtract(disc({0, 0}, 1.0, 48), disc({0.8, 0}, 0.7, 48));
  ASSERT_EQ(crescent.size(), 1u);
  const std::vector<Polygon> parts = convex_parts(crescent[0]);
  EXPECT_GT(parts.size(), 1u);
  for (const Polygon& p : parts) EXPECT_TRUE(is_convex(p));
  EXPECT_NEAR(total_area(parts), area(crescent[0]), 1e-12 * area(crescent[0]));
  EXPECT_EQ(convex_parts(disc({0, 0}, 1.0, 16)).size(), 1u);
}

// A part of the sheet's outline after a cut 95 s into the paper's analytic tow at mu 0.3: the ring comes back to the cut
// vertex at (11.8037, 1.8254) along the line it reached it by, and off that line by round-off (3e-14 rad), so
// its two edges there cross and CGAL found it not simple: the run stopped. Without the spike it partitions into
// convex parts of its area.
TEST(ConvexPartition, ARingWithASpikeFromTheTowPartitions) {
  const Polygon recorded = {{11.803711461135789, 1.8253538131033327}, {11.806633217924983, 1.816391558773081},
                            {25.999999999999996, 2.3980000000000006}, {25.999999999999996, -2.3979999999999992},
                            {12.401033691543962, 0.58152063876998483}, {12.371539994252275, 0.66951210012099027},
                            {12.180618086941813, 0.66922300450087913}};
  const std::vector<Polygon> parts = convex_parts(recorded);
  ASSERT_FALSE(parts.empty());
  for (const Polygon& p : parts) EXPECT_TRUE(is_convex(p));
  // the spike had no area: the parts have the ring's (its shoelace area counts the spike's two edges once each way)
  EXPECT_NEAR(total_area(parts), area(recorded), 1e-9 * area(recorded));
  // and the one that stopped the tow at mu 0.2, 150 s in: a spike at its first vertex (9e-15 rad)
  const Polygon second = {{16.208789170232109, 0.31303676956769172}, {16.298554616970854, 0.21052327156580142},
                          {16.315737591165245, 0.22200456785841116}, {16.31012590220525, 0.24701929755749646},
                          {25.999999999999996, -2.3979999999999997}, {16.355283553810541, 0.14573796759143667}};
  const std::vector<Polygon> its_parts = convex_parts(second);
  ASSERT_FALSE(its_parts.empty());
  for (const Polygon& p : its_parts) EXPECT_TRUE(is_convex(p));
  EXPECT_NEAR(total_area(its_parts), area(second), 1e-9 * area(second));
}

}  // namespace
}  // namespace icedem
