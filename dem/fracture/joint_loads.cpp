#include "dem/fracture/joint_loads.hpp"

#include <algorithm>
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

JointCapacity scaled(const JointCapacity& c, double ratio) {
  return JointCapacity{c.compression * ratio, c.shear * ratio, c.bending * ratio, c.tension * ratio,
                       c.in_plane_bending * ratio * ratio};
}

std::array<double, kFailureModes> criterion_ratios(const JointLoads& l, const JointCapacity& c) {
  auto r = [](double load, double capacity) { return capacity > 0 ? std::max(load, 0.0) / capacity : 0.0; };
  std::array<double, kFailureModes> ratios{};
  ratios[static_cast<int>(FailureMode::kCompression)] = r(-l.axial, c.compression);                           // eq. 1
  ratios[static_cast<int>(FailureMode::kShear)] = r(std::hypot(l.shear_in_plane, l.shear_vertical), c.shear);  // eq. 2
  ratios[static_cast<int>(FailureMode::kBending)] = r(std::abs(l.bending_out_of_plane), c.bending);            // eq. 3
  ratios[static_cast<int>(FailureMode::kTension)] = r(l.axial, c.tension);
  ratios[static_cast<int>(FailureMode::kInPlaneBending)] = r(std::abs(l.bending_in_plane), c.in_plane_bending);
  return ratios;
}

FailureMode failure_mode(const JointLoads& l, const JointCapacity& c, double& ratio) {
  const std::array<double, kFailureModes> ratios = criterion_ratios(l, c);
  // the first criterion with the largest ratio, in FailureMode order
  const int worst = static_cast<int>(std::max_element(ratios.begin(), ratios.end()) - ratios.begin());
  ratio = ratios[worst];
  return ratio > 1.0 ? static_cast<FailureMode>(worst) : FailureMode::kNone;
}

}  // namespace icedem
