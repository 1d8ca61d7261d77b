#include "dem/step/health_check.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/step/world_builder.hpp"
#include "dem/world/cone_geometry.hpp"

namespace icedem {
namespace {

[[noreturn]] void blow_up(const State& state, const std::string& what, const std::string& quantity,
                          double value, const std::string& limit) {
  throw NumericalError(fmt::format("numerical blow-up at step {} (t = {:.3f} s): {}: {} = {:.6g} {}",
                                   state.step, state.time, what, quantity, value, limit));
}

// an element of a breakable floe is named by its body index too (HDF5 /bodies order
// differs only by the stand-ins of a lattice region)
std::string body_name(const FloeBody& floe) {
  return floe.fragment >= 0 ? fmt::format("floe {} (element body {})", floe.floe_id, floe.body->getUserIndex2())
                            : fmt::format("floe {}", floe.floe_id);
}

void check_motion(const Scene& scene, const State& state, const FloeBody& floe) {
  const btRigidBody& body = *floe.body;
  const btVector3& x = body.getCenterOfMassPosition();
  const double v = body.getLinearVelocity().length();
  const double w = body.getAngularVelocity().length();
  if (!std::isfinite(x.length())) blow_up(state, body_name(floe), "|position|", x.length(), "m (not finite)");
  // how far outside the tank: a scene may sit anywhere, a body does not leave its tank
  const double outside = tank_box(scene).exteriorDistance(to_eigen(x));
  if (outside > kBlowUpDistance)
    blow_up(state, body_name(floe), "distance outside the tank", outside, fmt::format("m, beyond {} m", kBlowUpDistance));
  if (!std::isfinite(v) || v > kBlowUpSpeed)
    blow_up(state, body_name(floe), "speed", v, fmt::format("m/s, beyond {} m/s", kBlowUpSpeed));
  // a 0.3 m floe spinning at kBlowUpSpeed / 0.15 m would shed its edges at that speed
  const double size = std::max(scene.ice.floe_size, 1e-3);
  if (!std::isfinite(w) || w * size / 2 > kBlowUpSpeed)
    blow_up(state, body_name(floe), "angular speed", w, "rad/s, edge speed beyond the blow-up speed");
}

// 1/2 m v^2 + 1/2 w . I w, with I the shape's principal moments in the body frame
double kinetic_energy(const FloeBody& floe) {
  const btRigidBody& body = *floe.body;
  const Eigen::Vector3d w_body =
      to_eigen(body.getCenterOfMassTransform().getBasis().transpose() * body.getAngularVelocity());
  return 0.5 * floe.shape->mass * body.getLinearVelocity().length2() +
         0.5 * w_body.dot(floe.shape->inertia.cwiseProduct(w_body));
}

// deepest vertex of the body's prism inside the structure hull; bodies whose
// bounding sphere cannot reach the hull are skipped
double cone_penetration(const Scene& scene, const State& state, const FloeBody& floe, double hull_reach) {
  const Eigen::Isometry3d pose = body_pose(*floe.body);
  const Eigen::Vector3d axis_offset = pose.translation() - state.structure_position;
  double body_reach = 0;
  for (const Eigen::Vector3d& v : floe.shape->prism.vertices) body_reach = std::max(body_reach, v.norm());
  if (std::hypot(axis_offset.x(), axis_offset.z()) > hull_reach + body_reach) return 0.0;
  double deepest = 0;
  for (const Eigen::Vector3d& v : floe.shape->prism.vertices) {
    const Eigen::Vector3d p = pose * v - state.structure_position;
    deepest = std::max(deepest, hull_depth(scene.structure.profile, scene.structure.segments, p));
  }
  return deepest;
}

// distance between where the two elements hold the joint's anchor: zero for a
// rigid joint, the joint's compliance (CFM) times its load for a soft one
double joint_gap(const IceJoint& joint) {
  const btGeneric6DofSpring2Constraint& c = *joint.constraint;
  const btVector3 a = c.getRigidBodyA().getCenterOfMassTransform() * c.getFrameOffsetA().getOrigin();
  const btVector3 b = c.getRigidBodyB().getCenterOfMassTransform() * c.getFrameOffsetB().getOrigin();
  return (a - b).length();
}

}  // namespace

StepDiagnostics check_health(const Scene& scene, const State& state) {
  StepDiagnostics d;
  double hull_reach = 0;
  for (const ProfileStation& s : scene.structure.profile)
    hull_reach = std::max(hull_reach, equal_area_vertex_radius(s.radius, scene.structure.segments));
  const Eigen::AlignedBox3d tank = tank_box(scene);

  for (const FloeBody& floe : state.world->floes()) {
    if (state.world->in_dormant_lattice(floe)) continue;  // its stand-in counts
    const btRigidBody& body = *floe.body;
    // any other body out of the world (a split floe), but for ice left behind, which is still in the tank
    if (liveness(body) == Liveness::kOutside && !floe.left) continue;
    if (tank.contains(to_eigen(body.getCenterOfMassPosition()))) d.ice_mass += floe.shape->mass;
  }
  // the awake ones (a sleeping body does not move), in the floes' order
  for (int i : state.world->awake_floe_indices()) {
    const FloeBody& floe = state.world->floes()[i];
    const btRigidBody& body = *floe.body;
    check_motion(scene, state, floe);
    d.max_speed = std::max(d.max_speed, static_cast<double>(body.getLinearVelocity().length()));
    d.max_angular_speed = std::max(d.max_angular_speed, static_cast<double>(body.getAngularVelocity().length()));
    d.kinetic_energy += kinetic_energy(floe);
    d.max_cone_penetration = std::max(d.max_cone_penetration, cone_penetration(scene, state, floe, hull_reach));
  }
  // the deepest overlap of two touching bodies (Bullet's distance is negative inside)
  btDispatcher& dispatcher = *state.world->dynamics().getDispatcher();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p)
      d.max_contact_penetration = std::max(d.max_contact_penetration, -double(manifold.getContactPoint(p).getDistance()));
  }
  for (const IceJoint& joint : state.world->joints())
    if (joint.constraint && !state.world->in_dormant_lattice(state.world->floes()[joint.body_a]) &&
        liveness(*state.world->floes()[joint.body_a].body) != Liveness::kOutside)
      d.max_joint_gap = std::max(d.max_joint_gap, joint_gap(joint));

  if (!state.load.force.allFinite() || !state.load.moment.allFinite())
    blow_up(state, "structure", "ice load |F|", state.load.force.norm(), "N (not finite)");
  return d;
}

}  // namespace icedem
