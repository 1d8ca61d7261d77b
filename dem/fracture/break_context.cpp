#include "dem/fracture/break_context.hpp"

#include <algorithm>

#include "dem/world/bullet_eigen.hpp"
#include "dem/world/cone_geometry.hpp"
#include "dem/world/world.hpp"

namespace icedem {

const char* break_mechanism_name(BreakMechanism mechanism) {
  switch (mechanism) {
    case BreakMechanism::kOnSlope: return "on the slope";
    case BreakMechanism::kPressedUnder: return "pressed under";
    case BreakMechanism::kInRubble: return "in the rubble";
    case BreakMechanism::kInPack: return "in the pack";
  }
  return "unknown";
}

double distance_from_structure(const Scene& scene, const Eigen::Vector3d& structure_position,
                               const Eigen::Vector3d& point) {
  const std::vector<ProfileStation>& profile = scene.structure.profile;
  const double r = std::hypot(point.x() - structure_position.x(), point.z() - structure_position.z());
  // the section at the point's height (the nearest end station above the deck or below the keel)
  const double y = std::clamp(point.y() - structure_position.y(), profile.front().y, profile.back().y);
  return std::max(0.0, r - profile_radius(profile, y));
}

namespace {

// the layout floe a collision object belongs to, or -1 if it is no floe body
int floe_of(const World& world, const btCollisionObject* object) {
  const FloeBody* f = world.ice_body(object);
  return f ? f->floe_id : -1;
}

}  // namespace

BreakContext break_context(const Scene& scene, const World& world, int floe_id, const Eigen::Vector3d& midpoint,
                           const Eigen::Vector3d& structure_position, double h) {
  return break_context(
      scene, world, [&](const btCollisionObject* o) { return floe_of(world, o) == floe_id; }, midpoint,
      structure_position, h);
}

BreakContext break_context(const Scene& scene, const World& world,
                           const std::function<bool(const btCollisionObject*)>& is_floe,
                           const Eigen::Vector3d& midpoint, const Eigen::Vector3d& structure_position, double h) {
  BreakContext c;
  c.depth = -midpoint.y();
  c.distance = distance_from_structure(scene, structure_position, midpoint);
  Eigen::Vector3d structure_force = Eigen::Vector3d::Zero();
  double down = 0, toward = 0;  // N, the other floes' contact force on the floe
  btDispatcher& dispatcher = *const_cast<World&>(world).dynamics().getDispatcher();
  for (int i = 0; i < dispatcher.getNumManifolds(); ++i) {
    const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
    const bool floe_is_0 = is_floe(m->getBody0());
    const bool floe_is_1 = is_floe(m->getBody1());
    if (floe_is_0 == floe_is_1) continue;  // not this floe's, or between two of its fragments
    const btCollisionObject* other = floe_is_0 ? m->getBody1() : m->getBody0();
    const bool structure = other == world.structure();
    const bool ice = other->getUserIndex() == kIce;
    if (!structure && !ice) continue;  // the mother ice and the tank
    // impulses act on body 0 (dem/world/load_cell.cpp); the floe feels them with this sign
    const double sign = floe_is_0 ? 1.0 : -1.0;
    for (int k = 0; k < m->getNumContacts(); ++k) {
      const btManifoldPoint& p = m->getContactPoint(k);
      const Eigen::Vector3d force = sign / h * to_eigen(contact_impulse(p));
      if (structure) {
        c.touching_structure = true;
        structure_force += force;
        continue;
      }
      const Eigen::Vector3d at = to_eigen(floe_is_0 ? p.getPositionWorldOnA() : p.getPositionWorldOnB());
      Eigen::Vector3d inward(structure_position.x() - at.x(), 0.0, structure_position.z() - at.z());
      if (inward.norm() > 0) inward.normalize();
      // signed sums: a floe resting flush on elements has contacts on their side faces
      // whose friction pushes some elements up and others down; those cancel in the
      // force the other floes exert, which is what presses the floe
      down += -force.y();
      toward += force.dot(inward);
    }
  }
  c.structure_force = structure_force.norm();
  c.press_down = std::max(0.0, down);
  c.press_toward = std::max(0.0, toward);
  return c;
}

BreakMechanism classify_break(const BreakContext& c, double thickness) {
  const bool submerged = c.depth >= thickness;
  if (!c.touching_structure) return submerged ? BreakMechanism::kInRubble : BreakMechanism::kInPack;
  const bool pressed = c.press_down + c.press_toward > kPressingForce;
  return submerged && pressed ? BreakMechanism::kPressedUnder : BreakMechanism::kOnSlope;
}

}  // namespace icedem
