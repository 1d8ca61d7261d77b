#include "dem/fracture/level_ice.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/lattice_region.hpp"

namespace icedem {

Floe level_sheet_floe(const Scene& scene) {
  const double a = scene.channel.length / 2, b = scene.channel.width / 2 - scene.layout.min_gap;
  return Floe{Eigen::Vector2d(scene.channel.start_x + a, 0.0), 0.0, {{-a, -b}, {a, -b}, {a, b}, {-a, b}}};
}

void add_level_sheet(World& world, const Scene& scene, const Floe& floe, int floe_id, double y) {
  LevelSheet sheet;
  sheet.floe_id = floe_id;
  sheet.first_element = static_cast<int>(world.floes().size());
  sheet.first_joint = static_cast<int>(world.joints().size());
  add_lattice_floe(world, floe, floe_id, y, scene.fracture, scene.ice, scene.friction.ice_ice, /*held=*/true);
  sheet.elements = static_cast<int>(world.floes().size()) - sheet.first_element;
  sheet.joints = static_cast<int>(world.joints().size()) - sheet.first_joint;
  sheet.joint_in_world.assign(sheet.joints, 0);
  // the elements the ice around the sheet holds: along its sides and its far end (the structure
  // comes from x_min), within an element of the outline's edge
  double x_max = -INFINITY, z_min = INFINITY, z_max = -INFINITY;
  for (const Eigen::Vector2d& v : floe.shape) {
    x_max = std::max(x_max, floe.centre.x() + v.x());
    z_min = std::min(z_min, floe.centre.y() + v.y());
    z_max = std::max(z_max, floe.centre.y() + v.y());
  }
  const double near = scene.fracture.element_size;
  sheet.edge.assign(sheet.elements, 0);
  for (int i = 0; i < sheet.elements; ++i) {
    FloeBody& f = world.floes()[sheet.first_element + i];
    const btVector3 c = f.body->getCenterOfMassPosition();
    sheet.edge[i] = c.z() - z_min < near || z_max - c.z() < near || x_max - c.x() < near;
    f.fragment = sheet.first_element;  // named by its first element, as after a break (ice_lattice.cpp)
  }
  world.level_sheet() = std::move(sheet);
}

bool at_held_edge(const World& world, const IceJoint& joint) {
  const std::optional<LevelSheet>& sheet = world.level_sheet();
  return sheet && joint.floe == sheet->floe_id &&
         world.floes()[joint.body_a].frozen != world.floes()[joint.body_b].frozen;
}

void sync_level_sheet_joints(World& world) {
  std::optional<LevelSheet>& sheet = world.level_sheet();
  if (!sheet) return;
  for (int j = 0; j < sheet->joints; ++j) {
    IceJoint& joint = world.joints()[sheet->first_joint + j];
    char& in_world = sheet->joint_in_world[j];
    if (!joint.constraint) {  // broken: break_joint took it out of the solver
      in_world = 0;
      continue;
    }
    const bool wanted = !(world.floes()[joint.body_a].frozen && world.floes()[joint.body_b].frozen);
    if (wanted && !in_world)
      world.dynamics().addConstraint(joint.constraint.get(), false);  // the fragment filter handles collisions
    else if (!wanted && in_world)
      world.dynamics().removeConstraint(joint.constraint.get());
    in_world = wanted;
  }
}

void update_level_sheet(const Scene& scene, const Eigen::Vector3d& structure, World& world) {
  std::optional<LevelSheet>& sheet = world.level_sheet();
  if (!sheet) return;
  const double radius = scene.fracture.lattice_radius;
  std::vector<FloeBody>& floes = world.floes();
  // the fragments still part of the sheet: those with an element the ice around it holds
  std::set<int> attached;
  for (int i = 0; i < sheet->elements; ++i)
    if (sheet->edge[i]) attached.insert(floes[sheet->first_element + i].fragment);
  const double hold_beyond = radius + kLatticeHysteresis;
  // each element's nearest point is at least gap[i] from the axis and behind[i] behind it along
  // the travel (negative: ahead); a broken-off piece is as far behind as its nearest element,
  // indexed by the fragment's name (its first element) less the sheet's first
  const double travel = (scene.structure.speed > 0) - (scene.structure.speed < 0);
  std::vector<double> gap(sheet->elements), piece_behind(sheet->elements, INFINITY);
  for (int i = 0; i < sheet->elements; ++i) {
    const FloeBody& f = floes[sheet->first_element + i];
    const btVector3 c = f.body->getCenterOfMassPosition();
    gap[i] = std::hypot(c.x() - structure.x(), c.z() - structure.z()) - f.shape->radius;
    const double behind = (structure.x() - c.x()) * travel - f.shape->radius;
    double& piece = piece_behind[f.fragment - sheet->first_element];
    piece = std::min(piece, behind);
  }
  for (int i = 0; i < sheet->elements; ++i) {
    FloeBody& f = floes[sheet->first_element + i];
    // the attached sheet element by element; a broken-off piece whole, once the structure has left
    // all of it behind
    const bool hold = attached.count(f.fragment) ? gap[i] > hold_beyond
                                                 : piece_behind[f.fragment - sheet->first_element] > hold_beyond;
    if (f.frozen && gap[i] < radius) {
      world.unfreeze(f);  // at rest where it was held, awake
    } else if (!f.frozen && hold) {
      world.freeze(f);  // where it lies now: its joints keep the offsets they hold
    }
  }
  // every step, as the joints broken since (each a pass over two flags)
  sync_level_sheet_joints(world);
}

}  // namespace icedem
