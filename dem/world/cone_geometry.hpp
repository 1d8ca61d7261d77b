// The structure's geometry from its profile of (height, radius) stations.
//
// One description serves both consumers: the convex pieces become the Bullet
// collision hull (dem/world/world.cpp) and the closed triangle surface becomes the STL
// that the OpenFOAM case meshes. Structure frame: the axis is the y axis, y = 0
// is the still-water line, so a station (y, r) sits at height y in the tank.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dem/input/scene.hpp"

namespace icedem {

/// Radius of the vertices of a regular `segments`-gon whose area equals that of
/// the circle of radius r, so the faceted hull keeps the cross-section area.
double equal_area_vertex_radius(double r, int segments);

/// How deep a point lies inside the faceted hull (the Bullet shape: a regular
/// `segments`-gon of equal_area_vertex_radius at every height, first vertex on
/// +x): its horizontal distance to the nearest side of the hull's section at
/// the point's height, m; <= 0 outside, and negative above the deck or below
/// the keel. `p` is in the structure frame (axis along y through the origin).
double hull_depth(const std::vector<ProfileStation>& profile, int segments, const Eigen::Vector3d& p);

/// The profile as convex pieces (frusta between stations; consecutive stations
/// on one straight generator are merged). Each piece is a point cloud in the
/// structure frame whose convex hull is the piece.
std::vector<std::vector<Eigen::Vector3d>> hull_pieces(const std::vector<ProfileStation>& profile,
                                                      int segments);

/// A closed triangle surface; triangles wound counter-clockwise seen from outside.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;  // m
  std::vector<std::array<int, 3>> triangles;
};

/// The hull surface (side faces and the flat bottom and top caps).
TriangleMesh hull_surface(const std::vector<ProfileStation>& profile, int segments);

/// Enclosed volume of a closed mesh (divergence theorem), m^3.
double mesh_volume(const TriangleMesh& mesh);

/// Write an ASCII STL of `mesh` translated by `offset` (m). Throws on I/O failure.
void write_stl(const TriangleMesh& mesh, const std::string& path, const std::string& solid_name,
               const Eigen::Vector3d& offset = Eigen::Vector3d::Zero());

}  // namespace icedem
