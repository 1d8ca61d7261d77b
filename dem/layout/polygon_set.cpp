// Boolean operations of simple polygons by Boost.Geometry; see polygon_set.hpp.
#include "dem/layout/polygon_set.hpp"

#include <cmath>
#include <stdexcept>

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

namespace icedem {
namespace {

namespace bg = boost::geometry;
using Point = bg::model::d2::point_xy<double>;
// Boost's default ring is clockwise in a plot of (x, z) with z up, which is ccw seen from above
// (polygon.hpp): the project's own orientation, so rings pass through unchanged.
using BgPolygon = bg::model::polygon<Point>;
using BgMulti = bg::model::multi_polygon<BgPolygon>;

BgPolygon to_bg(const Polygon& p) {
  BgPolygon out;
  for (const Eigen::Vector2d& v : make_ccw(p)) bg::append(out.outer(), Point(v.x(), v.y()));
  bg::correct(out);  // closes the ring
  return out;
}

// Boost's overlay can leave a spike, a vertex the ring reaches and leaves along the same line (a tongue of
// no area where two cuts share an edge), which later operations on the ring take as invalid and answer
// with nothing: removed, with vertices repeated to within kSameVertex
constexpr double kSameVertex = 1e-9;  // m

// the opening's round corners (points per full turn) and its mitres' limit, in widths: a corner of half-angle
// beta comes back from (width / 2) / sin(beta) away, half-angles down to a thousandth of a radian
constexpr int kOpeningArcPoints = 16;
constexpr double kOpeningMiterLimit = 1000.0;

std::vector<Polygon> from_bg(BgMulti multi, const char* operation) {
  std::vector<Polygon> out;
  for (BgPolygon& p : multi) {
    bg::remove_spikes(p);
    if (!p.inners().empty())
      throw std::logic_error(std::string("polygon_set: ") + operation +
                             " would leave a hole in a region (a cut from inside the sheet, not from its edge)");
    Polygon ring;
    const auto& outer = p.outer();
    for (std::size_t i = 0; i + 1 < outer.size(); ++i) {
      const Eigen::Vector2d v(outer[i].x(), outer[i].y());
      if (ring.empty() || (v - ring.back()).norm() > kSameVertex) ring.push_back(v);
    }
    while (ring.size() > 1 && (ring.front() - ring.back()).norm() <= kSameVertex) ring.pop_back();
    ring = without_degenerate_vertices(ring);  // Boost's remove_spikes leaves a spike off its line by round-off
    if (ring.size() >= 3 && area(ring) > 0) out.push_back(make_ccw(std::move(ring)));
  }
  return out;
}

}  // namespace

std::vector<Polygon> intersect(const Polygon& a, const Polygon& b) {
  BgMulti out;
  bg::intersection(to_bg(a), to_bg(b), out);
  return from_bg(out, "intersect");
}

std::vector<Polygon> subtract(const Polygon& a, const Polygon& b) {
  BgMulti out;
  bg::difference(to_bg(a), to_bg(b), out);
  return from_bg(out, "subtract");
}

std::vector<Polygon> opening(const Polygon& region, double width) {
  // Shrunk with round corners at its notches (the disc's erosion: a mitre there would push a spike deep into the
  // region at a notch of a tenth of a degree), grown back with mitres at its corners, which put every corner the
  // shrinking kept back where it was and no farther (a round growth would round them: many vertices, each a
  // corner of the convex parts). What went is what a disc of diameter `width` cannot reach.
  const bg::strategy::buffer::join_round round(kOpeningArcPoints);
  const bg::strategy::buffer::join_miter mitre(kOpeningMiterLimit);
  const bg::strategy::buffer::end_flat end;  // (lines only)
  const bg::strategy::buffer::point_square point;
  const bg::strategy::buffer::side_straight side;
  BgMulti in, shrunk, grown;
  in.push_back(to_bg(region));
  bg::buffer(in, shrunk, bg::strategy::buffer::distance_symmetric<double>(-width / 2), side, round, end, point);
  if (shrunk.empty()) return {};
  bg::buffer(shrunk, grown, bg::strategy::buffer::distance_symmetric<double>(width / 2), side, mitre, end, point);
  // Boost's buffer of a region with edges a round-off apart can answer nothing, more than the region, less than
  // the shrunk region it grew (which an opening holds: 3 parts shrunk to 72.9 m^2 grown back to 1e-8 m^2, the
  // analytic tow at mu 0.2 and dt 0.01 s, 150.21 s, where growing each part alone gave them back), or parts grown
  // back into touch around a notch (a hole): then the region stands as it was (nothing is taken away rather than
  // ice made up or lost)
  for (const BgPolygon& p : grown)
    if (!p.inners().empty()) return {region};
  std::vector<Polygon> out = from_bg(grown, "opening");
  double total = 0;
  for (const Polygon& p : out) total += area(p);
  if (out.empty() || total > area(region) * (1 + 1e-9) || total < bg::area(shrunk) * (1 - 1e-9)) return {region};
  return out;
}

Polygon disc(const Eigen::Vector2d& centre, double radius, int segments) {
  Polygon out;
  for (int i = 0; i < segments; ++i) {
    const double t = 2 * M_PI * i / segments;
    out.emplace_back(centre.x() + radius * std::cos(t), centre.y() + radius * std::sin(t));
  }
  return make_ccw(std::move(out));
}

Polygon half_plane(const Eigen::Vector2d& point, const Eigen::Vector2d& normal, double reach) {
  const Eigen::Vector2d along(-normal.y(), normal.x());
  const Polygon box = {point - reach * along, point + reach * along, point + reach * along + 2 * reach * normal,
                       point - reach * along + 2 * reach * normal};
  return make_ccw(box);
}

bool contains(const Polygon& region, const Eigen::Vector2d& p) {
  return bg::covered_by(Point(p.x(), p.y()), to_bg(region));
}

bool is_simple(const Polygon& region) {
  if (region.size() < 3 || area(region) <= 0) return false;
  return bg::is_valid(to_bg(region));
}

}  // namespace icedem
