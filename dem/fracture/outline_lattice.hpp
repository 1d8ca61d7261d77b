// Breakable ice of any outline: a floe's outline (convex or not: a photo's, a layout file's)
// filled with square or hexagonal elements, each cut at the outline.
//
// The seed paper's elements are squares, so a floe breaks only into squares and rectangles;
// its closing remark expects hexagons to let "ice failure be represented in a form close to
// a shape having a curved surface". Here the plane is tiled with cells (squares of side
// element_size, or hexagons whose neighbouring centres are element_size apart, flat faces
// towards +-z), the grid anchored at the outline's lower corner (x, z least) or, fitted
// (fracture.tiling), shifted to where it cuts the fewest parts below a quarter and below half a
// cell, and each cell is cut to the part of the outline inside it. An element keeps the true
// area, centroid and second moments of its part (its mass and inertia follow), and two elements are joined
// where their parts share a stretch of their cells' common face, with that stretch's length
// (a joint's capacities scale with it, eqs. 1-3). A part smaller than `min_fraction` of a
// cell joins the neighbour it shares the longest face with, if the two make a convex body (a
// sliver of a few percent of a cell is a body of a few grams beside ones of half a kilogram);
// where they would not (a hexagon with a sliver of the next cell), it stays an element of its
// own, since a body is a convex prism whose mass is its hull's. A part that shares no face is
// dropped and its area reported. A rectangle of whole elements gives make_element_lattice's
// lattice exactly.
//
// Pure geometry in the floe's frame, as make_element_lattice; dem/fracture/ice_lattice.cpp
// makes the bodies (each the prism of an element's hull, on its own principal axes) and the
// joints (frames along each face's normal, capacities and springs by its length).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "dem/input/scene.hpp"
#include "dem/layout/polygon.hpp"

namespace icedem {

/// "square" or "hexagon" (fracture.element_shape's names).
const char* element_shape_name(ElementShape shape);

/// One element of an outline lattice.
struct OutlineElement {
  Polygon hull;               // m, ccw, floe frame: the convex hull of its part, its collision shape
  CentroidalMoments moments;  // of its true part (or parts, merged): area, centroid, second moments
};

/// One joint: the elements' indices, the face's middle, the unit axis from a's cell centre
/// towards b's, and the face's length (m).
struct OutlineJoint {
  int a, b;
  Eigen::Vector2d midpoint, axis;
  double face_length;
};

struct OutlineLattice {
  std::vector<OutlineElement> elements;
  std::vector<OutlineJoint> joints;
  double dropped_area = 0;  // m^2: parts below min_fraction of a cell sharing no face
};

/// The area of one cell: element_size^2 for a square, sqrt(3)/2 element_size^2 for a hexagon.
double cell_area(double element_size, ElementShape shape);

/// Fill `outline` (either orientation, at least three vertices, simple) with elements, the
/// tiling anchored at the outline's lower corner or fitted (Tiling). Throws
/// std::invalid_argument for a degenerate outline or a non-positive element size.
OutlineLattice fill_outline(const Polygon& outline, double element_size, ElementShape shape,
                            Tiling tiling = Tiling::kCorner, double min_fraction = 0.25);

}  // namespace icedem
