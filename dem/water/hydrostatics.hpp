// Hydrostatics of rigid convex bodies (floes, ice elements) cut by the still-water plane.
//
// A body is a convex polyhedron in its own frame, whose origin is the centre of mass.
// `submerge` clips every face against the half-space y <= water_level of the tank frame
// (y is up, y = 0 is the still-water line, docs/model/architecture.md, "Conventions") and returns the exact
// submerged volume, the centre of buoyancy and the wetted part of every face, for any
// orientation. The force at the centre of buoyancy then gives the right righting moment
// of a heeled floe (docs/model/validation_targets.md §1: GM = L^2/(12 d) + d/2 - h/2).
//
// `submerge` runs for every awake body at every time step, so it avoids heap allocation
// in its hot path: it reuses per-thread scratch buffers, and the overload that fills an
// existing Submersion reuses that object's face storage.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace icedem {

/// A convex polyhedron in the body frame (origin at the centre of mass).
struct ConvexPolyhedron {
  std::vector<Eigen::Vector3d> vertices;   // m, body frame
  std::vector<std::vector<int>> faces;     // vertex indices, counter-clockwise seen from outside
};

/// Builds a right prism: the convex polygon `outline` (points (x, z) in the body frame,
/// either orientation) extruded in y from -thickness/2 to +thickness/2. The outline must
/// be centred on its area centroid so that the body-frame origin is the centre of mass
/// of a uniform prism. Faces: 0 = bottom (normal -y), 1 = top (normal +y), then one side
/// face per outline edge, in outline order. Throws InputError if the outline has fewer
/// than 3 points, is not convex, has no area, or the thickness is not positive.
ConvexPolyhedron make_prism(const std::vector<Eigen::Vector2d>& outline, double thickness);

/// The wetted part of one face of a body.
struct WettedFace {
  Eigen::Vector3d normal;    // -, unit outward normal of the face, world
  double area;               // m^2, part of the face below the water plane
  Eigen::Vector3d centroid;  // m, world, centroid of that part
};

/// What lies below the water plane.
struct Submersion {
  double volume = 0.0;                                  // m^3, below y = water_level
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();   // m, world, centre of buoyancy (valid if volume > 0)
  std::vector<WettedFace> faces;                        // faces with a wetted part (area > 0)
};

/// Returns the part of `body`, placed at `pose` (body frame -> world), that lies strictly
/// below the plane y = water_level. Exact for convex polyhedra; robust to vertices lying
/// exactly on the plane (a face lying in the plane is not wetted).
Submersion submerge(const ConvexPolyhedron& body, const Eigen::Isometry3d& pose,
                    double water_level = 0.0);

/// Same as above, writing into `out` and reusing its face storage (no heap allocation once
/// `out.faces` has grown to the body's face count).
void submerge(const ConvexPolyhedron& body, const Eigen::Isometry3d& pose, double water_level,
              Submersion& out);

/// The section of a body by the water plane (the waterplane area), in the horizontal
/// (x, z) plane of the tank frame.
struct WaterplaneSection {
  double area = 0.0;                                   // m^2
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  // m, (x, z) world, valid if area > 0
  double second_moment_min = 0.0;  // m^4, smaller principal second moment about the centroid
  double second_moment_max = 0.0;  // m^4, larger principal second moment about the centroid
};

/// Returns the section of `body` at `pose` by the plane y = water_level (empty if the plane
/// misses the body). Not meant for the hot path (it allocates).
WaterplaneSection waterplane_section(const ConvexPolyhedron& body, const Eigen::Isometry3d& pose,
                                     double water_level = 0.0);

/// Total volume of the body, m^3.
double body_volume(const ConvexPolyhedron& body);

/// Returns the water level, in the body frame of the upright body (pose = identity), at
/// which the submerged volume equals `displaced_volume` (m^3), found by bisection with
/// `submerge` to 1e-12 of the body's height. A floating body therefore sits with its
/// centre of mass at y = -level in the tank frame; for a prism of thickness h the draft is
/// level + h/2. Clamped to the lowest vertex for displaced_volume <= 0 and to the highest
/// for displaced_volume >= body_volume (the body sinks).
double equilibrium_water_level(const ConvexPolyhedron& body, double displaced_volume);

}  // namespace icedem
