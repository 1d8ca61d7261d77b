#include "dem/fracture/sheet_breaking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "dem/fracture/wedge_bending.hpp"
#include "dem/layout/polygon_set.hpp"

namespace icedem {
namespace {

// The wedge's S and x* / l depend on a / l alone; a solve takes a millisecond and a run asks for them at every
// step a zone is loaded, so they are kept per a / l rounded to kPatchStep (a tenth of a millimetre of patch at
// the paper's l), which makes a memo's answer the one computed afresh.
constexpr double kPatchStep = 2.5e-4;

WedgeBending wedge_at(double patch_over_l) {
  static std::map<long, WedgeBending> memo;
  const long key = std::max(1L, std::lround(patch_over_l / kPatchStep));
  if (auto it = memo.find(key); it != memo.end()) return it->second;
  return memo[key] = wedge_bending(std::min(key * kPatchStep, 6.0));
}

double characteristic_length(const SheetIce& ice) {
  const double h = ice.thickness, nu = ice.poisson_ratio;
  const double rigidity = ice.elastic_modulus * h * h * h / (12 * (1 - nu * nu));
  return std::pow(rigidity / (ice.water_density * ice.gravity), 0.25);
}

// P_f = sigma_b h^2 tan(theta / 2) / (3 S) (wedge_bending.hpp)
double wedge_load(double angle, const WedgeBending& w, const SheetIce& ice) {
  return ice.bending_strength * ice.thickness * ice.thickness * std::tan(angle / 2) / (3 * w.stress_factor);
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
  const double l = characteristic_length(ice);
  const WedgeBending w = wedge_at(contact.half_width / l);
  plan.crack_distance = w.crack_distance * l;
  double filled = 0;
  for (const Polygon& p : intersect(sheet, disc(contact.centre, plan.crack_distance, kCrackSegments)))
    filled += area(p);
  // against the polygon's disc, a little smaller than the circle, so that a straight edge fills pi
  const double polygon_circle = 0.5 * kCrackSegments * std::sin(2 * M_PI / kCrackSegments) *
                                plan.crack_distance * plan.crack_distance;
  plan.opening_angle = std::clamp(2 * M_PI * filled / polygon_circle, 1e-3, M_PI);
  plan.radial_crack = plan.opening_angle > kRadialCrackAngle;
  plan.breaking_load = plan.radial_crack ? 2 * wedge_load(plan.opening_angle / 2, w, ice)
                                         : wedge_load(plan.opening_angle, w, ice);
  return plan;
}

SheetCut cut_sheet(const Polygon& sheet, const SheetContact& contact, const SheetBreakPlan& plan) {
  const Polygon circle = disc(contact.centre, plan.crack_distance, kCrackSegments);
  std::vector<Polygon> inside = intersect(sheet, circle);
  if (inside.empty()) throw std::logic_error("cut_sheet: the crack's circle misses the sheet");
  // what breaks off: the part of the sheet within the circle that holds the load; the rest of the circle's
  // ice (another tongue of the sheet that crosses it) stays
  const std::size_t loaded = part_holding(inside, contact.centre);
  const Polygon broken = inside[loaded];

  SheetCut out;
  std::vector<Polygon> left = subtract(sheet, broken);
  if (left.empty()) throw std::logic_error("cut_sheet: the break takes the whole sheet");
  const auto largest = std::max_element(left.begin(), left.end(),
                                        [](const Polygon& a, const Polygon& b) { return area(a) < area(b); });
  out.sheet = *largest;
  for (auto it = left.begin(); it != left.end(); ++it)
    if (it != largest) out.pieces.push_back(*it);

  if (!plan.radial_crack) {
    out.pieces.push_back(broken);
    return out;
  }
  // the radial crack through the centre along the load splits the broken ice in two
  const Eigen::Vector2d normal(-contact.direction.y(), contact.direction.x());
  const double reach = 2 * plan.crack_distance + 1.0;
  for (const Eigen::Vector2d side : {normal, Eigen::Vector2d(-normal)})
    for (Polygon& half : intersect(broken, half_plane(contact.centre, side, reach))) out.pieces.push_back(half);
  return out;
}

}  // namespace icedem
