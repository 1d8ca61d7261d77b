#include "dem/fracture/sheet_breaking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "dem/fracture/floating_plate.hpp"
#include "dem/fracture/plate_edge_load.hpp"
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

// what a cut may lose or gain of the sheet's area to Boost's round-off, relative to it (its cuts conserve it to 1e-12)
constexpr double kAreaRoundOff = 1e-9;

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

// The intact plate's crack across a patch, P_c = sigma_b h^2 / (6 m_x) at x_c (plate_edge_load.hpp), depends on
// a / l and the Poisson ratio. A solve takes 0.1-0.4 s (its largest M_x searched along the axis), so it is solved on
// nodes kAcrossStep apart in a / l, where P_c and x_c are smooth (P_c from 1.32 sigma_b h^2 at a point load to
// nearly straight in a), and interpolated linearly in the load factor 1 / (6 m_x) and in x_c, within 0.1 % of the
// solve (tests/unit/test_sheet_breaking.cpp). Past kWidestSolved the plate is Hetenyi's strip of width 2a to
// 0.02 %: m_x = e^(-pi/4) / (2 a / l) at x_c = pi / (4 beta) = (pi / 4) sqrt(2) l.
constexpr double kAcrossStep = 0.05;
constexpr double kWidestSolved = 8.0;

struct AcrossPatch {
  double load_factor = 0;  // P_c / (sigma_b h^2)
  double distance = 0;     // x_c / l
};

AcrossPatch across_node(long node, double poisson) {
  static std::map<std::pair<double, long>, AcrossPatch> memo;
  const auto key = std::make_pair(poisson, node);
  if (auto it = memo.find(key); it != memo.end()) return it->second;
  const PlateEdgeResponse r = plate_edge_response(node * kAcrossStep, poisson);
  return memo[key] = AcrossPatch{1.0 / (6.0 * r.circumferential_moment), r.circumferential_distance};
}

AcrossPatch across_at(double patch_over_l, double poisson) {
  const double a = std::max(patch_over_l, 0.0);
  if (a >= kWidestSolved) return AcrossPatch{a / (3.0 * std::exp(-M_PI / 4)), M_PI * std::sqrt(2.0) / 4};
  const long node = static_cast<long>(std::floor(a / kAcrossStep));
  const double t = a / kAcrossStep - node;
  const AcrossPatch lo = across_node(node, poisson), hi = across_node(node + 1, poisson);
  return AcrossPatch{lo.load_factor + t * (hi.load_factor - lo.load_factor),
                     lo.distance + t * (hi.distance - lo.distance)};
}

// the parts' area, m^2
double total_area(const std::vector<Polygon>& parts) {
  double sum = 0;
  for (const Polygon& p : parts) sum += area(p);
  return sum;
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
  const bool radial = plan.opening_angle > kRadialCrackAngle;
  plan.crack = radial ? SheetCrack::kRadialWedges : SheetCrack::kWedge;
  plan.breaking_load = radial ? 2 * wedge_load(plan.opening_angle / 2, w, ice.thickness, ice.bending_strength)
                              : wedge_load(plan.opening_angle, w, ice.thickness, ice.bending_strength);
  // a patch wider than the wedges can take: the plate's crack across it, where that needs less
  const AcrossPatch across = across_at(contact.half_width / l, ice.poisson_ratio);
  const double across_load = across.load_factor * ice.bending_strength * ice.thickness * ice.thickness;
  if (across_load < plan.breaking_load) {
    plan.crack = SheetCrack::kAcrossPatch;
    plan.breaking_load = across_load;
    plan.crack_distance = across.distance * l;
  }
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

// The region that breaks off the wedges: short of every wedge's chord, within 2 x* of the centre (a free edge that
// runs back towards a chord would otherwise let the region run along it). The wedges' axes are theta / 4 either
// side of the load when the radial crack along it halves the edge, else the load's. One convex region serves both
// wedges: on a wedge's side of the radial crack, (p - c) . a_other = (p - c) . a_own - 2 sin(theta / 4) |(p - c) . n|,
// so the other's chord holds wherever its own does. Cut as one region, the sheet is cut once: Boost's difference of
// two cuts in turn that share the radial crack can answer nothing.
Polygon wedges_region(const Eigen::Vector2d& c, const Eigen::Vector2d& d, const SheetBreakPlan& plan, double reach) {
  const Eigen::Vector2d n(-d.y(), d.x());
  const double x = plan.crack_distance;
  std::vector<Eigen::Vector2d> axes;
  if (plan.crack == SheetCrack::kRadialWedges) {
    const double turn = plan.opening_angle / 4;
    axes = {std::cos(turn) * d + std::sin(turn) * n, std::cos(turn) * d - std::sin(turn) * n};
  } else {
    axes = {d};
  }
  Polygon region = disc(c, 2 * x, kCrackSegments);
  for (const Eigen::Vector2d& axis : axes) {
    const std::vector<Polygon> r = intersect(region, half_plane(c + x * axis, -axis, reach));
    if (r.empty()) throw std::logic_error("cut_sheet: the chord misses the crack's circle");
    region = r.front();  // convex with convex: one part
  }
  return region;
}

// The region that breaks off across a patch of half-width a: short of the crack at x_c along the load, which spans
// the patch, its ends run back to the edge at 45 degrees, and no farther than x_c behind the centre (a free edge
// running back would otherwise let it run along that edge): the trapezoid of those four lines, written down. Cut
// out of half-planes as squares, two of the squares' sides lay on one line, and Boost's intersection of squares
// that share a side's line can answer nothing (the paper's tow at mu 0.3 started at 5.201 m, leave_behind 6 m,
// 108.16 s: the run stopped)
Polygon across_region(const Eigen::Vector2d& c, const Eigen::Vector2d& d, double x, double a) {
  const Eigen::Vector2d n(-d.y(), d.x());
  const double back = 2 * x + a;  // the ends at 45 degrees meet the line x_c behind the centre this far out
  return make_ccw({c + x * d + a * n, c - x * d + back * n, c - x * d - back * n, c + x * d - a * n});
}

}  // namespace

