#include "dem/world/cone_geometry.hpp"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "dem/core/constants.hpp"

namespace icedem {

double equal_area_vertex_radius(double r, int segments) {
  // polygon area n/2 R^2 sin(2 pi/n) = pi r^2
  const double n = segments;
  return r * std::sqrt(2.0 * kPi / (n * std::sin(2.0 * kPi / n)));
}

double hull_depth(const std::vector<ProfileStation>& profile, int segments, const Eigen::Vector3d& p) {
  if (profile.empty() || p.y() < profile.front().y || p.y() > profile.back().y) return -1.0;
  const double vertex_r = equal_area_vertex_radius(profile_radius(profile, p.y()), segments);
  // the nearest side of a regular n-gon is the one of the point's sector (between
  // two vertices); its outward normal points to the sector's middle and the side
  // lies at the inscribed radius R cos(pi/n)
  const double sector = 2.0 * kPi / segments;
  double a = std::atan2(p.z(), p.x());
  if (a < 0) a += 2.0 * kPi;
  const double middle = (std::floor(a / sector) + 0.5) * sector;
  return vertex_r * std::cos(kPi / segments) - (p.x() * std::cos(middle) + p.z() * std::sin(middle));
}

namespace {

// a ring of `segments` vertices at height y (first vertex on +x)
std::vector<Eigen::Vector3d> ring(double y, double r, int segments) {
  std::vector<Eigen::Vector3d> pts;
  const double R = equal_area_vertex_radius(r, segments);
  if (r <= 0.0) return {Eigen::Vector3d(0.0, y, 0.0)};
  for (int k = 0; k < segments; ++k) {
    const double a = 2.0 * kPi * k / segments;
    pts.emplace_back(R * std::cos(a), y, R * std::sin(a));
  }
  return pts;
}

// true if station b lies on the straight generator through a and c
bool collinear(const ProfileStation& a, const ProfileStation& b, const ProfileStation& c) {
  const double cross = (b.y - a.y) * (c.radius - a.radius) - (b.radius - a.radius) * (c.y - a.y);
  const double scale = std::hypot(c.y - a.y, c.radius - a.radius);
  return std::abs(cross) <= 1e-9 * scale * scale;
}

}  // namespace

std::vector<std::vector<Eigen::Vector3d>> hull_pieces(const std::vector<ProfileStation>& profile,
                                                      int segments) {
  // the stations that start a new generator
  std::vector<std::size_t> keep{0};
  for (std::size_t i = 1; i + 1 < profile.size(); ++i)
    if (!collinear(profile[keep.back()], profile[i], profile[i + 1])) keep.push_back(i);
  keep.push_back(profile.size() - 1);

  std::vector<std::vector<Eigen::Vector3d>> pieces;
  for (std::size_t k = 1; k < keep.size(); ++k) {
    const ProfileStation& a = profile[keep[k - 1]];
    const ProfileStation& b = profile[keep[k]];
    if (a.radius <= 0.0 && b.radius <= 0.0) continue;  // a gap in the profile
    std::vector<Eigen::Vector3d> piece = ring(a.y, a.radius, segments);
    const auto top = ring(b.y, b.radius, segments);
    piece.insert(piece.end(), top.begin(), top.end());
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

TriangleMesh hull_surface(const std::vector<ProfileStation>& profile, int segments) {
  TriangleMesh mesh;
  // one ring (or apex point) per station
  std::vector<std::vector<int>> rings;
  for (const ProfileStation& s : profile) {
    std::vector<int> ids;
    for (const Eigen::Vector3d& p : ring(s.y, s.radius, segments)) {
      ids.push_back(static_cast<int>(mesh.vertices.size()));
      mesh.vertices.push_back(p);
    }
    rings.push_back(ids);
  }
  auto at = [&](const std::vector<int>& r, int k) { return r.size() == 1 ? r[0] : r[k % segments]; };
  // side: quads between consecutive rings; outward winding for y up, angle from +x towards +z
  for (std::size_t i = 1; i < rings.size(); ++i) {
    const auto& lo = rings[i - 1];
    const auto& hi = rings[i];
    for (int k = 0; k < segments; ++k) {
      const int a = at(lo, k), b = at(lo, k + 1), c = at(hi, k + 1), d = at(hi, k);
      if (a != b) mesh.triangles.push_back({a, d, b});
      if (c != d) mesh.triangles.push_back({b, d, c});
    }
  }
  // caps: bottom faces -y, top faces +y (fan around a centre vertex)
  auto cap = [&](const std::vector<int>& r, double y, bool top) {
    if (r.size() == 1) return;
    const int centre = static_cast<int>(mesh.vertices.size());
    mesh.vertices.emplace_back(0.0, y, 0.0);
    for (int k = 0; k < segments; ++k) {
      const int a = r[k], b = r[(k + 1) % segments];
      if (top)
        mesh.triangles.push_back({centre, b, a});
      else
        mesh.triangles.push_back({centre, a, b});
    }
  };
  cap(rings.front(), profile.front().y, false);
  cap(rings.back(), profile.back().y, true);
  return mesh;
}

double mesh_volume(const TriangleMesh& mesh) {
  double v = 0.0;
  for (const auto& t : mesh.triangles)
    v += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]])) / 6.0;
  return v;
}

void write_stl(const TriangleMesh& mesh, const std::string& path, const std::string& solid_name,
               const Eigen::Vector3d& offset) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write STL file", path));
  out << "solid " << solid_name << "\n";
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] + offset, b = mesh.vertices[t[1]] + offset,
                          c = mesh.vertices[t[2]] + offset;
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    out << fmt::format("  facet normal {:.9g} {:.9g} {:.9g}\n    outer loop\n", n.x(), n.y(), n.z());
    for (const Eigen::Vector3d& p : {a, b, c})
      out << fmt::format("      vertex {:.9g} {:.9g} {:.9g}\n", p.x(), p.y(), p.z());
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid " << solid_name << "\n";
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path));
}

}  // namespace icedem
