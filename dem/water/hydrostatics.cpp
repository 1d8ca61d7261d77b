// Exact submerged volume, centre of buoyancy and wetted faces of a convex polyhedron.
//
// Method: every face polygon is clipped against the half-space y < water_level
// (Sutherland-Hodgman on one plane) and fan-triangulated on the fly. The closed surface
// of the submerged part is the clipped faces plus the cap polygon on the water plane; the
// volume and its centroid follow from the divergence theorem as a sum of tetrahedra with
// a common apex r ON the water plane, so the cap contributes zero and is never built.
#include "dem/water/hydrostatics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "dem/core/errors.hpp"
#include "dem/layout/polygon.hpp"

namespace icedem {

namespace {

/// Accumulates a convex polygon given vertex by vertex as a fan of triangles from its
/// first vertex: the polygon's area and centroid, and the tetrahedra (r, a, b, c) for the
/// volume. All points are relative to the apex r.
struct FanAccumulator {
  Eigen::Vector3d normal;           // -, unit normal of the face the polygon lies in
  Eigen::Vector3d anchor, prev;     // m, relative to r
  int count = 0;                    // vertices seen so far
  double area = 0.0;                // m^2
  Eigen::Vector3d area_moment = Eigen::Vector3d::Zero();    // m^3, sum of area * centroid
  double volume6 = 0.0;             // m^3, six times the signed volume of the tetrahedra
  Eigen::Vector3d volume6_moment = Eigen::Vector3d::Zero(); // m^4, sum of 6 vol * 4 centroid

  void add(const Eigen::Vector3d& p) {
    if (count == 0) {
      anchor = p;
    } else if (count >= 2) {
      triangle(anchor, prev, p);
    }
    prev = p;
    ++count;
  }

  void triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    // signed area along the face normal; positive for the counter-clockwise fan of a convex face
    const double tri_area = 0.5 * normal.dot((b - a).cross(c - a));
    area += tri_area;
    area_moment += tri_area * (a + b + c) / 3.0;
    // tetrahedron (r = 0, a, b, c): 6 V = a . (b x c), centroid (a + b + c) / 4
    const double v6 = a.dot(b.cross(c));
    volume6 += v6;
    volume6_moment += v6 * (a + b + c);
  }
};

/// Per-thread scratch space for submerge(), grown once and reused.
struct SubmergeScratch {
  std::vector<Eigen::Vector3d> world;  // m, vertices in the world frame, relative to r
  std::vector<double> depth;           // m, vertex height above the water plane
};

SubmergeScratch& scratch() {
  thread_local SubmergeScratch s;
  return s;
}

/// Newell normal of a face in the body frame (not normalised; length = 2 * area).
Eigen::Vector3d newell_normal(const ConvexPolyhedron& body, const std::vector<int>& face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const std::size_t count = face.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d& p = body.vertices[face[i]];
    const Eigen::Vector3d& q = body.vertices[face[(i + 1) % count]];
    n += p.cross(q);
  }
  return n;
}

std::string point_text(const Eigen::Vector2d& p) {
  std::ostringstream s;
  s << "(x = " << p.x() << " m, z = " << p.y() << " m)";
  return s.str();
}

}  // namespace

