// Water velocity models: still water, uniform current, strip-wise cylinder potential flow
// around the structure (see flow_field.hpp for the formulas).
#include "dem/water/flow_field.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dem/core/errors.hpp"

namespace icedem {

Eigen::Vector3d StillWater::velocity(const Eigen::Vector3d& x) const {
  return Eigen::Vector3d::Zero();
}

UniformFlow::UniformFlow(const Eigen::Vector3d& u) : u_(u) {}

Eigen::Vector3d UniformFlow::velocity(const Eigen::Vector3d& x) const { return u_; }

ConePotentialFlow::ConePotentialFlow(std::vector<std::pair<double, double>> stations)
    : stations_(std::move(stations)) {
  if (stations_.size() < 2) {
    throw InputError("potential flow stations: got " + std::to_string(stations_.size()) +
                     " (y, radius) stations; expected at least 2");
  }
  for (std::size_t i = 0; i < stations_.size(); ++i) {
    const auto& [y, radius] = stations_[i];
    std::ostringstream where;
    where << "potential flow station " << i << " (y = " << y << " m, radius = " << radius << " m)";
    if (!std::isfinite(y) || !std::isfinite(radius) || radius < 0.0) {
      throw InputError(where.str() + ": expected finite values and radius >= 0");
    }
    if (i > 0 && !(y > stations_[i - 1].first)) {
      throw InputError(where.str() + ": expected y strictly above the previous station's " +
                       std::to_string(stations_[i - 1].first) + " m");
    }
  }
}

void ConePotentialFlow::set_structure(const Eigen::Vector3d& axis_point,
                                      const Eigen::Vector3d& velocity) {
  axis_point_ = axis_point;
  // the strip-wise model is 2D in (x, z): a heave of the structure does not move the water
  structure_velocity_ = Eigen::Vector3d(velocity.x(), 0.0, velocity.z());
}

double ConePotentialFlow::radius_at(double y) const {
  if (y < stations_.front().first || y > stations_.back().first) return 0.0;
  // first station strictly above y (or the last one), then linear interpolation
  auto upper = std::upper_bound(stations_.begin(), stations_.end(), y,
                                [](double value, const std::pair<double, double>& s) {
                                  return value < s.first;
                                });
  if (upper == stations_.end()) return stations_.back().second;
  const auto lower = upper - 1;
  const double t = (y - lower->first) / (upper->first - lower->first);
  return lower->second + t * (upper->second - lower->second);
}

Eigen::Vector3d ConePotentialFlow::velocity(const Eigen::Vector3d& x) const {
  const double a = radius_at(x.y());
  if (!(a > 0.0)) return Eigen::Vector3d::Zero();

  // horizontal offset from the axis
  const Eigen::Vector2d d(x.x() - axis_point_.x(), x.z() - axis_point_.z());
  const double r2 = d.squaredNorm();
  const Eigen::Vector2d v(structure_velocity_.x(), structure_velocity_.z());
  if (r2 < a * a) return structure_velocity_;  // inside the hull: water moves with it

  // tank-frame cylinder flow: w = (a^2/r^2) (2 (V . e_r) e_r - V)
  const Eigen::Vector2d e_r = d / std::sqrt(r2);
  const Eigen::Vector2d w = (a * a / r2) * (2.0 * v.dot(e_r) * e_r - v);
  return Eigen::Vector3d(w.x(), 0.0, w.y());
}

}  // namespace icedem
