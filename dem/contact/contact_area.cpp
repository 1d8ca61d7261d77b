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

// the section of the hull of `vertices` by `plane` in the plane's axes e1, e2, into `hull`
void section(const std::vector<Eigen::Vector3d>& vertices, const Plane& plane, std::vector<Point2>& hull) {
  const Eigen::Vector3d seed = std::abs(plane.normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = plane.normal.cross(seed).normalized(), e2 = plane.normal.cross(e1);
  std::vector<Point2>& crossings = scratch_points;
  crossings.clear();
  const std::size_t n = vertices.size();
  std::vector<double>& s = scratch_side;  // each corner's signed distance from the plane
  s.resize(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = plane.normal.dot(vertices[i] - plane.point);
  auto add = [&](const Eigen::Vector3d& x) {
    const Eigen::Vector3d d = x - plane.point;
    crossings.emplace_back(e1.dot(d), e2.dot(d));
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (s[i] == 0.0) add(vertices[i]);
    for (std::size_t j = i + 1; j < n; ++j)
      if ((s[i] < 0.0 && s[j] > 0.0) || (s[i] > 0.0 && s[j] < 0.0))
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
  section(vertices, plane, scratch_hull);
  return area(scratch_hull);
}

double common_section_area(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                           const Plane& plane) {
  section(a, plane, scratch_a);
  section(b, plane, scratch_b);
  if (scratch_a.size() < 3 || scratch_b.size() < 3) return 0.0;
  clip_convex(scratch_a, scratch_b, scratch_hull);
  return area(scratch_hull);
}

}  // namespace icedem
