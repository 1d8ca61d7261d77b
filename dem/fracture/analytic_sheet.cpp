#include "dem/fracture/analytic_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "dem/core/errors.hpp"
#include "dem/layout/convex_partition.hpp"
#include "dem/layout/polygon_set.hpp"

namespace icedem {
namespace {

// the axis-aligned box of a polygon, for the cheap test of which tiles a cut can reach
struct Box {
  Eigen::Vector2d low, high;
  bool meets(const Box& o) const { return (low.array() <= o.high.array()).all() && (o.low.array() <= high.array()).all(); }
};
Box box_of(const Polygon& p) {
  Box b{p.front(), p.front()};
  for (const Eigen::Vector2d& v : p) b.low = b.low.cwiseMin(v), b.high = b.high.cwiseMax(v);
  return b;
}

// the record of a break of `contact` by `plan` at `time`, before the cut
SheetBreakRecord break_record(const SheetContact& contact, const SheetBreakPlan& plan, double time, const World& world) {
  SheetBreakRecord r;
  r.time = time;
  r.crack = static_cast<int32_t>(plan.crack);
  r.splits_before = static_cast<int32_t>(world.splits().size());
  r.x = contact.centre.x(), r.z = contact.centre.y();
  r.axis_x = contact.direction.x(), r.axis_z = contact.direction.y();
  r.half_width = contact.half_width;
  r.load = contact.bending_force;
  r.breaking_load = plan.breaking_load;
  r.opening_angle = plan.opening_angle;
  r.crack_distance = plan.crack_distance;
  return r;
}

}  // namespace

HullInIce hull_in_ice(const Scene& scene, const Eigen::Vector3d& structure) {
  HullInIce hull;
  hull.axis = Eigen::Vector2d(structure.x(), structure.z());
  hull.thickness = scene.ice.thickness;
  const double bottom = -scene.ice.draft, top = scene.ice.thickness - scene.ice.draft;
  hull.radius_top = profile_radius(scene.structure.profile, top - structure.y());
  hull.radius_bottom = profile_radius(scene.structure.profile, bottom - structure.y());
  return hull;
}

SheetIce sheet_ice(const Scene& scene) {
  const IceSettings& ice = scene.ice;
  return SheetIce{ice.thickness, ice.elastic_modulus, ice.poisson_ratio, ice.bending_strength,
                  scene.water.density, scene.water.gravity};
}

AnalyticSheet::AnalyticSheet(const Scene& scene, World& world, const Polygon& outline, int first_floe_id)
    : outline_(make_ccw(outline)),
      bottom_(-scene.ice.draft),
      thickness_(scene.ice.thickness),
      friction_(scene.friction.ice_ice),
      next_floe_id_(first_floe_id),
      sleeping_(scene.activation.sleeping),
      edge_bound_(sheet_ice(scene)) {
  // the ice around holds the sheet at every edge but the one the structure comes in from (its nearest)
  const Eigen::Vector2d start(scene.structure.start_x, scene.structure.start_z);
  std::size_t way_in = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < outline_.size(); ++i) {
    const Eigen::Vector2d mid = 0.5 * (outline_[i] + outline_[(i + 1) % outline_.size()]);
    if ((mid - start).norm() < nearest) nearest = (mid - start).norm(), way_in = i;
  }
  for (std::size_t i = 0; i < outline_.size(); ++i)
    if (i != way_in) held_.push_back({outline_[i], outline_[(i + 1) % outline_.size()]});
  const Box b = box_of(outline_);
  for (double x = b.low.x(); x < b.high.x() - 1e-9; x += kTileSize)
    for (double z = b.low.y(); z < b.high.y() - 1e-9; z += kTileSize) {
      cells_.push_back(make_ccw({{x, z}, {std::min(x + kTileSize, b.high.x()), z},
                                 {std::min(x + kTileSize, b.high.x()), std::min(z + kTileSize, b.high.y())},
                                 {x, std::min(z + kTileSize, b.high.y())}}));
      tile_cell(world, static_cast<int>(cells_.size()) - 1, intersect(outline_, cells_.back()));
    }
  edge_bound_.set_sheet(outline_, prism_bodies(world));
  world.contact_solver().set_contact_bound(&edge_bound_);
}

std::vector<Polygon> AnalyticSheet::prisms() const {
  std::vector<Polygon> out;
  for (const Tile& t : tiles_) out.push_back(t.outline);
  return out;
}

std::vector<const btCollisionObject*> AnalyticSheet::prism_bodies(const World& world) const {
  std::vector<const btCollisionObject*> out;
  for (const Tile& t : tiles_) out.push_back(world.bodies()[t.body].get());
  std::sort(out.begin(), out.end());
  return out;
}

