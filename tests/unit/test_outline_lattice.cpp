// Lattices of any outline (dem/fracture/outline_lattice.hpp): square and hexagonal elements
// cut at a floe's outline keep the floe's area, mass moments and shape, are joined only
// across faces inside the ice, and a rectangle of whole elements is the paper's lattice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "dem/fracture/element_lattice.hpp"
#include "dem/fracture/outline_lattice.hpp"

using namespace icedem;

namespace {

// the outline's polar moment about its centroid against the elements' (each about its own
// centroid, moved to the outline's): the floe's yaw inertia, which the elements must keep
double polar(const CentroidalMoments& m) { return m.ixx + m.izz; }
double elements_polar(const OutlineLattice& l, const Eigen::Vector2d& about) {
  double j = 0;
  for (const OutlineElement& e : l.elements) j += polar(e.moments) + e.moments.area * (e.moments.centroid - about).squaredNorm();
  return j;
}
double elements_area(const OutlineLattice& l) {
  double a = 0;
  for (const OutlineElement& e : l.elements) a += e.moments.area;
  return a;
}

// even-odd point in polygon, or within tol of its boundary
bool inside_or_on(const Polygon& p, const Eigen::Vector2d& q, double tol) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const Eigen::Vector2d a = p[j], b = p[i];
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((q - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    if ((a + t * ab - q).norm() <= tol) return true;
    if ((b.y() > q.y()) != (a.y() > q.y()) && q.x() < (a.x() - b.x()) * (q.y() - b.y()) / (a.y() - b.y()) + b.x())
      in = !in;
  }
  return in;
}

Polygon regular(int n, double radius, const Eigen::Vector2d& centre, double turn) {
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double a = turn + 2 * M_PI * k / n;
    p.push_back(centre + radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return p;
}

}  // namespace

TEST(OutlineLattice, ARectangleOfWholeSquaresIsThePapersLattice) {
  const Polygon floe = rectangle(0.6, 0.45);
  const OutlineLattice l = fill_outline(floe, 0.15, ElementShape::kSquare);
  const ElementLattice paper = make_element_lattice(floe, 0.15);
  ASSERT_EQ(l.elements.size(), paper.centres.size());
  ASSERT_EQ(l.joints.size(), paper.joints.size());
  // the same centres (in another order) and the same faces: each joint's midpoint is one of
  // the paper lattice's, with the face's full length L_e
  for (const OutlineElement& e : l.elements) {
    EXPECT_NEAR(e.moments.area, 0.0225, 1e-12);
    EXPECT_TRUE(std::any_of(paper.centres.begin(), paper.centres.end(),
                            [&](const Eigen::Vector2d& c) { return (c - e.moments.centroid).norm() < 1e-12; }));
  }
  for (const OutlineJoint& j : l.joints) {
    EXPECT_NEAR(j.face_length, 0.15, 1e-12);
    EXPECT_TRUE(std::any_of(paper.joints.begin(), paper.joints.end(),
                            [&](const LatticeJoint& p) { return (p.midpoint - j.midpoint).norm() < 1e-12; }));
  }
  EXPECT_EQ(l.dropped_area, 0.0);
}

TEST(OutlineLattice, AnyConvexOutlineKeepsItsAreaAndInertia) {
  // a 13-gon of radius 0.4 m off the origin and turned, as a photo's floe: the elements'
  // areas add up to the outline's and their yaw inertia to its own (to round-off: the cut
  // parts tile the outline exactly), with either element shape
  const Polygon floe = regular(13, 0.4, {0.3, -0.2}, 0.37);
  const CentroidalMoments whole = centroidal_moments(floe);
  for (ElementShape shape : {ElementShape::kSquare, ElementShape::kHexagon}) {
    SCOPED_TRACE(element_shape_name(shape));
    const OutlineLattice l = fill_outline(floe, 0.15, shape);
    EXPECT_NEAR(elements_area(l) + l.dropped_area, whole.area, 1e-12 * whole.area);
    // parts under 5 % of a cell that join no neighbour are dropped; this outline has none, so
    // the elements hold the floe's yaw inertia exactly
    EXPECT_EQ(l.dropped_area, 0.0);
    EXPECT_NEAR(elements_polar(l, whole.centroid), polar(whole), 1e-10 * polar(whole));
    for (const OutlineElement& e : l.elements) {
      // every body is its ice: a convex outline's parts are convex, and a small part joined
      // only a neighbour it makes a convex body with, so each hull is the element's area
      EXPECT_NEAR(area(e.hull), e.moments.area, 1e-9 * e.moments.area);
      EXPECT_GT(signed_area(e.hull), 0);  // ccw seen from above, as every polygon of the project
    }
    // every element is joined to at least one other (the lattice holds together), and each
    // joint's face is inside the outline
    std::set<int> joined;
    for (const OutlineJoint& j : l.joints) {
      joined.insert(j.a), joined.insert(j.b);
      EXPECT_TRUE(inside_or_on(floe, j.midpoint, 1e-12));
      EXPECT_GT(j.face_length, 0);
    }
    EXPECT_EQ(joined.size(), l.elements.size());
  }
}

TEST(OutlineLattice, HexagonsInsideTheIceHaveSixEqualFaces) {
  // a 1.8 x 1.8 m floe of hexagons 0.2 m across: a whole hexagon is sqrt(3)/2 w^2, has six
  // neighbours, each across a face of w / sqrt(3), along 30, 90, 150, ... degrees
  const double w = 0.2;
  const OutlineLattice l = fill_outline(rectangle(1.8, 1.8), w, ElementShape::kHexagon);
  std::map<int, int> joints_of;
  for (const OutlineJoint& j : l.joints) ++joints_of[j.a], ++joints_of[j.b];
  int whole = 0;
  for (std::size_t e = 0; e < l.elements.size(); ++e) {
    if (std::abs(l.elements[e].moments.area - cell_area(w, ElementShape::kHexagon)) > 1e-12) continue;
    const Eigen::Vector2d c = l.elements[e].moments.centroid;
    if (std::abs(c.x()) > 0.9 - 1.2 * w || std::abs(c.y()) > 0.9 - 1.2 * w) continue;  // away from the edge
    ++whole;
    EXPECT_EQ(joints_of[int(e)], 6);
  }
  EXPECT_GT(whole, 20);
  for (const OutlineJoint& j : l.joints) {
    if (std::abs(j.face_length - w / std::sqrt(3.0)) > 1e-9) continue;  // cut at the outline
    const double angle = std::atan2(j.axis.y(), j.axis.x()) * 180 / M_PI;
    const double from_30 = std::fmod(angle - 30 + 720, 60.0);
    EXPECT_TRUE(from_30 < 1e-6 || from_30 > 60 - 1e-6) << angle;
  }
}

TEST(OutlineLattice, NoJointAcrossAConcaveNotch) {
  // a U of 0.9 x 0.6 m with a slot 0.15 m wide and 0.45 m deep in the middle, cut into 0.15 m
  // squares: the slot's two sides share cells' faces only across open water, so no joint
  // lies in the slot, and the area is kept
  const Polygon u = {{-0.45, -0.3}, {0.45, -0.3}, {0.45, 0.3},  {0.075, 0.3},
                     {0.075, -0.15}, {-0.075, -0.15}, {-0.075, 0.3}, {-0.45, 0.3}};
  for (ElementShape shape : {ElementShape::kSquare, ElementShape::kHexagon}) {
    SCOPED_TRACE(element_shape_name(shape));
    const OutlineLattice l = fill_outline(u, 0.15, shape);
    EXPECT_NEAR(elements_area(l) + l.dropped_area, area(u), 1e-12);
    for (const OutlineJoint& j : l.joints) EXPECT_TRUE(inside_or_on(u, j.midpoint, 1e-12)) << j.midpoint.transpose();
  }
}

TEST(OutlineLattice, SliversJoinTheirNeighbours) {
  // 0.62 m across 0.15 m squares leaves a column 0.02 m wide (13 % of a cell): each of its
  // parts joins the element beside it, so the floe keeps its area and has the 4 x 3
  // elements of 0.6 m, the last column 0.17 m wide: its elements are joined to each other
  // across faces of 0.17 m (their own 0.15 m and the slivers' 0.02 m, summed into one joint),
  // every other face is 0.15 m
  const OutlineLattice l = fill_outline(rectangle(0.62, 0.45), 0.15, ElementShape::kSquare);
  EXPECT_EQ(l.elements.size(), 12u);
  EXPECT_NEAR(elements_area(l), 0.62 * 0.45, 1e-12);
  int wide = 0;
  for (const OutlineElement& e : l.elements) wide += std::abs(e.moments.area - 0.17 * 0.15) < 1e-12;
  EXPECT_EQ(wide, 3);
  EXPECT_EQ(l.joints.size(), 17u);
  int long_faces = 0;
  for (const OutlineJoint& j : l.joints) {
    const bool in_wide_column = j.midpoint.x() > 0.3 - 1e-9 - 0.15 && std::abs(j.axis.y()) > 0.99;
    EXPECT_NEAR(j.face_length, in_wide_column ? 0.17 : 0.15, 1e-12) << j.midpoint.transpose();
    long_faces += in_wide_column;
  }
  EXPECT_EQ(long_faces, 2);
}

TEST(OutlineLattice, EveryBodyStaysConvexAtACorner) {
  // 0.62 x 0.47 m: slivers 0.02 m wide along two sides meet at a corner, where the square
  // there could take both and leave the corner's 0.02 x 0.02 m out of its body's hull; it takes
  // one, the other joins the next square or stays an element of its own, and each body's hull
  // is exactly its ice
  const OutlineLattice l = fill_outline(rectangle(0.62, 0.47), 0.15, ElementShape::kSquare);
  for (const OutlineElement& e : l.elements) EXPECT_NEAR(area(e.hull), e.moments.area, 1e-12);
  EXPECT_NEAR(elements_area(l) + l.dropped_area, 0.62 * 0.47, 1e-12);
  EXPECT_LE(l.dropped_area, 0.02 * 0.02 + 1e-12);  // at most the corner's piece (under 5 % of a cell)
}

TEST(OutlineLattice, RefusesWhatIsNoOutline) {
  EXPECT_THROW(fill_outline({{0, 0}, {1, 0}}, 0.15, ElementShape::kSquare), std::invalid_argument);
  EXPECT_THROW(fill_outline(square(1.0), 0.0, ElementShape::kSquare), std::invalid_argument);
  EXPECT_STREQ(element_shape_name(ElementShape::kHexagon), "hexagon");
}

namespace {
// the elements' shares of a whole cell below `share`
int parts_below(const OutlineLattice& l, double cell, double share) {
  int n = 0;
  for (const OutlineElement& e : l.elements) n += e.moments.area < share * cell - 1e-12;
  return n;
}
}  // namespace

TEST(OutlineLattice, AFittedTilingCutsNoSmallPartsFromThePapersFloe) {
  // the paper's 0.6 m floe in hexagons 0.15 m across: anchored at its corner, the tiling cuts it
  // into 14 whole hexagons, 7 halves, 2 quarters and 4 eighths (the eighths cannot join a
  // neighbour in a convex body, so they stay elements); shifted so that its sides run along the
  // cells' centre lines and flats, it leaves nothing below a quarter and at most two parts below
  // half a cell. Either way the floe keeps its area, and joints lie inside the ice
  const Polygon floe = rectangle(0.6, 0.6);
  const double w = 0.15, cell = cell_area(w, ElementShape::kHexagon);
  const OutlineLattice corner = fill_outline(floe, w, ElementShape::kHexagon, Tiling::kCorner);
  const OutlineLattice fitted = fill_outline(floe, w, ElementShape::kHexagon, Tiling::kFitted);
  EXPECT_EQ(parts_below(corner, cell, 0.25), 4);
  EXPECT_EQ(parts_below(fitted, cell, 0.25), 0);
  EXPECT_LE(parts_below(fitted, cell, 0.5), 2);
  EXPECT_LT(fitted.elements.size(), corner.elements.size());
  for (const OutlineLattice* l : {&corner, &fitted}) {
    EXPECT_NEAR(elements_area(*l) + l->dropped_area, 0.36, 1e-12);
    EXPECT_EQ(l->dropped_area, 0.0);
    for (const OutlineJoint& j : l->joints) EXPECT_TRUE(inside_or_on(floe, j.midpoint, 1e-12));
  }
  // the 0.20 m hexagons: the corner cuts parts of 1 % of a cell, too small to keep (their ice is
  // dropped), and its smallest elements are quarters; fitted drops nothing, and its smallest
  // element is above 0.4 of a cell
  const double w2 = 0.2, cell2 = cell_area(w2, ElementShape::kHexagon);
  const OutlineLattice corner2 = fill_outline(floe, w2, ElementShape::kHexagon, Tiling::kCorner);
  const OutlineLattice fitted2 = fill_outline(floe, w2, ElementShape::kHexagon, Tiling::kFitted);
  EXPECT_GT(corner2.dropped_area, 0.0);
  EXPECT_EQ(fitted2.dropped_area, 0.0);
  EXPECT_EQ(parts_below(corner2, cell2, 0.3), 2);
  EXPECT_EQ(parts_below(fitted2, cell2, 0.4), 0);
}

TEST(OutlineLattice, AFittedTilingKeepsARectangleOfWholeSquares) {
  // no shift cuts fewer parts than none: the rectangle stays the paper's 4 x 3 whole squares
  const OutlineLattice l = fill_outline(rectangle(0.6, 0.45), 0.15, ElementShape::kSquare, Tiling::kFitted);
  ASSERT_EQ(l.elements.size(), 12u);
  for (const OutlineElement& e : l.elements) EXPECT_NEAR(e.moments.area, 0.0225, 1e-12);
  EXPECT_EQ(l.joints.size(), 17u);
}
