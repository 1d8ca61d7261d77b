#include "dem/step/world_builder.hpp"

#include <algorithm>
#include <cmath>

#include "dem/core/constants.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/level_ice.hpp"
#include "dem/world/cone_geometry.hpp"

namespace icedem {
namespace {
constexpr double kTankWallTop = 0.5;  // m above the still-water line
}

WorldSettings world_settings(const Scene& scene) {
  WorldSettings s;
  s.solver = scene.solver;
  s.activation = scene.activation;
  s.gravity = scene.water.gravity;
  s.contact_law.crushing_force = scene.ice.contact_crushing ? crushing_force(scene.ice) : 0.0;
  if (scene.contact.model == ContactModel::kCrushing)
    s.contact_law.crushing = CrushingLaw{scene.ice.compressive_strength, scene.contact.pressure_area_exponent,
                                         scene.ice.thickness * scene.ice.thickness};
  s.contact_law.crushing_scope = scene.contact.crushing_contacts == CrushingContacts::kAll ? CrushingScope::kAllIce
                                 : scene.contact.crushing_contacts == CrushingContacts::kStructureAndSheet
                                     ? CrushingScope::kStructureAndHeldIce
                                     : CrushingScope::kStructure;
  // the sweep-and-prune broadphase needs the world's bounds: the tank with a margin
  const ChannelSettings& c = scene.channel;
  const double x0 = std::min(scene.structure.start_x, c.start_x) - 10.0;
  const double x1 = c.start_x + c.length + 10.0;
  const double z = c.tank_width / 2 + 5.0;
  s.bounds = Eigen::AlignedBox3d(Eigen::Vector3d(x0, -c.tank_depth - 5.0, -z), Eigen::Vector3d(x1, 10.0, z));
  s.ice_thickness = scene.ice.thickness;
  s.ice_density = scene.ice.density;
  s.water = water_params(scene.water);
  s.added_mass = scene.water.added_mass;
  s.contact_law.static_friction = {scene.friction.ice_ice_static, scene.friction.ice_structure_static, scene.friction.stick_speed};
  return s;
}

Eigen::AlignedBox3d tank_box(const Scene& scene) {
  const ChannelSettings& c = scene.channel;
  const double x0 = std::min(scene.structure.start_x, c.start_x) - 2.0;  // tank start, behind the carriage
  const double x1 = c.start_x + c.length + 1.0;                          // 1 m beyond the channel end
  return {Eigen::Vector3d(x0, -c.tank_depth, -c.tank_width / 2), Eigen::Vector3d(x1, kTankWallTop, c.tank_width / 2)};
}

bool is_breakable(const Scene& scene, const Polygon& outline) {
  switch (scene.fracture.mode) {
    case FractureMode::kOff:
    case FractureMode::kAnalytic: return false;  // rigid floes (that may split: dem/fracture/fracture_split.hpp)
    case FractureMode::kOn: return true;
    case FractureMode::kAuto: {
      // floes smaller than the characteristic length stay rigid (paper: 0.3 m < l_c)
      double size = 0;
      for (const Eigen::Vector2d& a : outline)
        for (const Eigen::Vector2d& b : outline) size = std::max(size, (a - b).norm() / std::sqrt(2.0));
      return size >= scene.fracture.characteristic_length;
    }
  }
  return false;
}

double initial_height(const Scene& scene, const Floe& floe) {
  const double h = scene.ice.thickness;
  return h / 2 - scene.ice.draft + floe.layer * (h + scene.layout.min_gap);
}

void add_profile_structure(World& world, const Scene& scene, const Eigen::Vector3d& start) {
  auto compound = std::make_unique<btCompoundShape>();
  std::vector<std::unique_ptr<btCollisionShape>> pieces;
  btTransform identity;
  identity.setIdentity();
  for (const auto& piece : hull_pieces(scene.structure.profile, scene.structure.segments)) {
    auto hull = std::make_unique<btConvexHullShape>();
    for (const Eigen::Vector3d& p : piece) hull->addPoint(to_bt(p), false);
    hull->recalcLocalAabb();
    hull->setMargin(scene.structure.collision_margin);
    compound->addChildShape(identity, hull.get());
    pieces.push_back(std::move(hull));
  }
  world.add_structure(std::move(compound), start, scene.friction.ice_structure, std::move(pieces));
}

void add_boundaries(World& world, const Scene& scene) {
  const ChannelSettings& c = scene.channel;
  const double h = scene.ice.thickness;
  const double y_ice = h / 2 - scene.ice.draft;  // centre of a floating sheet
  const Eigen::AlignedBox3d tank = tank_box(scene);
  const double x0 = tank.min().x(), x1 = tank.max().x();
  const double x_end = c.start_x + c.length;
  const double side = (c.tank_width - c.width) / 2;  // mother ice left along each wall
  const double f = scene.friction.ice_ice;           // the tank's walls and floor
  const double f_edge = f * c.edge_friction_factor;  // mother ice: ice, its edges as cut

  // mother ice along both sides of the channel: fixed sheets at the waterline
  if (side > 0)
    for (double sign : {-1.0, 1.0})
      world.add_static_box({(x0 + x1) / 2, y_ice, sign * (c.width / 2 + side / 2)}, {(x1 - x0) / 2, h / 2, side / 2},
                           kBoundary, f_edge);
  // mother ice closing the far end of the channel
  if (c.end_wall) world.add_static_box({x_end + 0.5, y_ice, 0.0}, {0.5, h / 2, c.width / 2}, kBoundary, f_edge);

  // tank walls, ends and floor (floes pushed under the ice must not fall out)
  const double wall = 0.1, top = kTankWallTop;
  const double ymid = (top - c.tank_depth) / 2, yhalf = (top + c.tank_depth) / 2;
  for (double sign : {-1.0, 1.0})
    world.add_static_box({(x0 + x1) / 2, ymid, sign * (c.tank_width / 2 + wall)},
                         {(x1 - x0) / 2 + 2 * wall, yhalf, wall}, kBoundary, f);
  world.add_static_box({x0 - wall, ymid, 0.0}, {wall, yhalf, c.tank_width / 2}, kBoundary, f);
  world.add_static_box({x1 + wall, ymid, 0.0}, {wall, yhalf, c.tank_width / 2}, kBoundary, f);
  world.add_static_box({(x0 + x1) / 2, -c.tank_depth - wall, 0.0},
                       {(x1 - x0) / 2 + 2 * wall, wall, c.tank_width / 2 + 2 * wall}, kBoundary, f);
}

void add_floes(World& world, const Scene& scene, const std::vector<Floe>& floes) {
  world.floes().reserve(world.floes().size() + floes.size());
  int floe_id = 0;  // continue after the floes already in the world
  for (const FloeBody& f : world.floes()) floe_id = std::max(floe_id, f.floe_id + 1);
  for (const Floe& floe : floes) {
    const double y = initial_height(scene, floe);
    if (scene.ice.cover == IceCover::kLevel) {  // the layout's one floe: the sheet
      // cut by closed forms, the sheet is the State's (initial_state), not a floe
      if (!analytic_level_ice(scene)) add_level_sheet(world, scene, floe, floe_id, y);
      ++floe_id;
      continue;
    }
    if (is_breakable(scene, floe.shape)) {
      add_lattice_floe(world, floe, floe_id++, y, scene.fracture, scene.ice, scene.friction.ice_ice);
      continue;
    }
    const FloeShape& shape = world.shape(floe.shape);
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(btVector3(floe.centre.x(), y, floe.centre.y()));
    pose.setRotation(btQuaternion(btVector3(0, 1, 0), floe.yaw + shape.principal_yaw));
    world.add_resting_floe(shape, pose, floe_id++, scene.friction.ice_ice);
  }
}

std::unique_ptr<World> build_world(const Scene& scene, const std::vector<Floe>& floes,
                                   const Eigen::Vector3d& structure_start) {
  // at once, not after filling the sweep and prune up to its limit (World::enter_world)
  if (scene.solver.broadphase == Broadphase::kSweepAndPrune) require_sweep_and_prune_room(floes.size());
  auto world = std::make_unique<World>(world_settings(scene));
  add_profile_structure(*world, scene, structure_start);
  add_boundaries(*world, scene);
  add_floes(*world, scene, floes);
  world->settle_broadphase();
  return world;
}

}  // namespace icedem