ConvexPolyhedron make_prism(const std::vector<Eigen::Vector2d>& outline, double thickness) {
  const int n = static_cast<int>(outline.size());
  if (n < 3) {
    throw InputError("floe outline: has " + std::to_string(n) +
                     " points; expected a convex polygon with at least 3 points");
  }
  if (!(thickness > 0.0) || !std::isfinite(thickness)) {
    std::ostringstream s;
    s << "floe thickness: " << thickness << " m; expected a finite value > 0";
    throw InputError(s.str());
  }
  double scale = 0.0;  // m, largest coordinate, for relative tolerances
  for (int i = 0; i < n; ++i) {
    if (!outline[i].allFinite()) {
      throw InputError("floe outline: point " + std::to_string(i) + " " + point_text(outline[i]) +
                       " is not finite; expected finite coordinates");
    }
    scale = std::max(scale, outline[i].cwiseAbs().maxCoeff());
  }

  // (x, z) signed area, shoelace; positive means counter-clockwise in the (x, z) axes
  double twice_area = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& p = outline[i];
    const Eigen::Vector2d& q = outline[(i + 1) % n];
    twice_area += p.x() * q.y() - q.x() * p.y();
  }
  const double area_tol = 1e-12 * scale * scale;
  if (std::abs(twice_area) <= area_tol) {
    throw InputError("floe outline: has zero area; expected a convex polygon with area > 0");
  }

  // index order that walks the outline with +y on the left of the right-handed (x, y, z)
  // frame, i.e. negative (x, z) shoelace area; in that order the top face is CCW from +y
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = twice_area < 0.0 ? i : n - 1 - i;

  // convexity: every turn has the sign of the whole polygon; repeated points are rejected
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = outline[order[i]];
    const Eigen::Vector2d& b = outline[order[(i + 1) % n]];
    const Eigen::Vector2d& c = outline[order[(i + 2) % n]];
    const Eigen::Vector2d e1 = b - a;
    const Eigen::Vector2d e2 = c - b;
    if (e1.norm() <= 1e-12 * scale) {
      throw InputError("floe outline: point " + point_text(b) +
                       " repeats its neighbour; expected distinct consecutive points");
    }
    if (e1.x() * e2.y() - e1.y() * e2.x() > area_tol) {
      throw InputError("floe outline: turns the wrong way at point " + point_text(b) +
                       "; expected a convex polygon");
    }
  }

  ConvexPolyhedron body;
  body.vertices.reserve(2 * n);
  const double half = 0.5 * thickness;
  for (int i = 0; i < n; ++i) body.vertices.emplace_back(outline[order[i]].x(), -half, outline[order[i]].y());
  for (int i = 0; i < n; ++i) body.vertices.emplace_back(outline[order[i]].x(), +half, outline[order[i]].y());

  body.faces.reserve(n + 2);
  // bottom: the ring reversed, so that its normal is -y
  std::vector<int> bottom(n), top(n);
  for (int i = 0; i < n; ++i) {
    bottom[i] = n - 1 - i;
    top[i] = n + i;
  }
  body.faces.push_back(std::move(bottom));
  body.faces.push_back(std::move(top));
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    body.faces.push_back({i, j, n + j, n + i});
  }
  return body;
}

Submersion submerge(const ConvexPolyhedron& body, const Eigen::Isometry3d& pose,
                    double water_level) {
  Submersion out;
  submerge(body, pose, water_level, out);
  return out;
}

void submerge(const ConvexPolyhedron& body, const Eigen::Isometry3d& pose, double water_level,
              Submersion& out) {
  out.volume = 0.0;
  out.faces.clear();

  // apex of the tetrahedra: on the water plane above the centre of mass, which keeps the
  // coordinates small (tank positions reach ~35 m, floes are ~0.3 m)
  const Eigen::Vector3d r(pose.translation().x(), water_level, pose.translation().z());
  out.centroid = r;

  // world vertices relative to r; the body is dry if no vertex is strictly below the plane
  SubmergeScratch& s = scratch();
  const std::size_t nv = body.vertices.size();
  s.world.resize(nv);
  s.depth.resize(nv);
  const Eigen::Matrix3d rot = pose.linear();
  const Eigen::Vector3d shift = pose.translation() - r;
  bool any_wet = false;
  for (std::size_t i = 0; i < nv; ++i) {
    s.world[i] = rot * body.vertices[i] + shift;
    s.depth[i] = s.world[i].y();
    any_wet = any_wet || s.depth[i] < 0.0;
  }
  if (!any_wet) return;

  double volume6 = 0.0;
  Eigen::Vector3d volume6_moment = Eigen::Vector3d::Zero();
  for (const std::vector<int>& face : body.faces) {
    const std::size_t count = face.size();
    if (count < 3) continue;
    bool face_wet = false;
    for (int idx : face) face_wet = face_wet || s.depth[idx] < 0.0;
    if (!face_wet) continue;

    const Eigen::Vector3d body_normal = newell_normal(body, face);
    const double normal_length = body_normal.norm();
    if (!(normal_length > 0.0)) continue;  // degenerate face, no area
    FanAccumulator fan;
    fan.normal = rot * (body_normal / normal_length);

    // sutherland-hodgman against y < 0 (relative to r): "inside" is strictly below the
    // plane, so a vertex on the plane is emitted as the end of a crossing edge, once
    for (std::size_t i = 0; i < count; ++i) {
      const int ip = face[i];
      const int iq = face[(i + 1) % count];
      const double dp = s.depth[ip];
      const double dq = s.depth[iq];
      const bool p_in = dp < 0.0;
      const bool q_in = dq < 0.0;
      if (p_in != q_in) {
        // dp and dq differ strictly in sign class, so dp - dq != 0
        Eigen::Vector3d x = s.world[ip] + (s.world[iq] - s.world[ip]) * (dp / (dp - dq));
        x.y() = 0.0;  // exactly on the plane: its tetrahedra with the cap vanish
        fan.add(x);
      }
      if (q_in) fan.add(s.world[iq]);
    }
    if (fan.count < 3) continue;

    volume6 += fan.volume6;
    volume6_moment += fan.volume6_moment;
    if (fan.area > 0.0) {
      out.faces.push_back(WettedFace{fan.normal, fan.area, fan.area_moment / fan.area + r});
    }
  }

  if (volume6 > 0.0) {
    out.volume = volume6 / 6.0;
    out.centroid = volume6_moment / (4.0 * volume6) + r;
  }
}

