#include "dem/fracture/fracture_split.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <vector>

#include "dem/fracture/break_context.hpp"
#include "dem/fracture/fracture_analytic.hpp"
#include "dem/world/bullet_eigen.hpp"
#include "dem/world/load_cell.hpp"

namespace icedem {
namespace {

// The beam's moment per load depends on its length only (the water's stiffness and the ice's
// rigidity both scale with the width), and the capacity grows with the width: the breaking load
// per metre of width and the crack's place are a function of the length. They are computed at
// the length rounded to kLengthStep, so that a memo of them gives the same numbers as
// computing them afresh, and kept per ice and water.
constexpr double kLengthStep = 1e-4;  // m

EdgeBreak breaking_load_per_width(const Scene& scene, double length) {
  const long step = std::lround(length / kLengthStep);
  using Key = std::tuple<long, double, double, double, double, double, double>;
  static std::map<Key, EdgeBreak> memo;
  const IceSettings& ice = scene.ice;
  const Key key{step, ice.thickness, ice.elastic_modulus, ice.poisson_ratio, ice.bending_strength,
                scene.water.density, scene.water.gravity};
  if (auto it = memo.find(key); it != memo.end()) return it->second;
  const EdgeBreak b = edge_breaking_load(step * kLengthStep, 1.0, ice.thickness, ice.elastic_modulus,
                                         ice.poisson_ratio, ice.bending_strength, scene.water.density,
                                         scene.water.gravity);
  return memo[key] = b;
}

// the structure's contact force on one floe over the Bullet step, and where it acts
struct StructureLoad {
  int floe = -1;  // index into World::floes()
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // N, on the floe, tank frame
  Eigen::Vector3d weighted_point = Eigen::Vector3d::Zero();  // N m: contact points times |impulse| / h
  double weight = 0;  // N: the sum of the |impulse| / h
};

// every awake whole rigid floe the structure touches, with its load, summed in the canonical
// order of the manifolds (structure_manifolds)
std::vector<StructureLoad> structure_loads(World& world, double h) {
  const btRigidBody* structure = world.structure();
  std::vector<const btPersistentManifold*> touching;
  structure_manifolds(*world.dynamics().getDispatcher(), structure, touching);
  std::map<int, StructureLoad> loads;
  for (const btPersistentManifold* m : touching) {
    const bool floe_is_0 = m->getBody0() != structure;
    const FloeBody* f = world.ice_body(floe_is_0 ? m->getBody0() : m->getBody1());
    if (!f || f->fragment >= 0 || f->stand_in || liveness(*f->body) != Liveness::kAwake) continue;
    StructureLoad& load = loads[f->body->getUserIndex2()];
    load.floe = f->body->getUserIndex2();
    // impulses act on body 0 (dem/world/load_cell.cpp); the floe feels them with this sign
    const double sign = floe_is_0 ? 1.0 : -1.0;
    for (int k = 0; k < m->getNumContacts(); ++k) {
      const btManifoldPoint& p = m->getContactPoint(k);
      const Eigen::Vector3d force = sign / h * to_eigen(contact_impulse(p));
      const Eigen::Vector3d at = to_eigen(floe_is_0 ? p.getPositionWorldOnA() : p.getPositionWorldOnB());
      load.force += force;
      load.weighted_point += force.norm() * at;
      load.weight += force.norm();
    }
  }
  std::vector<StructureLoad> out;
  for (auto& [index, load] : loads)
    if (load.weight > 0) out.push_back(load);
  return out;
}

}  // namespace

CrackPlan plan_crack(const Scene& scene, const Polygon& outline, const Eigen::Vector2d& contact) {
  CrackPlan plan;
  const CentroidalMoments m = centroidal_moments(outline);
  const Eigen::Vector2d d = m.centroid - contact;
  if (d.norm() > 0) plan.direction = d.normalized();  // a contact at the centroid: along body x
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const Eigen::Vector2d& v : outline) {
    low = std::min(low, v.dot(plan.direction));
    high = std::max(high, v.dot(plan.direction));
  }
  plan.length = high - low;
  plan.width = m.area / plan.length;
  const EdgeBreak per_width = breaking_load_per_width(scene, plan.length);
  plan.breaking_load = per_width.load * plan.width;
  plan.crack_distance = per_width.crack_distance;
  // the crack line across the direction, through the centroid's projection on it
  const double along = low + plan.crack_distance - m.centroid.dot(plan.direction);
  plan.point = m.centroid + along * plan.direction;
  // both pieces at least the shortest along the load and at their narrowest (a crack across a
  // corner would leave a sliver)
  const double shortest = kMinPieceThicknesses * scene.ice.thickness;
  plan.splits = plan.crack_distance >= shortest && plan.length - plan.crack_distance >= shortest;
  if (plan.splits) {
    const PolygonCut parts = cut(outline, plan.point, plan.direction);
    plan.splits = min_width(parts.behind) >= shortest && min_width(parts.ahead) >= shortest;
  }
  return plan;
}

void check_splits(const Scene& scene, World& world, double time, const Eigen::Vector3d& structure, double h,
                  FractureState& fracture) {
  // every floe's load and crack first, then the splits: a split removes the floe and its
  // contacts, which the context of another floe's split may still need
  struct Split {
    FloeSplit split;
    FractureEvent event;
  };
  std::vector<Split> splits;
  for (const StructureLoad& load : structure_loads(world, h)) {
    const FloeBody& floe = world.floes()[load.floe];
    const Eigen::Isometry3d pose = body_pose(*floe.body);
    const Eigen::Vector3d at = pose.inverse() * (load.weighted_point / load.weight);
    const CrackPlan plan = plan_crack(scene, floe.shape->outline, Eigen::Vector2d(at.x(), at.z()));
    // bending is by the force normal to the floe's plane (its body y axis)
    const double normal_load = std::abs(load.force.dot(pose.linear().col(1)));
    const double ratio = normal_load / plan.breaking_load;
    if (fracture.floe_margins.size() <= static_cast<std::size_t>(floe.floe_id))
      fracture.floe_margins.resize(floe.floe_id + 1);
    FloeFailureMargin& margin = fracture.floe_margins[floe.floe_id];
    margin.max_ratio = std::max(margin.max_ratio, ratio);
    margin.min_distance = 0.0;  // touching the structure
    if (ratio < 1.0 || !plan.splits) continue;

    const Eigen::Vector3d crack = pose * Eigen::Vector3d(plan.point.x(), 0.0, plan.point.y());
    const btRigidBody* body = floe.body;
    BreakContext context = break_context(
        scene, world, [body](const btCollisionObject* o) { return o == body; }, crack, structure, h);
    const BreakMechanism mechanism = classify_break(context, scene.ice.thickness);
    FractureEvent e{time, floe.floe_id, -1, static_cast<int>(FailureMode::kBending), ratio, crack.x(), crack.z()};
    e.mechanism = static_cast<int>(mechanism);
    e.touching_structure = context.touching_structure ? 1 : 0;
    e.depth = context.depth;
    e.distance = context.distance;
    e.structure_force = context.structure_force;
    e.press_down = context.press_down;
    e.press_toward = context.press_toward;
    e.ratio_bending = ratio;
    splits.push_back(Split{FloeSplit{load.floe, {plan.point.x(), plan.point.y()},
                                     {plan.direction.x(), plan.direction.y()}},
                           e});
  }
  for (const Split& s : splits) {
    world.split_floe(s.split);
    fracture.add(s.event);
  }
}

}  // namespace icedem
