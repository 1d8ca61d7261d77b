#include "dem/fracture/sheet_breaking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "dem/fracture/floating_plate.hpp"
#include "dem/fracture/wedge_bending.hpp"
#include "dem/layout/polygon_set.hpp"

namespace icedem {
namespace {

// The wedge's S and x* / l depend on a / l alone, smoothly; a solve takes milliseconds (a beam of 4,800
// elements) and a run asks at every step for each zone's and each floe's patch, whose widths vary without end
// (kept per a / l rounded to a tenth of a millimetre, the solves and their page faults were about 40 % of the
// CPU of a tow's first 8 s, by perf). So they are solved on nodes kPatchStep apart in sqrt(a / l), where x* / l,
// steep as a -> 0, is nearly straight, and interpolated linearly between them, within 0.1 % of the solve
// (tests/unit/test_sheet_breaking.cpp): 127 nodes up to a / l = 0.4, a patch of 0.15 m at the paper's l. The
// first node stands for a -> 0.
constexpr double kPatchStep = 0.005;
constexpr double kSmallestPatch = 1e-6;

// segments of the circle the sheet's opening angle is measured on
constexpr int kAngleSegments = 128;

// a / l at a node
double node_patch(long node) { return node == 0 ? kSmallestPatch : (node * kPatchStep) * (node * kPatchStep); }

WedgeBending wedge_node(long node) {
  static std::map<long, WedgeBending> memo;
  if (auto it = memo.find(node); it != memo.end()) return it->second;
  return memo[node] = wedge_bending(node_patch(node));
}

WedgeBending wedge_at(double patch_over_l) {
  const double u = std::sqrt(std::clamp(patch_over_l, 0.0, 6.0));
  const long last = static_cast<long>(std::sqrt(6.0) / kPatchStep) - 1;
  const long node = std::min(static_cast<long>(std::floor(u / kPatchStep)), last);
  const double low = std::sqrt(node_patch(node)), high = std::sqrt(node_patch(node + 1));
  const double t = std::clamp((u - low) / (high - low), 0.0, 1.0);
  const WedgeBending a = wedge_node(node), b = wedge_node(node + 1);
  return WedgeBending{a.stress_factor + t * (b.stress_factor - a.stress_factor),
                      a.crack_distance + t * (b.crack_distance - a.crack_distance)};
}

// the part of `parts` that holds `point`, else the one nearest to it (a zone's centroid can lie a hair
// outside a crescent-shaped part)
std::size_t part_holding(const std::vector<Polygon>& parts, const Eigen::Vector2d& point) {
  std::size_t best = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (contains(parts[i], point)) return i;
    for (const Eigen::Vector2d& v : parts[i]) {
      const double d = (v - point).norm();
      if (d < nearest) nearest = d, best = i;
    }
  }
  return best;
}

}  // namespace

SheetBreakPlan plan_sheet_break(const Polygon& sheet, const SheetContact& contact, const SheetIce& ice) {
  SheetBreakPlan plan;
  // S and x* depend on the patch alone (the angle cancels: wedge_bending.hpp)
  const double l = characteristic_length(ice.thickness, ice.elastic_modulus, ice.poisson_ratio, ice.water_density,
                                         ice.gravity);
  const WedgeBending w = wedge_at(contact.half_width / l);
  plan.crack_distance = w.crack_distance * l;
  // the angle the sheet fills about the centre, measured on a finer circle than the crack's (an angle of a
  // polygon of few sides depends on where its vertices fall), against that polygon's own area, so that a
  // straight edge fills pi
  double filled = 0;
  for (const Polygon& p : intersect(sheet, disc(contact.centre, plan.crack_distance, kAngleSegments)))
    filled += area(p);
  const double polygon_circle = 0.5 * kAngleSegments * std::sin(2 * M_PI / kAngleSegments) *
                                plan.crack_distance * plan.crack_distance;
  plan.opening_angle = std::clamp(2 * M_PI * filled / polygon_circle, 1e-3, M_PI);
  plan.radial_crack = plan.opening_angle > kRadialCrackAngle;
  plan.breaking_load = plan.radial_crack
                           ? 2 * wedge_load(plan.opening_angle / 2, w, ice.thickness, ice.bending_strength)
                           : wedge_load(plan.opening_angle, w, ice.thickness, ice.bending_strength);
  return plan;
}