void AnalyticSheet::tile_cell(World& world, int cell, const std::vector<Polygon>& sheet_in_cell) {
  for (const Polygon& part : sheet_in_cell)
    for (const Polygon& convex : convex_parts(part))
      tiles_.push_back(Tile{convex, world.add_static_prism(convex, bottom_, thickness_, friction_), cell});
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> AnalyticSheet::step(const Scene& scene, World& world,
                                                               const Eigen::Vector3d& structure, double time,
                                                               double h, FractureState& fracture) {
  const HullInIce hull = hull_in_ice(scene, structure);
  const CrushingLaw law{scene.ice.compressive_strength, scene.contact.pressure_area_exponent,
                        scene.ice.thickness * scene.ice.thickness};
  const SheetIce ice = sheet_ice(scene);
  const double mid = bottom_ + thickness_ / 2;  // the loads act at the ice's mid-depth
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero(), angular = Eigen::Vector3d::Zero();
  // the floes' pushes on the sheet over the step just solved
  std::vector<SheetLoadPoint> pushes = floe_loads_on_prisms(*world.dynamics().getDispatcher(), prism_bodies(world), h);
  // the floes whose push the edge's bound held in the solve: the edge gave way under them (sheet_edge_bound.hpp)
  const std::vector<int> gave_way = edge_bound_.floes_at_bound();
  // a break changes the outline, and with it the zones and patches: find them again until none breaks (a cut
  // takes the zone it breaks, and a patch that broke is spent, so each pass makes progress); the last pass's
  // zones are those that bear load
  std::vector<SheetContact> zones;
  for (bool broke = true, first = true; broke; first = false) {
    broke = false;
    holds_ = 0;  // the last pass, which cut nothing, saw every zone and patch of the final outline
    zones = sheet_contacts(outline_, hull, law, scene.friction.ice_structure);
    const FloePatches floes = floe_patches(outline_, pushes, thickness_);
    if (first) {
      for (const SheetContact& c : floes.patches) floe_totals_.edge += h * c.bending_force;
      floe_totals_.interior += h * floes.interior_vertical;
    }
    // the hull's zones first, then the floes' patches
    const std::size_t hull_zones = zones.size();
    for (std::size_t k = 0; k < hull_zones + floes.patches.size() && !broke; ++k) {
      const bool by_floe = k >= hull_zones;
      const SheetContact& c = by_floe ? floes.patches[k - hull_zones] : zones[k];
      const SheetBreakPlan plan = plan_sheet_break(outline_, c, ice);
      const bool bounded =
          by_floe && std::binary_search(gave_way.begin(), gave_way.end(), floes.floes[k - hull_zones]);
      if (c.bending_force < plan.breaking_load && !bounded) continue;
      SheetBreakRecord r = break_record(c, plan, time, world);
      r.by_floe = by_floe ? 1 : 0;
      if (!by_floe) r.hull_x = hull.axis.x(), r.hull_z = hull.axis.y(), r.hull_radius = hull.larger();
      if (!cut(world, r)) {
        ++holds_;
        continue;
      }
      FractureEvent e{time, -1, -1, static_cast<int>(FailureMode::kBending), c.bending_force / plan.breaking_load,
                      c.centre.x(), c.centre.y()};
      e.touching_structure = by_floe ? 0 : 1;
      e.structure_force = by_floe ? 0.0 : c.force_on_ice(hull).norm();
      fracture.add(e);
      if (by_floe) {  // its push is spent: it left with the piece
        const int spent = floes.floes[k - hull_zones];
        pushes.erase(std::remove_if(pushes.begin(), pushes.end(), [&](const SheetLoadPoint& p) { return p.floe == spent; }),
                     pushes.end());
      }
      broke = true;
    }
  }
  // what the unbroken zones bear this step: the crushing load, on the structure
  for (const SheetContact& c : zones) {
    const Eigen::Vector3d on_hull = -c.force_on_ice(hull);
    const Eigen::Vector3d at(c.centre.x(), mid, c.centre.y());
    impulse += h * on_hull;
    angular += h * (at - structure).cross(on_hull);
  }
  return {impulse, angular};
}

void AnalyticSheet::replay(World& world, const SheetBreakRecord& record) {
  SheetBreakRecord again = record;
  again.broken_area = again.crushed_area = 0;
  again.pieces = 0;
  if (!cut(world, again) || breaks_.back().pieces != record.pieces)
    throw InputError("the sheet's break at t = " + std::to_string(record.time) + " s did not make its " +
                     std::to_string(record.pieces) + " pieces again: the checkpoint is not this scene's or this build's");
}

bool AnalyticSheet::cut(World& world, SheetBreakRecord record) {
  SheetContact contact;
  contact.centre = Eigen::Vector2d(record.x, record.z);
  contact.direction = Eigen::Vector2d(record.axis_x, record.axis_z);
  contact.half_width = record.half_width;
  SheetBreakPlan plan;
  plan.opening_angle = record.opening_angle;
  plan.crack = static_cast<SheetCrack>(record.crack);
  plan.breaking_load = record.breaking_load;
  plan.crack_distance = record.crack_distance;
  const Polygon before = outline_;
  const SheetCut cut = cut_sheet(outline_, contact, plan, thickness_, held_);
  if (cut.pieces.empty() && cut.slivers == 0) return false;
  outline_ = cut.sheet;
  record.broken_area = area(before) - area(outline_);
  // a cut that made pieces must have taken their ice from the sheet, else the next pass breaks it again, without end
  if (!(record.broken_area > 0))
    throw std::logic_error("the level sheet's cut at t = " + std::to_string(record.time) +
                           " s made pieces but took no ice from the sheet (docs/model/breakage.md, \"Level ice cut by "
                           "closed forms\")");

  // the cells the ice that left crosses (the pieces and the slivers): each whose sheet changed is partitioned
  // again from its square, its prisms replaced
  Box reach = box_of(Polygon{contact.centre});
  for (const Polygon& p : subtract(before, outline_)) {
    const Box b = box_of(p);
    reach.low = reach.low.cwiseMin(b.low), reach.high = reach.high.cwiseMax(b.high);
  }
  std::vector<double> had(cells_.size(), 0.0);  // m^2, each cell's prisms
  for (const Tile& t : tiles_) had[t.cell] += area(t.outline);
  std::vector<int> changed;
  std::vector<std::vector<Polygon>> changed_sheet;  // each changed cell's sheet now
  for (int c = 0; c < static_cast<int>(cells_.size()); ++c) {
    if (had[c] <= 0 || !reach.meets(box_of(cells_[c]))) continue;
    std::vector<Polygon> left = intersect(outline_, cells_[c]);
    double left_area = 0;
    for (const Polygon& p : left) left_area += area(p);
    if (std::abs(left_area - had[c]) <= 1e-9 * area(cells_[c])) continue;
    changed.push_back(c);
    changed_sheet.push_back(std::move(left));
  }
  std::vector<Tile> kept;
  for (Tile& t : tiles_) {
    if (std::binary_search(changed.begin(), changed.end(), t.cell))
      world.remove_static(t.body);
    else
      kept.push_back(std::move(t));
  }
  tiles_ = std::move(kept);
  for (std::size_t k = 0; k < changed.size(); ++k) tile_cell(world, changed[k], changed_sheet[k]);
  edge_bound_.set_sheet(outline_, prism_bodies(world));

  // the pieces: under a hull's zone less the crushed ice, all that lies short of the line across the load that
  // touches the hull's larger section (straight, where the hull's circle would leave a concave face of many
  // corners, each a sliver of a convex part), as convex rigid floes at rest
  std::vector<Polygon> kept_pieces;
  if (!record.by_floe) {
    const Eigen::Vector2d axis(record.hull_x, record.hull_z);
    const Polygon beyond = half_plane(axis + record.hull_radius * contact.direction, contact.direction,
                                      2 * plan.crack_distance + 2 * record.hull_radius + 1.0);
    for (const Polygon& piece : cut.pieces)
      for (Polygon& outside : intersect(piece, beyond)) kept_pieces.push_back(std::move(outside));
  } else {
    kept_pieces = cut.pieces;
  }
  const double smallest = kSmallestPiece * thickness_ * thickness_;
  const double y = bottom_ + thickness_ / 2;
  double floes = 0;  // m^2, the pieces' floes; the rest of what left is crushed
  for (const Polygon& piece : kept_pieces)
    for (const Polygon& part : convex_parts(piece)) {
      if (area(part) < smallest || min_width(part) < thickness_) continue;
      const Eigen::Vector2d c = centroid(part);
      Polygon local;
      for (const Eigen::Vector2d& v : part) local.push_back(v - c);
      const FloeShape& shape = world.shape(local);
      btTransform pose;
      pose.setIdentity();
      pose.setOrigin(btVector3(c.x(), y, c.y()));
      pose.setRotation(btQuaternion(btVector3(0, 1, 0), shape.principal_yaw));
      const int index = world.add_body(shape, pose, next_floe_id_++, friction_);
      btRigidBody& b = *world.floes()[index].body;
      b.forceActivationState(sleeping_ ? ACTIVE_TAG : DISABLE_DEACTIVATION);
      b.setDeactivationTime(0);
      ++record.pieces;
      floes += area(part);
    }
  record.crushed_area = record.broken_area - floes;
  breaks_.push_back(record);
  outlines_after_.push_back(outline_);
  return true;
}

}  // namespace icedem