WaterplaneSection waterplane_section(const ConvexPolyhedron& body, const Eigen::Isometry3d& pose,
                                     double water_level) {
  // points of the section: vertices on the plane and crossings of edges that cross it
  // (each edge is seen from both of its faces; the hull removes the duplicates)
  std::vector<Eigen::Vector3d> world(body.vertices.size());
  for (std::size_t i = 0; i < world.size(); ++i) world[i] = pose * body.vertices[i];
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector3d& w : world) {
    if (w.y() == water_level) points.emplace_back(w.x(), w.z());
  }
  for (const std::vector<int>& face : body.faces) {
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Eigen::Vector3d& p = world[face[i]];
      const Eigen::Vector3d& q = world[face[(i + 1) % face.size()]];
      const double dp = p.y() - water_level;
      const double dq = q.y() - water_level;
      if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) {
        const Eigen::Vector3d x = p + (q - p) * (dp / (dp - dq));
        points.emplace_back(x.x(), x.z());
      }
    }
  }

  // the section is the convex hull of where the faces' edges cross the plane
  WaterplaneSection section;
  const CentroidalMoments m = centroidal_moments(convex_hull(std::move(points)));
  if (!(m.area > 0.0)) return section;
  const double mean = 0.5 * (m.ixx + m.izz);
  const double radius = std::hypot(0.5 * (m.ixx - m.izz), m.ixz);
  section.area = m.area;
  section.centroid = m.centroid;
  section.second_moment_min = mean - radius;
  section.second_moment_max = mean + radius;
  return section;
}

double body_volume(const ConvexPolyhedron& body) {
  // divergence theorem with the apex at the body-frame origin
  double volume6 = 0.0;
  for (const std::vector<int>& face : body.faces) {
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      const Eigen::Vector3d& a = body.vertices[face[0]];
      volume6 += a.dot(body.vertices[face[i]].cross(body.vertices[face[i + 1]]));
    }
  }
  return volume6 / 6.0;
}

double equilibrium_water_level(const ConvexPolyhedron& body, double displaced_volume) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& v : body.vertices) {
    lo = std::min(lo, v.y());
    hi = std::max(hi, v.y());
  }
  if (displaced_volume <= 0.0) return lo;
  if (displaced_volume >= body_volume(body)) return hi;

  // the submerged volume grows monotonically with the water level
  const double tolerance = 1e-12 * (hi - lo);
  const Eigen::Isometry3d upright = Eigen::Isometry3d::Identity();
  Submersion sub;
  for (int iteration = 0; iteration < 200 && hi - lo > tolerance; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    submerge(body, upright, mid, sub);
    (sub.volume < displaced_volume ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace icedem
