// Convex polygon geometry in the (x, z) plane; see polygon.hpp for conventions.
#include "dem/layout/polygon.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "dem/core/constants.hpp"

namespace icedem {
namespace {

// relative tolerance for "zero" lengths and angles: a few hundred ulps of the
// polygon's own size, far below any physical dimension of a floe
constexpr double kRelTol = 1e-12;

// standard 2D cross product of (x, z) vectors: positive when b is
// counter-clockwise from a in a plot with x right and z up (i.e. clockwise
// seen from above), hence the minus sign in signed_area()
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// largest coordinate extent, m: the length scale for relative tolerances
double extent(const Polygon& p) {
  Eigen::Vector2d lo = p.front(), hi = p.front();
  for (const auto& v : p) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return (hi - lo).maxCoeff();
}

// projection interval of a polygon on an axis
void project(const Polygon& p, const Eigen::Vector2d& axis, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity();
  hi = -lo;
  for (const auto& v : p) {
    const double s = v.dot(axis);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
}

// largest gap between the projections of a and b over the edge normals of
// `edges_of`; for convex polygons the edge normals of both are the only
// candidate separating axes (separating axis theorem)
double max_separation_on(const Polygon& edges_of, const Polygon& a, const Polygon& b) {
  double best = -std::numeric_limits<double>::infinity();
  const size_t n = edges_of.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e = edges_of[(i + 1) % n] - edges_of[i];
    const double len = e.norm();
    if (len == 0.0) continue;
    const Eigen::Vector2d axis(-e.y() / len, e.x() / len);
    double alo, ahi, blo, bhi;
    project(a, axis, alo, ahi);
    project(b, axis, blo, bhi);
    best = std::max(best, std::max(blo - ahi, alo - bhi));
  }
  return best;
}

// signed SAT separation, m: > 0 separated by at least this much along some
// axis, 0 touching, < 0 minus the penetration depth
double max_separation(const Polygon& a, const Polygon& b) {
  return std::max(max_separation_on(a, a, b), max_separation_on(b, a, b));
}

// smallest distance from the vertices of `from` to the edges of `to`
double vertex_edge_distance(const Polygon& from, const Polygon& to) {
  double best = std::numeric_limits<double>::infinity();
  const size_t n = to.size();
  for (const auto& p : from) {
    for (size_t i = 0; i < n; ++i) {
      best = std::min(best, point_segment_distance(p, to[i], to[(i + 1) % n]));
    }
  }
  return best;
}

}  // namespace

double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& s0,
                              const Eigen::Vector2d& s1) {
  const Eigen::Vector2d d = s1 - s0;
  const double len2 = d.squaredNorm();
  double t = len2 > 0.0 ? (p - s0).dot(d) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (s0 + t * d - p).norm();
}

double signed_area(const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return 0.0;
  // shoelace formula relative to the first vertex (less cancellation far from
  // the origin); negated so that ccw seen from above (+y) is positive
  double twice = 0.0;
  for (size_t i = 1; i + 1 < n; ++i) {
    twice += cross(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
  }
  return -0.5 * twice;
}

double area(const Polygon& polygon) { return std::abs(signed_area(polygon)); }

CentroidalMoments centroidal_moments(const Polygon& hull) {
  CentroidalMoments m;
  if (hull.size() < 3) return m;
  // area moments about the first vertex (small numbers), then about the centroid
  const Eigen::Vector2d o = hull[0];
  double a2 = 0.0, sx = 0.0, sz = 0.0, sxx = 0.0, szz = 0.0, sxz = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d p = hull[i] - o;
    const Eigen::Vector2d q = hull[(i + 1) % hull.size()] - o;
    const double c = p.x() * q.y() - q.x() * p.y();
    a2 += c;
    sx += (p.x() + q.x()) * c;
    sz += (p.y() + q.y()) * c;
    sxx += (p.x() * p.x() + p.x() * q.x() + q.x() * q.x()) * c;
    szz += (p.y() * p.y() + p.y() * q.y() + q.y() * q.y()) * c;
    sxz += (p.x() * q.y() + 2.0 * p.x() * p.y() + 2.0 * q.x() * q.y() + q.x() * p.y()) * c;
  }
  if (a2 < 0.0) {  // the other vertex order: every sum changes sign (exactly)
    a2 = -a2, sx = -sx, sz = -sz, sxx = -sxx, szz = -szz, sxz = -sxz;
  }
  const double area = 0.5 * a2;
  if (!(area > 0.0)) return m;
  const double cx = sx / (6.0 * area);
  const double cz = sz / (6.0 * area);
  m.area = area;
  m.centroid = o + Eigen::Vector2d(cx, cz);
  // parallel-axis theorem
  m.ixx = sxx / 12.0 - area * cx * cx;
  m.izz = szz / 12.0 - area * cz * cz;
  m.ixz = sxz / 24.0 - area * cx * cz;
  return m;
}

