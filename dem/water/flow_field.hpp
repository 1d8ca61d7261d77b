// Water velocity models in the tank frame (x surge, y up, z sway; docs/model/architecture.md, "Conventions").
//
// The hydrodynamic forces on a floe (water_forces.hpp) use the velocity of the floe
// relative to the local water. A FlowField says what the water does at a point:
//   StillWater        : nothing moves.
//   UniformFlow       : a uniform current.
//   ConePotentialFlow : the disturbance of the towed structure, seen strip-wise as a circular
//                       cylinder of the local radius (docs/model/validation_targets.md §5; a
//                       slender-body approximation, poor for a 45-degree cone, but it puts the
//                       2U shoulder speed-up and the bow stagnation in the right places).
// The coupled (OpenFOAM) model lives in coupling/ and implements the same interface.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace icedem {

/// A water velocity field in the tank frame.
class FlowField {
 public:
  virtual ~FlowField() = default;

  /// Returns the water velocity, m/s, tank frame, at the point x (m, tank frame).
  virtual Eigen::Vector3d velocity(const Eigen::Vector3d& x) const = 0;

  /// Tells the field where the structure is: a point on its vertical axis (m, tank frame)
  /// and its velocity (m/s, tank frame). Fields that ignore the structure ignore this.
  virtual void set_structure(const Eigen::Vector3d& axis_point, const Eigen::Vector3d& velocity) {}
};

/// Water at rest everywhere.
class StillWater : public FlowField {
 public:
  Eigen::Vector3d velocity(const Eigen::Vector3d& x) const override;
};

/// A uniform current.
class UniformFlow : public FlowField {
 public:
  /// `u`: the current, m/s, tank frame.
  explicit UniformFlow(const Eigen::Vector3d& u);
  Eigen::Vector3d velocity(const Eigen::Vector3d& x) const override;

 private:
  Eigen::Vector3d u_;  // m/s, tank frame
};

/// Potential flow around a vertical body of revolution (axis along y through the structure's
/// axis point) moving horizontally with velocity V through otherwise still water.
///
/// At height y the body is taken as a circular cylinder of the local radius a(y), linear
/// between stations and 0 (no disturbance) above the top and below the bottom station. In
/// the structure frame the far field is U = -V and the 2D cylinder flow holds,
/// u_r = U (1 - a^2/r^2) cos(th), u_th = -U (1 + a^2/r^2) sin(th); in the tank frame this is
///   w = (a^2/r^2) (2 (V . e_r) e_r - V),   r >= a,
/// which vanishes far away, equals -V at the shoulders (relative speed 2|V|) and +V at the
/// bow, and has zero normal velocity relative to the hull at r = a. Inside the hull (r < a)
/// the water moves with it: w = V. Only the horizontal part of V is used and the vertical
/// water velocity is 0.
class ConePotentialFlow : public FlowField {
 public:
  /// `stations`: (y, radius) pairs, m, tank frame heights relative to the still-water line,
  /// strictly increasing in y, radius >= 0, at least 2 of them. Throws InputError otherwise.
  explicit ConePotentialFlow(std::vector<std::pair<double, double>> stations);

  Eigen::Vector3d velocity(const Eigen::Vector3d& x) const override;
  void set_structure(const Eigen::Vector3d& axis_point, const Eigen::Vector3d& velocity) override;

  /// Returns the local radius a(y), m (0 outside the stations' range).
  double radius_at(double y) const;

 private:
  std::vector<std::pair<double, double>> stations_;         // (y m, radius m), sorted by y
  Eigen::Vector3d axis_point_ = Eigen::Vector3d::Zero();    // m, tank frame
  Eigen::Vector3d structure_velocity_ = Eigen::Vector3d::Zero();  // m/s, horizontal part of V
};

}  // namespace icedem
