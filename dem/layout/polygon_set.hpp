// Regions of the horizontal plane of any simple shape, convex or not: what the level sheet's outline
// and the pieces cut from it are (dem/fracture/level_sheet.hpp). Their Boolean operations are Boost.Geometry's,
// in double precision; the polygons are polygon.hpp's (vertices (x, z) in m), ccw seen from above.
//
// A region has one outer ring and no holes: the level sheet is cut from its edge inwards, so a cut never
// leaves a hole, and an operation whose answer would have one throws (std::logic_error) rather than drop it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dem/layout/polygon.hpp"

namespace icedem {

/// The parts of `a` that lie in `b` (none if they do not overlap), each ccw.
std::vector<Polygon> intersect(const Polygon& a, const Polygon& b);

/// The parts of `a` that lie outside `b`, each ccw.
std::vector<Polygon> subtract(const Polygon& a, const Polygon& b);

/// `region` less every part of it narrower than `width` (m), Boost.Geometry's buffer shrinking it by width / 2
/// and growing it back: its edges and corners come back where they were (to round-off) wherever it is wider, and a
/// tongue or neck narrower than `width` is gone (but for a stub at its root as deep as a disc of that diameter
/// reaches into it, whose corners the mitres put back a hair beyond the region: 5e-7 m^2 for a 5 mm tongue opened
/// at 33 mm). The parts left, each ccw; a neck's two sides become two parts; none if all of it is narrower.
/// Where Boost's buffer answers what an opening cannot (nothing of a region it shrank to something, more than the
/// region, less than what it shrank to, a hole), the region as it was.
std::vector<Polygon> opening(const Polygon& region, double width);

/// The disc of `radius` (m) about `centre` as a polygon of `segments` vertices on the circle, ccw.
Polygon disc(const Eigen::Vector2d& centre, double radius, int segments);

/// The half-plane of the points p with (p - point) . normal >= 0 (`normal` a unit vector), as the part of the
/// square of half-side `reach` (m) about `point` that lies in it: large enough to hold every region it cuts.
Polygon half_plane(const Eigen::Vector2d& point, const Eigen::Vector2d& normal, double reach);

/// Whether `p` lies in or on the simple polygon `region`.
bool contains(const Polygon& region, const Eigen::Vector2d& p);

/// Whether the simple polygon `region` is valid for the operations above: at least three vertices, no
/// self-intersection, a positive area.
bool is_simple(const Polygon& region);

}  // namespace icedem