Polygon convex_hull(std::vector<Eigen::Vector2d> points) {
  if (points.size() < 3) return {};
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  auto turn = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  Polygon hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

Eigen::Vector2d centroid(const Polygon& polygon) {
  assert(!polygon.empty());
  const CentroidalMoments m = centroidal_moments(polygon);
  if (polygon.size() < 3 || m.area <= 0.5 * kRelTol * kRelTol * std::pow(extent(polygon), 2)) {
    // no area: fall back to the vertex mean
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const auto& v : polygon) mean += v;
    return mean / static_cast<double>(polygon.size());
  }
  return m.centroid;
}

bool is_convex(const Polygon& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return false;
  for (const auto& v : polygon) {
    if (!std::isfinite(v.x()) || !std::isfinite(v.y())) return false;
  }
  const double scale = extent(polygon);
  if (!(scale > 0.0)) return false;

  // every corner must turn the same way (or go straight on); total turning
  // must be one revolution, which rules out star polygons whose corners all
  // turn the same way but wind twice
  int sign = 0;
  double total_turn = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e0 = polygon[i] - polygon[(i + n - 1) % n];
    const Eigen::Vector2d e1 = polygon[(i + 1) % n] - polygon[i];
    const double l0 = e0.norm(), l1 = e1.norm();
    if (l0 <= kRelTol * scale || l1 <= kRelTol * scale) return false;  // repeated vertex
    const double s = cross(e0, e1) / (l0 * l1);
    const double c = e0.dot(e1) / (l0 * l1);
    if (std::abs(s) <= kRelTol) {
      if (c < 0.0) return false;  // fold-back spike
      continue;                   // straight on: collinear vertex
    }
    const int corner_sign = s > 0.0 ? 1 : -1;
    if (sign == 0) sign = corner_sign;
    if (corner_sign != sign) return false;  // reflex corner
    total_turn += std::atan2(s, c);
  }
  if (std::abs(std::abs(total_turn) - 2.0 * kPi) > 1e-6) return false;
  return area(polygon) > kRelTol * scale * scale;
}

