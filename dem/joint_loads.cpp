#include "dem/joint_loads.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace icedem {

JointLoads decompose_joint_load(const Eigen::Vector3d& force_on_a, const Eigen::Vector3d& torque_on_a,
                                const Eigen::Vector3d& centre_of_a, const Eigen::Vector3d& midpoint,
                                const Eigen::Vector3d& axis_a_to_b, const Eigen::Vector3d& floe_up) {
  // the same wrench about the joint midpoint: M_p = M_c + (c - p) x F
  const Eigen::Vector3d moment = torque_on_a + (centre_of_a - midpoint).cross(force_on_a);
  const Eigen::Vector3d n = axis_a_to_b.normalized();
  const Eigen::Vector3d v = (floe_up - floe_up.dot(n) * n).normalized();
  const Eigen::Vector3d t = v.cross(n);
  return JointLoads{force_on_a.dot(n), force_on_a.dot(t), force_on_a.dot(v),
                    moment.dot(t),     moment.dot(v),     moment.dot(n)};
}

const char* failure_mode_name(FailureMode mode) {
  switch (mode) {
    case FailureMode::kCompression: return "compression";
    case FailureMode::kShear: return "shear";
    case FailureMode::kBending: return "bending";
    case FailureMode::kTension: return "tension";
    case FailureMode::kInPlaneBending: return "in-plane bending";
    case FailureMode::kNone: break;
  }
  return "none";
}

JointCapacity paper_joint_capacity(double element_size, double thickness, double compressive_strength,
                                   double shear_strength, double bending_strength) {
  const double area = element_size * thickness;  // the joint's cross-section L_e T_e
  return JointCapacity{area * compressive_strength, area * shear_strength,
                       element_size * thickness * thickness * bending_strength / 6.0, 0.0, 0.0};
}

FailureMode failure_mode(const JointLoads& l, const JointCapacity& c, double& ratio) {
  FailureMode worst = FailureMode::kNone;
  ratio = 0.0;
  auto consider = [&](double load, double capacity, FailureMode mode) {
    if (capacity <= 0) return;  // criterion off
    const double r = load / capacity;
    if (r > ratio) {
      ratio = r;
      if (r > 1.0) worst = mode;
    }
  };
  consider(-l.axial, c.compression, FailureMode::kCompression);                                   // eq. 1
  consider(std::hypot(l.shear_in_plane, l.shear_vertical), c.shear, FailureMode::kShear);          // eq. 2
  consider(std::abs(l.bending_out_of_plane), c.bending, FailureMode::kBending);                    // eq. 3
  consider(l.axial, c.tension, FailureMode::kTension);
  consider(std::abs(l.bending_in_plane), c.in_plane_bending, FailureMode::kInPlaneBending);
  if (ratio <= 1.0) worst = FailureMode::kNone;
  return worst;
}

}  // namespace icedem
