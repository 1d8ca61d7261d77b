// Convex polygons in the horizontal (x, z) plane of the tank frame: area,
// centroid, convexity, rigid placement and the separating-axis overlap test.
//
// A polygon is a list of vertices (x, z) in metres; the last vertex connects
// back to the first. Orientation convention used throughout icedem:
//   a polygon is "ccw" (signed_area > 0) when its vertices run counter-clockwise
//   SEEN FROM ABOVE (from +y looking down), i.e. in the same sense as a positive
//   yaw, which turns +x towards -z. The top face of a floe extruded from a ccw
//   outline then has its outward normal +y by the right-hand rule.
//   Caution: in a plot with x to the right and z upwards (the view from below)
//   a ccw polygon appears clockwise.
// Yaw is a right-handed rotation about +y by theta (docs/model/architecture.md, "Conventions"):
//   x' = x cos(theta) + z sin(theta),  z' = -x sin(theta) + z cos(theta).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace icedem {

/// Vertices (x, z) in m, in order; the polygon closes from the last to the first.
using Polygon = std::vector<Eigen::Vector2d>;

/// Signed area in m^2: positive for ccw (counter-clockwise seen from above, +y),
/// negative for clockwise, zero for degenerate polygons and fewer than 3 vertices.
double signed_area(const Polygon& polygon);

/// Absolute area in m^2.
double area(const Polygon& polygon);

/// Area, centroid and second moments about the centroid of a polygon (either vertex order),
/// summed relative to its first vertex (small numbers, for polygons far from the origin).
/// Zero area for fewer than three vertices. The one shoelace sum behind a floe's mass and
/// inertia, a waterplane section's stiffness and centroid().
struct CentroidalMoments {
  double area = 0;                                     // m^2
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  // m
  double ixx = 0;  // m^4, integral of x'^2 dA about the centroid
  double izz = 0;  // m^4, integral of z'^2 dA
  double ixz = 0;  // m^4, integral of x' z' dA
};
CentroidalMoments centroidal_moments(const Polygon& polygon);

/// The convex hull of `points` (Andrew's monotone chain), its vertices turning from +x towards
/// +z: clockwise seen from above, signed_area < 0. Fewer than three vertices when the points
/// do not span an area.
Polygon convex_hull(std::vector<Eigen::Vector2d> points);

/// Area centroid (x, z) in m. For a polygon of zero area the vertex mean is
/// returned (it has no area centroid).
Eigen::Vector2d centroid(const Polygon& polygon);

/// True if the polygon is a simple convex polygon of positive area: at least 3
/// finite vertices, no repeated consecutive vertices, no reflex corner, no
/// fold-back (spike) and a total turn of exactly one revolution (so star
/// polygons and other self-intersecting outlines are rejected). Collinear
/// vertices on a straight edge are accepted. Either orientation is accepted.
bool is_convex(const Polygon& polygon);

/// The same polygon with its vertices in ccw order (see the file comment);
/// reverses the order if the signed area is negative, otherwise unchanged.
Polygon make_ccw(Polygon polygon);

/// The polygon without its degenerate vertices: a vertex repeated by its successor, one straight on between its
/// neighbours, and a spike (a vertex the outline reaches and leaves back along the same line, to within
/// kSpikeAngle): dropped until none is left, since dropping one can make its neighbour one. Boolean operations on
/// outlines leave such vertices where two cuts share an edge, and CGAL's partition and Boost's overlays take a
/// ring with them as not simple. Fewer than three vertices when nothing of area is left.
Polygon without_degenerate_vertices(const Polygon& polygon);

/// rad: a vertex whose outline turns back by more than pi minus this is a spike (a tongue narrower than a
/// millionth of its length is round-off, not ice)
constexpr double kSpikeAngle = 1e-6;

/// Point `p` (x, z) rotated by `yaw` (rad) about +y, per the convention above.
Eigen::Vector2d rotate(const Eigen::Vector2d& p, double yaw);

/// World outline of a polygon given in its local frame, placed with its local
/// origin at `centre` (m) and rotated by `yaw` (rad) about +y:
/// world = centre + rotate(local, yaw).
Polygon transformed(const Polygon& local, const Eigen::Vector2d& centre, double yaw);

/// Distance of the point `p` from the segment s0-s1, m.
double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& s0, const Eigen::Vector2d& s1);

/// Minimum distance between two convex polygons in m; zero if they touch or
/// their interiors intersect.
double distance(const Polygon& a, const Polygon& b);

/// Separating-axis test for convex polygons. True if `a` and `b` are closer than
/// `gap` (m, the minimum required clearance). With gap = 0 it is true only if
/// the interiors intersect: touching polygons do not overlap. With gap > 0 the
/// true Euclidean distance is compared (corner-to-corner gaps included). A
/// negative gap tolerates an interpenetration depth up to |gap| (to forgive
/// rounding, e.g. for touching floes typed into a layout file).
bool overlap(const Polygon& a, const Polygon& b, double gap = 0.0);

/// Largest distance of a vertex from the local origin, m. For a shape centred
/// on its area centroid, a circle of this radius about the centre holds it at
/// any yaw.
double bounding_radius(const Polygon& polygon);

/// Square of side `side` (m) centred on the origin, edges along x and z, ccw.
Polygon square(double side);

/// Rectangle of length `lx` along x and `lz` along z (m), centred on the origin, ccw.
Polygon rectangle(double lx, double lz);

/// The width of a convex polygon, m: the least distance between two parallel lines that hold it
/// (rotating calipers: the least over its edges of the farthest vertex from the edge's line).
/// 0 for fewer than three vertices.
double min_width(const Polygon& polygon);

/// The two parts of a convex polygon cut by the line through `point` with normal `normal`
/// (need not be unit): `behind` where (p - point) . normal <= 0, `ahead` the rest, each in the
/// polygon's vertex order, the cut's two ends shared. A part is empty when the line misses
/// the polygon or runs along an edge (no vertex lies strictly on that side).
struct PolygonCut {
  Polygon behind, ahead;
};
PolygonCut cut(const Polygon& polygon, const Eigen::Vector2d& point, const Eigen::Vector2d& normal);

}  // namespace icedem