SheetCut cut_sheet(const Polygon& sheet, const SheetContact& contact, const SheetBreakPlan& plan, double thickness,
                   const HeldEdges& held) {
  const Eigen::Vector2d& c = contact.centre;
  const Eigen::Vector2d d = contact.direction;
  const Eigen::Vector2d n(-d.y(), d.x());
  const double x = plan.crack_distance;
  const double a = contact.half_width;
  const double reach = 4 * x + 2 * a + 1.0;  // half-planes as squares larger than anything they cut here
  const Polygon region = plan.crack == SheetCrack::kAcrossPatch ? across_region(c, d, x, a)
                                                                : wedges_region(c, d, plan, reach);
  const std::vector<Polygon> inside = intersect(sheet, region);
  if (inside.empty()) return SheetCut{sheet, {}, 0.0};  // the load is at a point of the outline that holds no ice
  // what breaks off is the part that holds the load; another tongue of the sheet that crosses the region stays
  const std::size_t holding_load = part_holding(inside, c);
  const Polygon broken = inside[holding_load];

  SheetCut out;
  std::vector<Polygon> left, parts;
  // Boost's difference of a part of the sheet from the sheet (the two share that part's edges along the outline)
  // can answer the sheet unchanged: the ice that broke off would stay sheet and leave as pieces too, and the next
  // pass would break it again, without end (the paper's tow at mu 0.2 started at 5.202 m, at 215.78 s: 11,000 breaks
  // in one step, until the memory ran out). So the ice the difference takes must be the ice that breaks off, to
  // round-off of the sheet's area; where it is not, the region itself is taken, the other tongues in it breaking
  // off too (slivers of it, there); where that fails as well, the sheet holds this step.
  const double inside_area = total_area(inside);
  const double tolerance = kAreaRoundOff * area(sheet);
  const auto takes = [&](const std::vector<Polygon>& rest, double expected) {
    return std::abs(area(sheet) - total_area(rest) - expected) <= tolerance;
  };
  bool with_tongues = inside.size() == 1;
  try {
    parts = subtract(sheet, with_tongues ? region : broken);
    if (!takes(parts, with_tongues ? inside_area : area(broken))) {
      if (with_tongues) return SheetCut{sheet, {}, 0.0};
      with_tongues = true;
      parts = subtract(sheet, region);
      if (!takes(parts, inside_area)) return SheetCut{sheet, {}, 0.0};
    }
  } catch (const std::logic_error&) {
    // what breaks off would leave a hole in the sheet: the part holding the load meets the outline nowhere but at
    // a point (the paper's tow at mu 0.3, 92.84 s: the load 1.7 mm off an edge where the sheet within 2 x* was
    // three tongues). No break from the edge there: the sheet holds this step, as where no ice lies within the crack
    return SheetCut{sheet, {}, 0.0};
  }
  if (with_tongues)
    for (std::size_t k = 0; k < inside.size(); ++k)
      if (k != holding_load) out.pieces.push_back(inside[k]);
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
  if (plan.crack != SheetCrack::kRadialWedges) {
    out.pieces.push_back(broken);
    return out;
  }
  for (const Eigen::Vector2d& side : {n, Eigen::Vector2d(-n)})
    for (Polygon& half : intersect(broken, half_plane(c, side, reach))) out.pieces.push_back(std::move(half));
  return out;
}

}  // namespace icedem
