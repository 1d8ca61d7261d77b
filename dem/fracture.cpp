#include "dem/fracture.hpp"

#include "dem/bullet_eigen.hpp"

namespace icedem {

JointLoads joint_loads(const World& world, const IceJoint& joint) {
  const Eigen::Isometry3d pose_a = body_pose(*world.floes()[joint.body_a].body);
  return decompose_joint_load(to_eigen(joint.feedback->m_appliedForceBodyA),
                              to_eigen(joint.feedback->m_appliedTorqueBodyA), pose_a.translation(),
                              pose_a * joint.midpoint_a, pose_a.linear() * joint.axis_a,
                              pose_a.linear() * Eigen::Vector3d::UnitY());
}

void check_fracture(const Scene& scene, State& state) {
  World& world = *state.world;
  if (world.joints().empty()) return;
  const JointCapacity capacity =
      paper_joint_capacity(scene.fracture.element_size, scene.ice.thickness, scene.ice.compressive_strength,
                           scene.ice.shear_strength, scene.ice.bending_strength);
  for (IceJoint& joint : world.joints()) {
    if (!joint.constraint) continue;  // broken already
    const btRigidBody& a = *world.floes()[joint.body_a].body;
    const btRigidBody& b = *world.floes()[joint.body_b].body;
    if (!a.isActive() && !b.isActive()) continue;  // asleep: the feedback is stale (bullet-notes.md)

    const JointLoads loads = joint_loads(world, joint);
    double ratio = 0;
    const FailureMode mode = failure_mode(loads, capacity, ratio);
    if (mode == FailureMode::kNone) continue;

    state.fracture_events.push_back(FractureEvent{state.time, joint.floe, joint.index, static_cast<int>(mode), ratio});
    ++state.breaks_by_mode[static_cast<int>(mode)];
    world.break_joint(joint);
  }
}

}  // namespace icedem