namespace {

// whether a vertex of `part` lies on one of the held edges (within round-off of the sheet's size: the parts'
// boundaries there are the start outline's edges, cut by Boost.Geometry)
bool reaches_held(const Polygon& part, const HeldEdges& held) {
  constexpr double kOnEdge = 1e-7;  // m
  for (const Eigen::Vector2d& v : part)
    for (const auto& [a, b] : held)
      if (point_segment_distance(v, a, b) < kOnEdge) return true;
  return false;
}

}  // namespace

SheetCut cut_sheet(const Polygon& sheet, const SheetContact& contact, const SheetBreakPlan& plan, double thickness,
                   const HeldEdges& held) {
  const Eigen::Vector2d& c = contact.centre;
  const Eigen::Vector2d d = contact.direction;
  const Eigen::Vector2d n(-d.y(), d.x());
  const double x = plan.crack_distance;
  const double reach = 4 * x + 1.0;  // half-planes as squares larger than anything they cut here
  // the wedges' axes: theta / 4 either side of the load when the radial crack along it halves the edge, else
  // the load's
  std::vector<Eigen::Vector2d> axes;
  if (plan.radial_crack) {
    const double turn = plan.opening_angle / 4;
    axes = {std::cos(turn) * d + std::sin(turn) * n, std::cos(turn) * d - std::sin(turn) * n};
  } else {
    axes = {d};
  }
  // The region that breaks off: short of every wedge's chord, within 2 x* of the centre (a free edge that runs
  // back towards a chord would otherwise let the region run along it). One convex region serves both wedges:
  // on a wedge's side of the radial crack, (p - c) . a_other = (p - c) . a_own - 2 sin(theta / 4) |(p - c) . n|,
  // so the other's chord holds wherever its own does. Cut as one region, the sheet is cut once: Boost's
  // difference of two cuts in turn that share the radial crack can answer nothing.
  Polygon region = disc(c, 2 * x, kCrackSegments);
  for (const Eigen::Vector2d& a : axes) {
    const std::vector<Polygon> r = intersect(region, half_plane(c + x * a, -a, reach));
    if (r.empty()) throw std::logic_error("cut_sheet: the chord misses the crack's circle");
    region = r.front();  // convex with convex: one part
  }
  const std::vector<Polygon> inside = intersect(sheet, region);
  if (inside.empty()) return SheetCut{sheet, {}, 0.0};  // the load is at a point of the outline that holds no ice
  // what breaks off is the part that holds the load; another tongue of the sheet that crosses the region stays
  const Polygon broken = inside[part_holding(inside, c)];

  SheetCut out;
  std::vector<Polygon> left, parts;
  try {
    parts = subtract(sheet, inside.size() == 1 ? region : broken);
  } catch (const std::logic_error&) {
    // what breaks off would leave a hole in the sheet: the part holding the load meets the outline nowhere but at
    // a point (the paper's tow at mu 0.3, 92.84 s: the load 1.7 mm off an edge where the sheet within 2 x* was
    // three tongues). No break from the edge there: the sheet holds this step, as where no ice lies within the crack
    return SheetCut{sheet, {}, 0.0};
  }
  for (const Polygon& part : parts) {
    double kept = 0;
    for (Polygon& wide : opening(part, thickness)) {
      kept += area(wide);
      left.push_back(std::move(wide));
    }
    out.slivers += area(part) - kept;
  }
  if (left.empty()) throw std::logic_error("cut_sheet: the break takes the whole sheet");
  // the part that stays: the one the ice around holds, else the largest
  std::vector<std::size_t> holding;
  if (!held.empty())
    for (std::size_t k = 0; k < left.size(); ++k)
      if (reaches_held(left[k], held)) holding.push_back(k);
  if (holding.size() > 1) return SheetCut{sheet, {}, 0.0};  // it would part the held sheet: it holds this step
  const std::size_t stays =
      holding.size() == 1 ? holding.front()
                          : static_cast<std::size_t>(std::max_element(left.begin(), left.end(),
                                                                      [](const Polygon& a, const Polygon& b) {
                                                                        return area(a) < area(b);
                                                                      }) -
                                                     left.begin());
  out.sheet = left[stays];
  for (std::size_t k = 0; k < left.size(); ++k)
    if (k != stays) out.pieces.push_back(left[k]);
  if (!plan.radial_crack) {
    out.pieces.push_back(broken);
    return out;
  }
  for (const Eigen::Vector2d& side : {n, Eigen::Vector2d(-n)})
    for (Polygon& half : intersect(broken, half_plane(c, side, reach))) out.pieces.push_back(std::move(half));
  return out;
}

}  // namespace icedem
