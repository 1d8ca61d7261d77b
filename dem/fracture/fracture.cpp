#include "dem/fracture/fracture.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dem/fracture/break_context.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/level_ice.hpp"
#include "dem/world/bullet_eigen.hpp"

namespace icedem {

JointLoads joint_loads(const World& world, const IceJoint& joint) {
  return joint_loads(world, joint, to_eigen(joint.feedback->m_appliedForceBodyA),
                     to_eigen(joint.feedback->m_appliedTorqueBodyA));
}

JointLoads joint_loads(const World& world, const IceJoint& joint, const Eigen::Vector3d& force_on_a,
                       const Eigen::Vector3d& torque_on_a) {
  const Eigen::Isometry3d pose_a = body_pose(*world.floes()[joint.body_a].body);
  return decompose_joint_load(force_on_a, torque_on_a, pose_a.translation(), pose_a * joint.midpoint_a,
                              pose_a.linear() * joint.axis_a, pose_a.linear() * Eigen::Vector3d::UnitY());
}

JointCapacity joint_capacity(const Scene& scene, const IceJoint& joint) {
  const JointCapacity square =
      paper_joint_capacity(scene.fracture.element_size, scene.ice.thickness, scene.ice.compressive_strength,
                           scene.ice.shear_strength, scene.ice.bending_strength);
  // a joint's capacities are its face's (eqs. 1-3: each is proportional to the face's length)
  JointCapacity c = joint.face_length > 0 ? scaled(square, joint.face_length / scene.fracture.element_size) : square;
  // the lattice's calibration (fracture.strength_scale) scales the bending capacity only: it is
  // measured in bending (the wide cantilever), where a crack through hexagons must zig-zag and
  // their faces' capacities sum to 1.2-1.4 times the plate's. In the plate's own plane the
  // unscaled hexagons already break at the compressive strength along x (0.95-1.07 sigma_c, the
  // squares' 1.00) and off it no lower than the squares (the wide cantilever pushed along its
  // plane; docs/model/breakage.md, "In the plate's plane"), so scaling eqs. 1-2 as well made them
  // a quarter weaker in compression and shear than any measurement asks
  c.bending *= scene.fracture.strength_scale;
  return c;
}

JointRatios joint_ratios(const Scene& scene, const World& world, const ContactProblem& p, const Eigen::VectorXd& l) {
  // the wrench each joint's rows put on its element A, as Bullet's joint feedback sums it
  // (J_A^T l / h: the rows' linear and angular parts on A)
  struct Wrench {
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  };
  std::vector<std::pair<int, Wrench>> on_a;  // joint index in World::joints(), wrench
  for (std::size_t r = 0; r < p.joints.size(); ++r) {
    const ProblemJointRow& row = p.joints[r];
    if (row.joint < 0) continue;
    const IceJoint& joint = world.joints()[row.joint];
    const bool a_first = row.a >= 0 && p.bodies[row.a].id == joint.body_a;
    if (!a_first && !(row.b >= 0 && p.bodies[row.b].id == joint.body_a)) continue;
    const RowJacobian& j = a_first ? row.ja : row.jb;
    if (on_a.empty() || on_a.back().first != row.joint) on_a.emplace_back(row.joint, Wrench{});
    Wrench& w = on_a.back().second;
    w.force += j.head<3>().transpose() * (l(static_cast<int>(r)) / p.dt);
    w.torque += j.tail<3>().transpose() * (l(static_cast<int>(r)) / p.dt);
  }
  JointRatios out;
  for (const auto& [index, w] : on_a) {
    const IceJoint& joint = world.joints()[index];
    if (at_held_edge(world, joint)) continue;
    double ratio = 0;
    failure_mode(joint_loads(world, joint, w.force, w.torque), joint_capacity(scene, joint), ratio);
    out.largest = std::max(out.largest, ratio);
    if (std::abs(ratio - 1) < std::abs(out.nearest - 1)) out.nearest = ratio;
  }
  return out;
}

namespace {

// First-order low-pass y += a (x - y), a = h / (tau + h): a load held for much
// less than tau reaches only a fraction of its value, a sustained load reaches
// all of it. It removes the one-step impulses of an unconverged PGS solve
// without lowering the static capacity of a joint.
void low_pass(JointLoads& y, const JointLoads& x, double a) {
  y.axial += a * (x.axial - y.axial);
  y.shear_in_plane += a * (x.shear_in_plane - y.shear_in_plane);
  y.shear_vertical += a * (x.shear_vertical - y.shear_vertical);
  y.bending_out_of_plane += a * (x.bending_out_of_plane - y.bending_out_of_plane);
  y.bending_in_plane += a * (x.bending_in_plane - y.bending_in_plane);
  y.torsion += a * (x.torsion - y.torsion);
}

}  // namespace

int check_fracture(const Scene& scene, World& world, double time, const Eigen::Vector3d& structure, double h,
                   FractureState& fracture) {
  std::vector<IceJoint>& joints = world.joints();
  if (joints.empty()) return 0;
  const double tau = scene.fracture.load_filter_time;
  const double a = h / (tau + h);
  if (tau > 0 && fracture.filtered_joint_loads.size() != joints.size())
    fracture.filtered_joint_loads.resize(joints.size(), JointLoads{});

  // The joints that fail this step are broken after all of them are found: breaking one
  // refreshes its floe's broadphase proxies, which drops the floe's contact manifolds until
  // the next collision pass, and the context of the floe's other breaks of the step (its
  // contacts with the structure and with other floes) must be read from those manifolds.
  std::vector<std::size_t> failed;
  int held_edge_overloads = 0;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    IceJoint& joint = joints[i];
    if (!joint.constraint) continue;  // broken already
    // a dormant lattice's elements are out of the world, not awake: skipped below as well
    if (scene.activation.skip_asleep && world.in_dormant_lattice(world.floes()[joint.body_a])) continue;
    const btRigidBody& body_a = *world.floes()[joint.body_a].body;
    const btRigidBody& body_b = *world.floes()[joint.body_b].body;
    // asleep: the feedback is stale (docs/model/bullet.md) and the filter keeps its last value
    if (liveness(body_a) != Liveness::kAwake && liveness(body_b) != Liveness::kAwake && scene.activation.skip_asleep)
      continue;

    JointLoads loads = joint_loads(world, joint);
    if (tau > 0) {
      low_pass(fracture.filtered_joint_loads[i], loads, a);
      loads = fracture.filtered_joint_loads[i];
    }
    const JointCapacity own = joint_capacity(scene, joint);
    double ratio = 0;
    const FailureMode mode = failure_mode(loads, own, ratio);
    if (at_held_edge(world, joint)) {  // the clamp's load, not the ice's: counted, never broken
      held_edge_overloads += mode != FailureMode::kNone;
      continue;
    }
    const Eigen::Vector3d at = body_pose(body_a) * joint.midpoint_a;
    if (fracture.floe_margins.size() <= static_cast<std::size_t>(joint.floe))
      fracture.floe_margins.resize(joint.floe + 1);
    FloeFailureMargin& margin = fracture.floe_margins[joint.floe];
    margin.max_ratio = std::max(margin.max_ratio, ratio);
    margin.min_distance =
        std::min(margin.min_distance, distance_from_structure(scene, structure, at));
    if (mode == FailureMode::kNone) continue;

    BreakContext context = break_context(scene, world, joint.floe, at, structure, h);
    context.ratios = criterion_ratios(loads, own);
    const BreakMechanism mechanism = classify_break(context, scene.ice.thickness);
    const std::array<double, kFailureModes>& r = context.ratios;  // FailureMode order
    fracture.add(FractureEvent{
        time, joint.floe, joint.index, static_cast<int>(mode), ratio, at.x(), at.z(),
        static_cast<int>(mechanism), context.touching_structure ? 1 : 0, context.depth, context.distance,
        context.structure_force, context.press_down, context.press_toward, r[0], r[1], r[2], r[3], r[4]});
    failed.push_back(i);
  }
  for (std::size_t i : failed) break_joint(world, joints[i]);
  return held_edge_overloads;
}

}  // namespace icedem
