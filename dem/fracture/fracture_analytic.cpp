#include "dem/fracture/fracture_analytic.hpp"

#include <array>
#include <cmath>

#include <Eigen/Dense>

namespace icedem {

namespace {

using BeamState = std::array<double, 4>;  // w, w', w'', w'''

// w'''' = -(k / EI) w, one classical Runge-Kutta step of h
BeamState rk4(const BeamState& y, double c, double h) {
  auto f = [c](const BeamState& u) { return BeamState{u[1], u[2], u[3], -c * u[0]}; };
  auto add = [](const BeamState& u, const BeamState& d, double s) {
    return BeamState{u[0] + s * d[0], u[1] + s * d[1], u[2] + s * d[2], u[3] + s * d[3]};
  };
  const BeamState k1 = f(y), k2 = f(add(y, k1, h / 2)), k3 = f(add(y, k2, h / 2)), k4 = f(add(y, k3, h));
  BeamState out;
  for (int i = 0; i < 4; ++i) out[i] = y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  return out;
}

// the solution from y over n steps: the state at every section, s_i = i length / n
std::vector<BeamState> integrate(BeamState y, double c, double length, int n) {
  std::vector<BeamState> path{y};
  const double h = length / n;
  for (int i = 0; i < n; ++i) path.push_back(y = rk4(y, c, h));
  return path;
}

}  // namespace

std::vector<double> floating_beam_moment_per_load(double length, double flexural_rigidity,
                                                  double foundation_stiffness, int n) {
  const double c = foundation_stiffness / flexural_rigidity;
  // At s = 0: no moment (w'' = 0) and the unit load as the shear (EI w''' = 1); w and w'
  // unknown. The equation is linear, so the solution is the one with w = w' = 0 plus a
  // and b times those starting from w = 1 and from w' = 1; a and b make the far end free.
  const std::vector<BeamState> p = integrate({0, 0, 0, 1.0 / flexural_rigidity}, c, length, n);
  const std::vector<BeamState> wa = integrate({1, 0, 0, 0}, c, length, n);
  const std::vector<BeamState> wb = integrate({0, 1, 0, 0}, c, length, n);
  Eigen::Matrix2d m;
  m << wa.back()[2], wb.back()[2], wa.back()[3], wb.back()[3];
  const Eigen::Vector2d ab = m.fullPivLu().solve(Eigen::Vector2d(-p.back()[2], -p.back()[3]));
  std::vector<double> moment(n + 1);
  for (int i = 0; i <= n; ++i)
    moment[i] = std::abs(flexural_rigidity * (p[i][2] + ab[0] * wa[i][2] + ab[1] * wb[i][2]));
  return moment;
}

EdgeBreak edge_breaking_load(double length, double width, double thickness, double elastic_modulus,
                             double poisson_ratio, double bending_strength, double water_density, double gravity) {
  const double ei = width * elastic_modulus * std::pow(thickness, 3) / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
  const double k = water_density * gravity * width;
  const int n = 2000;
  const std::vector<double> m = floating_beam_moment_per_load(length, ei, k, n);
  int at = 0;
  for (int i = 1; i <= n; ++i)
    if (m[i] > m[at]) at = i;
  const double capacity = bending_strength * width * thickness * thickness / 6.0;  // N m
  return EdgeBreak{capacity / m[at], at * length / n};
}

}  // namespace icedem
