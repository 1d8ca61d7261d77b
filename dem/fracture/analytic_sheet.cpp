#include "dem/fracture/analytic_sheet.hpp"

#include <algorithm>
#include <cmath>

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
      next_floe_id_(first_floe_id) {
  const Box b = box_of(outline_);
  for (double x = b.low.x(); x < b.high.x() - 1e-9; x += kTileSize)
    for (double z = b.low.y(); z < b.high.y() - 1e-9; z += kTileSize) {
      const Polygon square = make_ccw({{x, z}, {std::min(x + kTileSize, b.high.x()), z},
                                       {std::min(x + kTileSize, b.high.x()), std::min(z + kTileSize, b.high.y())},
                                       {x, std::min(z + kTileSize, b.high.y())}});
      for (const Polygon& part : intersect(outline_, square))
        for (const Polygon& convex : convex_parts(part)) add_tile(world, convex);
    }
}

std::vector<Polygon> AnalyticSheet::prisms() const {
  std::vector<Polygon> out;
  for (const Tile& t : tiles_) out.push_back(t.outline);
  return out;
}

void AnalyticSheet::add_tile(World& world, const Polygon& outline) {
  tiles_.push_back(Tile{outline, world.add_static_prism(outline, bottom_, thickness_, friction_)});
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
  // a break changes the outline, and with it the zones: find them again until none breaks (a cut takes the
  // zone it breaks, so each pass makes progress)
  for (bool broke = true; broke;) {
    broke = false;
    for (const SheetContact& c : sheet_contacts(outline_, hull, law, scene.friction.ice_structure)) {
      const SheetBreakPlan plan = plan_sheet_break(outline_, c, ice);
      if (c.bending_force < plan.breaking_load) continue;
      FractureEvent e{time, -1, -1, static_cast<int>(FailureMode::kBending), c.bending_force / plan.breaking_load,
                      c.centre.x(), c.centre.y()};
      e.touching_structure = 1;
      e.structure_force = c.force_on_ice(hull).norm();
      fracture.add(e);
      cut(scene, world, c, plan, hull, time);
      breaks_.back().load = c.bending_force;
      broke = true;
      break;
    }
  }
  // what the unbroken zones bear this step: the crushing load, on the structure
  for (const SheetContact& c : sheet_contacts(outline_, hull, law, scene.friction.ice_structure)) {
    const Eigen::Vector3d on_hull = -c.force_on_ice(hull);
    const Eigen::Vector3d at(c.centre.x(), mid, c.centre.y());
    impulse += h * on_hull;
    angular += h * (at - structure).cross(on_hull);
  }
  return {impulse, angular};
}

void AnalyticSheet::cut(const Scene& scene, World& world, const SheetContact& contact, const SheetBreakPlan& plan,
                        const HullInIce& hull, double time) {
  const double before = area(outline_);
  const SheetCut cut = cut_sheet(outline_, contact, plan);
  outline_ = cut.sheet;
  SheetBreakRecord record;
  record.time = time;
  record.centre = contact.centre;
  record.plan = plan;
  record.broken_area = before - area(outline_);

  // the fixed prisms the broken ice crosses (all of it lies within the crack's circle, but for parts of the
  // sheet cut off whole): replaced by their convex parts that are still sheet
  Box reach = box_of(disc(contact.centre, plan.crack_distance, kCrackSegments));
  for (const Polygon& p : cut.pieces) {
    const Box b = box_of(p);
    reach.low = reach.low.cwiseMin(b.low), reach.high = reach.high.cwiseMax(b.high);
  }
  std::vector<Tile> kept;
  std::vector<Polygon> replaced;
  for (Tile& t : tiles_) {
    if (!reach.meets(box_of(t.outline))) {
      kept.push_back(std::move(t));
      continue;
    }
    // the tile's part that is still sheet
    std::vector<Polygon> left;
    for (const Polygon& p : intersect(t.outline, outline_)) left.push_back(p);
    double left_area = 0;
    for (const Polygon& p : left) left_area += area(p);
    if (std::abs(left_area - area(t.outline)) <= 1e-9 * area(t.outline)) {
      kept.push_back(std::move(t));
      continue;
    }
    world.remove_static(t.body);
    for (const Polygon& p : left) replaced.push_back(p);
  }
  tiles_ = std::move(kept);
  for (const Polygon& p : replaced)
    for (const Polygon& convex : convex_parts(p)) add_tile(world, convex);

  // the pieces: less the crushed ice, all that lies short of the line across the load that touches the hull's
  // larger section (straight, where the hull's circle would leave a concave face of many corners, each a
  // sliver of a convex part), as convex rigid floes at rest
  const Eigen::Vector2d face = hull.axis + hull.larger() * contact.direction;
  const Polygon beyond = half_plane(face, contact.direction, 2 * plan.crack_distance + 2 * hull.larger() + 1.0);
  const double smallest = kSmallestPiece * thickness_ * thickness_;
  const double y = bottom_ + thickness_ / 2;
  for (const Polygon& piece : cut.pieces)
    for (const Polygon& outside : intersect(piece, beyond))
      for (const Polygon& part : convex_parts(outside)) {
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
        b.forceActivationState(scene.activation.sleeping ? ACTIVE_TAG : DISABLE_DEACTIVATION);
        b.setDeactivationTime(0);
        ++record.pieces;
        record.crushed_area -= area(part);
      }
  record.crushed_area += record.broken_area;
  breaks_.push_back(record);
}

}  // namespace icedem