Polygon make_ccw(Polygon polygon) {
  if (signed_area(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

Polygon without_degenerate_vertices(const Polygon& polygon) {
  Polygon out = polygon;
  double scale = 0;
  for (const Eigen::Vector2d& v : polygon) scale = std::max(scale, v.cwiseAbs().maxCoeff());
  const double same = kRelTol * std::max(scale, 1.0);  // m: a repeated vertex
  for (bool dropped = true; dropped && out.size() >= 3;) {
    dropped = false;
    for (std::size_t i = 0; i < out.size() && out.size() >= 3; ++i) {
      const std::size_t n = out.size();
      const Eigen::Vector2d u = out[i] - out[(i + n - 1) % n], w = out[(i + 1) % n] - out[i];
      const double lu = u.norm(), lw = w.norm();
      bool degenerate = lw <= same;  // repeated by its successor
      if (!degenerate) {
        const double s = std::abs(cross(u, w)) / (lu * lw), c = u.dot(w) / (lu * lw);
        degenerate = (c > 0 && s <= kRelTol) || (c < 0 && s <= kSpikeAngle);  // straight on, or a spike
      }
      if (!degenerate) continue;
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
      dropped = true;
      --i;
    }
  }
  if (out.size() < 3) out.clear();
  return out;
}

Eigen::Vector2d rotate(const Eigen::Vector2d& p, double yaw) {
  // rotation about +y (docs/model/architecture.md): x' = x c + z s, z' = -x s + z c
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {p.x() * c + p.y() * s, -p.x() * s + p.y() * c};
}

Polygon transformed(const Polygon& local, const Eigen::Vector2d& centre, double yaw) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  Polygon world;
  world.reserve(local.size());
  for (const auto& p : local) {
    world.emplace_back(centre.x() + p.x() * c + p.y() * s, centre.y() - p.x() * s + p.y() * c);
  }
  return world;
}

double distance(const Polygon& a, const Polygon& b) {
  if (max_separation(a, b) <= 0.0) return 0.0;
  // disjoint convex polygons: the closest pair involves a vertex of one and an
  // edge of the other
  return std::min(vertex_edge_distance(a, b), vertex_edge_distance(b, a));
}

bool overlap(const Polygon& a, const Polygon& b, double gap) {
  const double sep = max_separation(a, b);
  // the true distance is never smaller than the SAT separation
  if (sep >= gap) return false;
  // touching or intersecting, and sep < gap
  if (sep <= 0.0) return true;
  // 0 < sep < gap: the SAT separation underestimates corner-to-corner gaps
  return std::min(vertex_edge_distance(a, b), vertex_edge_distance(b, a)) < gap;
}

double bounding_radius(const Polygon& polygon) {
  double r = 0.0;
  for (const auto& v : polygon) r = std::max(r, v.norm());
  return r;
}

Polygon square(double side) { return rectangle(side, side); }

Polygon rectangle(double lx, double lz) {
  const double hx = 0.5 * lx, hz = 0.5 * lz;
  // ccw seen from above: +x turns towards -z first
  return {{hx, hz}, {hx, -hz}, {-hx, -hz}, {-hx, hz}};
}

double min_width(const Polygon& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return 0.0;
  double width = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = polygon[(i + 1) % n] - polygon[i];
    const double length = edge.norm();
    if (length == 0) continue;
    const Eigen::Vector2d normal(-edge.y() / length, edge.x() / length);
    double farthest = 0;
    for (const Eigen::Vector2d& v : polygon) farthest = std::max(farthest, std::abs((v - polygon[i]).dot(normal)));
    width = std::min(width, farthest);
  }
  return width;
}

PolygonCut cut(const Polygon& polygon, const Eigen::Vector2d& point, const Eigen::Vector2d& normal) {
  // Sutherland-Hodgman against one line, both sides at once: each edge that crosses the
  // line adds its crossing to both parts
  PolygonCut out;
  const std::size_t n = polygon.size();
  std::vector<double> side(n);
  bool any_behind = false, any_ahead = false;
  for (std::size_t i = 0; i < n; ++i) {
    side[i] = (polygon[i] - point).dot(normal);
    any_behind = any_behind || side[i] < 0;
    any_ahead = any_ahead || side[i] > 0;
  }
  if (!any_ahead) {
    if (any_behind) out.behind = polygon;
    return out;
  }
  if (!any_behind) {
    out.ahead = polygon;
    return out;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if (side[i] <= 0) out.behind.push_back(a);
    if (side[i] >= 0) out.ahead.push_back(a);
    if ((side[i] < 0 && side[j] > 0) || (side[i] > 0 && side[j] < 0)) {
      const Eigen::Vector2d x = a + (b - a) * (side[i] / (side[i] - side[j]));
      out.behind.push_back(x);
      out.ahead.push_back(x);
    }
  }
  return out;
}

}  // namespace icedem
