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

#include "dem/contact/problem.hpp"
#include "dem/fracture/fracture_state.hpp"
#include "dem/fracture/joint_loads.hpp"
#include "dem/input/scene.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// The load on an intact joint in its last Bullet step (joint feedback on
/// element A, moved to the joint midpoint and split in the joint frame).
JointLoads joint_loads(const World& world, const IceJoint& joint);

/// The same for a wrench on element A given apart from the feedback (force at A's centre of
/// mass, torque about it; tank frame): a solve's answer before the step integrates.
JointLoads joint_loads(const World& world, const IceJoint& joint, const Eigen::Vector3d& force_on_a,
                       const Eigen::Vector3d& torque_on_a);

/// The capacities of `joint` (eqs. 1-3 for its face: a square's side unless it has its own).
JointCapacity joint_capacity(const Scene& scene, const IceJoint& joint);

/// The failure ratios (load over capacity, eqs. 1-3) the joints of an island's contact
/// problem reach with its joint rows' impulses `l` over the problem's step: the measure of
/// check_fracture, taken on a solve's answer before the step integrates (the contact solver
/// solves an island again, tighter, when a joint's is near 1: solver.breaking_ratio). A level
/// sheet's joints at its held edge, which do not break, are left out.
struct JointRatios {
  double largest = 0;       // -, the largest (0 without joints)
  double nearest = 0;       // -, the one nearest to 1 (0 without joints)
};
JointRatios joint_ratios(const Scene& scene, const World& world, const ContactProblem& problem,
                         const Eigen::VectorXd& l);

/// Check every intact joint of `world` with an awake element after a Bullet step of `h` seconds
/// that ended at `time`, the structure's reference point at `structure` (low-passing the loads
/// if fracture.load_filter_time > 0); break those that fail and add their events to `fracture`.
/// A level sheet's joints at its held edge (at_held_edge) do not break; returns how many of them
/// reached their capacity.
int check_fracture(const Scene& scene, World& world, double time, const Eigen::Vector3d& structure, double h,
                   FractureState& fracture);

}  // namespace icedem
