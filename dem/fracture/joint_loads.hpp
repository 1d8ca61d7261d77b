// Loads on the joint between two ice elements, and the paper's failure
// criteria (seed paper eq. 1-3).
//
// Bullet's joint feedback gives the force and torque the joint applied to
// element A, the torque about A's centre of mass. The failure criteria need the
// load at the joint, i.e. at the middle of the shared face, split in the joint
// frame: n from A's centre towards B's, v the floe's vertical, t = v x n along
// the joint line.
#pragma once

#include <array>

#include <Eigen/Core>

namespace icedem {

/// The six load components of one joint, acting on element A.
struct JointLoads {
  double axial;                 // N, along n: > 0 tension, < 0 compression
  double shear_in_plane;        // N, along t
  double shear_vertical;        // N, along v
  double bending_out_of_plane;  // N m, about t: plate bending (eq. 3)
  double bending_in_plane;      // N m, about v
  double torsion;               // N m, about n
};

/// Move the wrench on A (force at its centre of mass, torque about it; world
/// frame) to the joint midpoint and split it in the joint frame.
JointLoads decompose_joint_load(const Eigen::Vector3d& force_on_a, const Eigen::Vector3d& torque_on_a,
                                const Eigen::Vector3d& centre_of_a, const Eigen::Vector3d& midpoint,
                                const Eigen::Vector3d& axis_a_to_b, const Eigen::Vector3d& floe_up);

enum class FailureMode : int { kNone = -1, kCompression = 0, kShear = 1, kBending = 2, kTension = 3, kInPlaneBending = 4 };

/// Names of the failure modes, indexed by their integer value (HDF5 attribute).
const char* failure_mode_name(FailureMode mode);

/// The capacities of one joint, from the element size L_e, thickness T_e and
/// the ice strengths (eq. 1-3); tension and in-plane bending are optional.
struct JointCapacity {
  double compression;        // N, L_e T_e sigma_c (eq. 1)
  double shear;              // N, L_e T_e sigma_s (eq. 2)
  double bending;            // N m, L_e T_e^2 sigma_b / 6 (eq. 3)
  double tension;            // N, L_e T_e sigma_t; <= 0: criterion off (paper mode)
  double in_plane_bending;   // N m, T_e L_e^2 sigma_b / 6; <= 0: criterion off (paper mode)
};

JointCapacity paper_joint_capacity(double element_size, double thickness, double compressive_strength,
                                   double shear_strength, double bending_strength);

/// The capacities of a joint whose face is `ratio` times as long as the one `c` is for: every
/// capacity in proportion to the face's length, the in-plane bending to its square.
JointCapacity scaled(const JointCapacity& c, double ratio);

/// Number of failure criteria (FailureMode values 0 .. kFailureModes - 1).
constexpr int kFailureModes = 5;

/// Load / capacity of every criterion, indexed by FailureMode value; 0 for a
/// criterion that is off (capacity <= 0) or loaded the other way.
std::array<double, kFailureModes> criterion_ratios(const JointLoads& loads, const JointCapacity& capacity);

/// The criterion that fails with the largest load/capacity ratio (> 1), or
/// kNone. `ratio` receives that ratio (or the largest ratio below 1).
FailureMode failure_mode(const JointLoads& loads, const JointCapacity& capacity, double& ratio);

}  // namespace icedem
