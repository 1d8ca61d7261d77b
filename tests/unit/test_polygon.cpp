// Unit tests of the convex polygon geometry in the (x, z) plane (dem/layout/polygon.hpp):
// area and centroid, orientation, convexity, placement and the SAT overlap test.
#include "dem/layout/polygon.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dem/core/constants.hpp"

namespace icedem {
namespace {

// rounding of a handful of operations on coordinates of order 1 m is ~1e-16 m;
// 1e-12 is far above it and far below any physical length of interest
constexpr double kTol = 1e-12;

TEST(Polygon, SquareAreaIsSideSquared) {
  EXPECT_NEAR(area(square(0.3)), 0.09, kTol);
  EXPECT_NEAR(area(rectangle(2.0, 0.5)), 1.0, kTol);
}

TEST(Polygon, GeneratedShapesAreCcwSeenFromAbove) {
  EXPECT_GT(signed_area(square(0.3)), 0.0);
  EXPECT_GT(signed_area(rectangle(2.0, 0.5)), 0.0);
}

TEST(Polygon, CcwMeansTheSenseOfPositiveYaw) {
  // a point carried round by positive yaw steps traces a ccw polygon
  const Eigen::Vector2d p(1.0, 0.2);
  const Polygon traced = {rotate(p, 0.0), rotate(p, 2.0 * kPi / 3.0), rotate(p, 4.0 * kPi / 3.0)};
  EXPECT_GT(signed_area(traced), 0.0);
}

TEST(Polygon, ReversedOrderFlipsTheSignOfTheArea) {
  Polygon p = square(1.0);
  std::reverse(p.begin(), p.end());
  EXPECT_NEAR(signed_area(p), -1.0, kTol);
  EXPECT_NEAR(area(p), 1.0, kTol);
  const Polygon q = make_ccw(p);
  EXPECT_NEAR(signed_area(q), 1.0, kTol);
  // make_ccw leaves an already ccw polygon untouched
  EXPECT_EQ(make_ccw(square(1.0)), square(1.0));
}

TEST(Polygon, TriangleCentroidIsTheVertexMean) {
  const Polygon t = {{0.0, 0.0}, {3.0, 0.0}, {0.0, 3.0}};
  EXPECT_NEAR(centroid(t).x(), 1.0, kTol);
  EXPECT_NEAR(centroid(t).y(), 1.0, kTol);
}

TEST(Polygon, LShapeCentroidIsTheAreaWeightedMeanOfItsRectangles) {
  // [0,2]x[0,1] (area 2, centroid (1, 0.5)) plus [0,1]x[1,2] (area 1, centroid (0.5, 1.5))
  const Polygon l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_NEAR(area(l), 3.0, kTol);
  EXPECT_NEAR(centroid(l).x(), 2.5 / 3.0, kTol);
  EXPECT_NEAR(centroid(l).y(), 2.5 / 3.0, kTol);
}

TEST(Polygon, CentroidOfAFarAwaySquareIsItsCentre) {
  const Polygon far = transformed(square(0.3), {1.0e4, -3.0e3}, 0.3);
  // coordinates of 1e4 m carry rounding of ~1e-12 m; allow 1e-9 m
  EXPECT_NEAR(centroid(far).x(), 1.0e4, 1e-9);
  EXPECT_NEAR(centroid(far).y(), -3.0e3, 1e-9);
}

TEST(Polygon, ConvexPolygonsInEitherOrderAreConvex) {
  EXPECT_TRUE(is_convex(square(0.3)));
  Polygon cw = square(0.3);
  std::reverse(cw.begin(), cw.end());
  EXPECT_TRUE(is_convex(cw));
  EXPECT_TRUE(is_convex(Polygon{{0, 0}, {1, 0}, {0, 1}}));
  // a vertex in the middle of a straight edge does not spoil convexity
  EXPECT_TRUE(is_convex(Polygon{{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

// repeated, straight-on and spike vertices go; every real corner stays, however sharp (a wedge of a
// thousandth of a radian is ice, a fold-back within kSpikeAngle is round-off)
TEST(Polygon, DegenerateVerticesAreDroppedAndCornersKept) {
  // a square with a vertex mid-edge, a repeated corner and a spike from (1, 1) up to (1, 2) and back, 2e-9 rad off
  const Polygon messy = {{0, 0}, {0.5, 0}, {1, 0}, {1, 0}, {1, 1}, {1, 2}, {1 + 1e-9, 1}, {0, 1}};
  const Polygon clean = without_degenerate_vertices(messy);
  ASSERT_EQ(clean.size(), 4u);
  for (const Eigen::Vector2d& v : clean) EXPECT_LT(v.y(), 1.5);  // the spike's tip is gone
  EXPECT_NEAR(area(clean), 1.0, 1e-8);
  // a sharp wedge is a corner
  EXPECT_EQ(without_degenerate_vertices({{0, 0}, {10, -0.01}, {10, 0}}).size(), 3u);
  EXPECT_TRUE(without_degenerate_vertices({{0, 0}, {1, 0}, {2, 0}}).empty());  // no area
}

TEST(Polygon, ReflexCornerIsNotConvex) {
  const Polygon l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_FALSE(is_convex(l));
}

TEST(Polygon, SelfIntersectingOutlinesAreNotConvex) {
  // bow tie: the corners alternate their turning sense
  EXPECT_FALSE(is_convex(Polygon{{0, 0}, {1, 1}, {1, 0}, {0, 1}}));
  // pentagram: every corner turns the same way, but the outline winds twice
  Polygon star;
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * kPi * 2.0 * k / 5.0;
    star.emplace_back(std::cos(a), std::sin(a));
  }
  EXPECT_FALSE(is_convex(star));
}

TEST(Polygon, DegeneratePolygonsAreNotConvex) {
  EXPECT_FALSE(is_convex(Polygon{}));
  EXPECT_FALSE(is_convex(Polygon{{0, 0}, {1, 0}}));
  // collinear points: zero area
  EXPECT_FALSE(is_convex(Polygon{{0, 0}, {1, 0}, {2, 0}}));
  // repeated vertex
  EXPECT_FALSE(is_convex(Polygon{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}}));
  // a spike folding back along an edge
  EXPECT_FALSE(is_convex(Polygon{{0, 0}, {2, 0}, {1, 0}, {1, 1}}));
  // non-finite vertex
  EXPECT_FALSE(is_convex(Polygon{{0, 0}, {1, 0}, {std::nan(""), 1}}));
}

TEST(Polygon, PositiveYawTurnsXTowardsMinusZ) {
  // docs/model/architecture.md: x' = x cos t + z sin t, z' = -x sin t + z cos t
  const Eigen::Vector2d p = rotate({1.0, 0.0}, kPi / 2.0);
  EXPECT_NEAR(p.x(), 0.0, kTol);
  EXPECT_NEAR(p.y(), -1.0, kTol);
  const Eigen::Vector2d q = rotate({0.3, -0.7}, 0.4);
  EXPECT_NEAR(q.x(), 0.3 * std::cos(0.4) - 0.7 * std::sin(0.4), kTol);
  EXPECT_NEAR(q.y(), -0.3 * std::sin(0.4) - 0.7 * std::cos(0.4), kTol);
}

TEST(Polygon, TransformedPlacesThenInverseRestores) {
  const Polygon local = {{0.2, -0.1}, {0.1, 0.3}, {-0.3, 0.05}};
  const Eigen::Vector2d centre(12.5, -1.7);
  const double yaw = 0.7;
  const Polygon world = transformed(local, centre, yaw);
  for (size_t k = 0; k < local.size(); ++k) {
    EXPECT_NEAR((world[k] - centre - rotate(local[k], yaw)).norm(), 0.0, kTol);
  }
  // inverse placement: rotate by -yaw about the origin after moving the centre there
  const Polygon back = transformed(world, -rotate(centre, -yaw), -yaw);
  for (size_t k = 0; k < local.size(); ++k) {
    EXPECT_NEAR((back[k] - local[k]).norm(), 0.0, kTol);
  }
  // a rigid motion keeps area and moves the centroid with the body
  EXPECT_NEAR(area(world), area(local), kTol);
  EXPECT_NEAR((centroid(world) - centre - rotate(centroid(local), yaw)).norm(), 0.0, kTol);
}

TEST(Polygon, BoundingRadiusOfASquareIsHalfItsDiagonal) {
  EXPECT_NEAR(bounding_radius(square(0.3)), 0.3 / std::sqrt(2.0), kTol);
}

TEST(Overlap, SeparatedSquaresDoNotOverlap) {
  const Polygon a = transformed(square(1.0), {0, 0}, 0.0);
  const Polygon b = transformed(square(1.0), {1.5, 0.2}, 0.0);
  EXPECT_FALSE(overlap(a, b));
  EXPECT_FALSE(overlap(b, a));
  EXPECT_NEAR(distance(a, b), 0.5, kTol);
}

TEST(Overlap, InterpenetratingSquaresOverlap) {
  const Polygon a = transformed(square(1.0), {0, 0}, 0.0);
  const Polygon b = transformed(square(1.0), {0.9, 0.3}, 0.3);
  EXPECT_TRUE(overlap(a, b));
  EXPECT_TRUE(overlap(b, a));
  EXPECT_EQ(distance(a, b), 0.0);
  // one inside the other
  EXPECT_TRUE(overlap(square(1.0), square(0.2)));
}

TEST(Overlap, EdgeToEdgeTouchingIsNotOverlapButIsWithinAGap) {
  // exactly representable: [0,1] and [1,2] along x share the edge x = 1
  const Polygon a = transformed(square(1.0), {0.5, 0.5}, 0.0);
  const Polygon b = transformed(square(1.0), {1.5, 0.75}, 0.0);
  EXPECT_FALSE(overlap(a, b, 0.0));
  EXPECT_TRUE(overlap(a, b, 1e-3));
}

TEST(Overlap, CornerTouchingAnEdgeExactlyIsNotOverlap) {
  // a diamond whose left corner lies exactly on the right edge x = 1 of the unit square
  const Polygon sq = {{1, 1}, {1, 0}, {0, 0}, {0, 1}};
  const Polygon diamond = {{1, 0.5}, {1.5, 1}, {2, 0.5}, {1.5, 0}};
  EXPECT_FALSE(overlap(sq, diamond, 0.0));
  EXPECT_FALSE(overlap(diamond, sq, 0.0));
  EXPECT_TRUE(overlap(sq, diamond, 1e-3));
}

TEST(Overlap, RotatedSquareCornerAgainstAnEdge) {
  // a unit square turned by 45 degrees reaches sqrt(2)/2 from its centre; its
  // corner sits at x = 0.5 + d against the edge x = 0.5 of the square at the origin
  const Polygon a = transformed(square(1.0), {0, 0}, 0.0);
  const double reach = std::sqrt(2.0) / 2.0;
  // d = +-1e-9 m: far beyond the ~1e-16 m rounding of sin/cos and the sums,
  // so each case is unambiguous
  for (double yaw : {kPi / 4.0, -kPi / 4.0, 3.0 * kPi / 4.0}) {
    const Polygon apart = transformed(square(1.0), {0.5 + reach + 1e-9, 0.1}, yaw);
    const Polygon into = transformed(square(1.0), {0.5 + reach - 1e-9, 0.1}, yaw);
    EXPECT_FALSE(overlap(a, apart)) << "yaw " << yaw;
    EXPECT_TRUE(overlap(a, into)) << "yaw " << yaw;
    EXPECT_FALSE(overlap(apart, a)) << "yaw " << yaw;
    EXPECT_TRUE(overlap(into, a)) << "yaw " << yaw;
    EXPECT_NEAR(distance(a, apart), 1e-9, 1e-14);  // rounding of ~1 m coordinates
  }
}

TEST(Overlap, GapIsTheTrueDistanceAcrossACornerToCornerDiagonal) {
  // squares offset diagonally by 0.01 m on each axis: the SAT separation is
  // 0.01 m but the corners are 0.01 * sqrt(2) = 0.01414 m apart
  const Polygon a = transformed(square(1.0), {0, 0}, 0.0);
  const Polygon b = transformed(square(1.0), {1.01, 1.01}, 0.0);
  EXPECT_NEAR(distance(a, b), 0.01 * std::sqrt(2.0), kTol);
  EXPECT_FALSE(overlap(a, b, 0.012));
  EXPECT_TRUE(overlap(a, b, 0.015));
}

TEST(Overlap, PolygonOrientationDoesNotMatter) {
  Polygon a = transformed(square(1.0), {0, 0}, 0.2);
  Polygon b = transformed(rectangle(1.0, 0.4), {0.95, 0.1}, -0.3);
  const bool expected = overlap(a, b);
  std::reverse(a.begin(), a.end());
  EXPECT_EQ(overlap(a, b), expected);
  std::reverse(b.begin(), b.end());
  EXPECT_EQ(overlap(a, b), expected);
  EXPECT_TRUE(expected);
}

TEST(Polygon, ConvexHullDropsInnerAndCollinearPoints) {
  // a 2 x 1 rectangle's corners, an inner point and a point on an edge, shuffled
  const Polygon hull = convex_hull({{2, 1}, {1, 0.5}, {0, 0}, {1, 0}, {0, 1}, {2, 0}});
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_LT(signed_area(hull), 0.0);  // from +x towards +z: clockwise seen from above
  EXPECT_DOUBLE_EQ(area(hull), 2.0);
  EXPECT_TRUE(convex_hull({{0, 0}, {1, 1}}).size() < 3u);  // no area
}

TEST(Polygon, CentroidalMomentsOfARectangleFarFromTheOriginAreItsOwn) {
  // a 0.6 x 0.3 rectangle 1 km away: b h^3 / 12 about its centroid, not swamped by the offset
  const double b = 0.6, h = 0.3, x0 = 1000.0, z0 = -500.0;
  const CentroidalMoments m =
      centroidal_moments({{x0, z0}, {x0 + b, z0}, {x0 + b, z0 + h}, {x0, z0 + h}});
  EXPECT_NEAR(m.area, b * h, 1e-12);
  EXPECT_NEAR(m.centroid.x(), x0 + b / 2, 1e-9);
  EXPECT_NEAR(m.centroid.y(), z0 + h / 2, 1e-9);
  // 1e-9 relative: the sums are taken about the first vertex, so only round-off of O(1) numbers
  EXPECT_NEAR(m.ixx, h * b * b * b / 12, 1e-9 * h * b * b * b / 12);
  EXPECT_NEAR(m.izz, b * h * h * h / 12, 1e-9 * b * h * h * h / 12);
  EXPECT_NEAR(m.ixz, 0.0, 1e-12);
  // the other vertex order gives the same
  const CentroidalMoments r = centroidal_moments({{x0, z0 + h}, {x0 + b, z0 + h}, {x0 + b, z0}, {x0, z0}});
  EXPECT_NEAR(r.area, m.area, 1e-12);
  EXPECT_NEAR(r.ixx, m.ixx, 1e-9 * m.ixx);
}

TEST(Polygon, ACutSplitsAConvexPolygonIntoTwoThatFillIt) {
  // a 0.6 m square cut 0.2 m from its -x edge, and an oblique cut off the centre
  for (const auto& [point, normal] : {std::pair<Eigen::Vector2d, Eigen::Vector2d>{{-0.1, 0.0}, {1.0, 0.0}},
                                      std::pair<Eigen::Vector2d, Eigen::Vector2d>{{0.05, 0.02}, {1.0, 0.5}}}) {
    const Polygon sq = square(0.6);
    const PolygonCut c = cut(sq, point, normal);
    ASSERT_GE(c.behind.size(), 3u);
    ASSERT_GE(c.ahead.size(), 3u);
    EXPECT_TRUE(is_convex(c.behind));
    EXPECT_TRUE(is_convex(c.ahead));
    // the vertex order of the polygon (ccw): the parts' areas keep its sign and sum to it
    EXPECT_GT(signed_area(c.behind), 0.0);
    EXPECT_NEAR(area(c.behind) + area(c.ahead), area(sq), 1e-15);
    for (const Eigen::Vector2d& v : c.behind) EXPECT_LE((v - point).dot(normal), 1e-15);
    for (const Eigen::Vector2d& v : c.ahead) EXPECT_GE((v - point).dot(normal), -1e-15);
  }
  EXPECT_NEAR(area(cut(square(0.6), {-0.1, 0.0}, {1.0, 0.0}).behind), 0.2 * 0.6, 1e-15);
}

TEST(Polygon, MinWidthIsTheNarrowestCaliper) {
  EXPECT_NEAR(min_width(rectangle(0.6, 0.2)), 0.2, 1e-15);
  EXPECT_NEAR(min_width(square(0.6)), 0.6, 1e-15);  // not the diagonal
  // a right triangle with legs 0.3 and 0.4: its height onto the hypotenuse, 0.3 x 0.4 / 0.5 m
  EXPECT_NEAR(min_width({{0, 0}, {0.4, 0}, {0, 0.3}}), 0.24, 1e-15);
  EXPECT_EQ(min_width({{0, 0}, {1, 0}}), 0.0);
}

TEST(Polygon, ACutThatMissesOrFollowsAnEdgeLeavesOnePartEmpty) {
  const PolygonCut missed = cut(square(0.6), {1.0, 0.0}, {1.0, 0.0});
  EXPECT_EQ(missed.behind.size(), 4u);
  EXPECT_TRUE(missed.ahead.empty());
  const PolygonCut along = cut(square(0.6), {0.3, 0.0}, {-1.0, 0.0});  // the +x edge, the square ahead
  EXPECT_TRUE(along.behind.empty());
  EXPECT_EQ(along.ahead.size(), 4u);
}

}  // namespace
}  // namespace icedem
