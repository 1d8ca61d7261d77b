// The nominal contact area of a crushing contact (dem/contact/crushing.hpp): where two
// convex bodies overlap, the area over which the ice at the contact is crushed.
//
// A convex body cut by a plane has a convex section: the convex hull of the points where
// the segments between its vertices on either side of the plane cross it (every edge of
// the body is such a segment, and every such point lies in the body). The nominal area is
// the overlap of the two bodies seen along the contact normal (Daley's). Of ice pressed into
// a body that does not crush: the ice's section by the body's surface plane, where it lies
// over the body's section by the parallel plane through the ice's deepest point; on a flat
// face that is the whole section (for a corner of opening angle phi against a face whose
// normal is beta from the horizontal, delta^2 tan(phi/2) / (sin beta cos^2 beta) at
// penetration delta), on a curved hull (the faceted cone) a long edge's section is cut to the
// band of the hull within the penetration. Of two pieces of ice pressed into each other,
// which both crush: the larger of the areas their sections share on the planes of their two
// surfaces at the contact (dem/world/crushing_contact.cpp). The hull by Andrew's monotone chain, the
// common part by Sutherland-Hodgman's clipping of one convex section by the other: on the
// few points of a floe's section these take a fraction of Boost.Geometry's time, to which
// the tests compare them (bench/micro/contact_area.cpp, tests/unit/test_crushing.cpp).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace icedem {

/// A plane: the points x with normal . (x - point) = 0; `normal` of unit length.
struct Plane {
  Eigen::Vector3d point;
  Eigen::Vector3d normal;
};

/// The section of the convex hull of `vertices` (m) by `plane`, m^2 (0 if the plane misses it).
double section_area(const std::vector<Eigen::Vector3d>& vertices, const Plane& plane);

/// The area common to the sections of the convex hulls of `a` and `b` by `plane`, m^2.
double common_section_area(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                           const Plane& plane);

/// The area common to the section of the hull of `a` by `plane_a` and that of `b` by the plane
/// through `plane_b.point` parallel to it, seen along their normal (`plane_a.normal`), m^2:
/// the nominal area of ice (a) pressed into a body (b) that does not crush, with plane_a through
/// b's surface point and plane_b through a's deepest point (the projected overlap, where b's
/// surface curves away from the contact).
double common_section_area(const std::vector<Eigen::Vector3d>& a, const Plane& plane_a,
                           const std::vector<Eigen::Vector3d>& b, const Plane& plane_b);

}  // namespace icedem
