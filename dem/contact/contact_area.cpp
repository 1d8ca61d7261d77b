#include "dem/contact/contact_area.hpp"

#include <algorithm>
#include <cmath>

namespace icedem {
namespace {

using Point2 = Eigen::Vector2d;

// scratch of the sections: a run computes one or two per crushing manifold and substep, and
// allocating them was a tenth of such a run's CPU
thread_local std::vector<Point2> scratch_points, scratch_hull, scratch_a, scratch_b, scratch_clip;
thread_local std::vector<double> scratch_side;
thread_local std::vector<int> scratch_above, scratch_below;

// twice the signed area of the triangle (o, a, b): > 0 when a -> b turns left about o
double turn(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// the convex hull of `points` (reordered), counter-clockwise, into `hull` (Andrew's monotone chain)
void convex_hull(std::vector<Point2>& points, std::vector<Point2>& hull) {
  hull.clear();
  const int n = static_cast<int>(points.size());
  if (n < 3) return;
  std::sort(points.begin(), points.end(),
            [](const Point2& a, const Point2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  hull.resize(2 * n);
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first
}

// the area of a counter-clockwise polygon (the shoelace formula)
double area(const std::vector<Point2>& polygon) {
  const int n = static_cast<int>(polygon.size());
  if (n < 3) return 0.0;
  double twice = 0.0;
  for (int i = 0, j = n - 1; i < n; j = i++) twice += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  return 0.5 * std::abs(twice);
}

// the section of the hull of `vertices` by `plane` in the axes e1, e2 normal to `plane.normal`
// about `origin` (one origin for sections by parallel planes: their points then share
// coordinates), into `hull`
void section(const std::vector<Eigen::Vector3d>& vertices, const Plane& plane, const Eigen::Vector3d& origin,
             std::vector<Point2>& hull) {
  const Eigen::Vector3d seed = std::abs(plane.normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = plane.normal.cross(seed).normalized(), e2 = plane.normal.cross(e1);
  std::vector<Point2>& crossings = scratch_points;
  crossings.clear();
  const std::size_t n = vertices.size();
  std::vector<double>& s = scratch_side;  // each corner's signed distance from the plane
  s.resize(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = plane.normal.dot(vertices[i] - plane.point);
  auto add = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d d = x - origin;
    crossings.emplace_back(e1.dot(d), e2.dot(d));
  };
  // the corners on either side (a hull piece of the structure has a hundred, of which a
  // plane near its surface leaves a few on the far side: pairs of these with the rest only)
  std::vector<int>& above = scratch_above;
  std::vector<int>& below = scratch_below;
  above.clear(), below.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (s[i] == 0.0) add(vertices[i]);
    if (s[i] > 0.0) above.push_back(static_cast<int>(i));
    if (s[i] < 0.0) below.push_back(static_cast<int>(i));
  }
  for (const int k : above)
    for (const int l : below) {
      const auto [i, j] = std::minmax(k, l);  // the lower first: the same rounding whichever side it is on
      add(vertices[i] + (vertices[j] - vertices[i]) * (s[i] / (s[i] - s[j])));
    }
  convex_hull(crossings, hull);
}

// `subject` clipped to the convex counter-clockwise polygon `clip` (Sutherland-Hodgman: the
// subject's part left of each of the clip's edges in turn), into `out`
void clip_convex(const std::vector<Point2>& subject, const std::vector<Point2>& clip, std::vector<Point2>& out) {
  out = subject;
  std::vector<Point2>& input = scratch_clip;
  const int m = static_cast<int>(clip.size());
  for (int e = 0; e < m && !out.empty(); ++e) {
    const Point2& a = clip[e];
    const Point2& b = clip[(e + 1) % m];
    input.swap(out);
    out.clear();
    const int n = static_cast<int>(input.size());
    for (int i = 0; i < n; ++i) {
      const Point2& p = input[i];
      const Point2& q = input[(i + 1) % n];
      const double sp = turn(a, b, p), sq = turn(a, b, q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
  }
}

}  // namespace

double section_area(const std::vector<Eigen::Vector3d>& vertices, const Plane& plane) {
  section(vertices, plane, plane.point, scratch_hull);
  return area(scratch_hull);
}

double common_section_area(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                           const Plane& plane) {
  return common_section_area(a, plane, b, plane);
}

double common_section_area(const std::vector<Eigen::Vector3d>& a, const Plane& plane_a,
                           const std::vector<Eigen::Vector3d>& b, const Plane& plane_b) {
  section(a, plane_a, plane_a.point, scratch_a);
  if (scratch_a.size() < 3) return 0.0;
  section(b, Plane{plane_b.point, plane_a.normal}, plane_a.point, scratch_b);
  if (scratch_b.size() < 3) return 0.0;
  clip_convex(scratch_a, scratch_b, scratch_hull);
  return area(scratch_hull);
}

}  // namespace icedem
