// The fracture stage: after each Bullet step, the load on every intact joint of
// a breakable floe (Bullet's joint feedback, moved to the joint midpoint and
// split in the joint frame, dem/fracture/joint_loads.hpp) is checked against the paper's
// criteria (eq. 1-3); a joint that fails is removed and the break recorded.
//
// Per-step joint loads from the PGS solver are noisy and depend on the
// iteration count; fracture.joint_iterations and fracture.load_filter_time are
// the two remedies (docs/model/physics.md, "Breakable ice": measured effect on breaks and cost).
#pragma once

#include <Eigen/Core>

#include "dem/fracture/fracture_state.hpp"
#include "dem/fracture/joint_loads.hpp"
#include "dem/input/scene.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// The load on an intact joint in its last Bullet step (joint feedback on
/// element A, moved to the joint midpoint and split in the joint frame).
JointLoads joint_loads(const World& world, const IceJoint& joint);

/// Check every intact joint of `world` with an awake element after a Bullet step of `h` seconds
/// that ended at `time`, the structure's reference point at `structure` (low-passing the loads
/// if fracture.load_filter_time > 0); break those that fail and add their events to `fracture`.
void check_fracture(const Scene& scene, World& world, double time, const Eigen::Vector3d& structure, double h,
                    FractureState& fracture);

}  // namespace icedem
