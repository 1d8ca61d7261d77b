#include "dem/validation/ralston.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/core/errors.hpp"

namespace icedem {
namespace {

constexpr double kPi = 3.14159265358979323846;

// complete elliptic integrals of modulus k = sin a, by their polynomial approximations in the
// complementary parameter m1 = 1 - k^2 (Abramowitz and Stegun 17.3.34 and 17.3.36; error below 3e-5)
double elliptic_k(double a) {
  const double m1 = 1.0 - std::sin(a) * std::sin(a);
  return 1.3862944 + 0.1119723 * m1 + 0.0725296 * m1 * m1 +
         std::log(1.0 / m1) * (0.5 + 0.1213478 * m1 + 0.0288729 * m1 * m1);
}
double elliptic_e(double a) {
  const double m1 = 1.0 - std::sin(a) * std::sin(a);
  return 1.0 + 0.4630151 * m1 + 0.1077812 * m1 * m1 + std::log(1.0 / m1) * (0.2452727 * m1 + 0.0412496 * m1 * m1);
}

}  // namespace

RalstonLoad ralston_cone_load(const ConeLoadInputs& in) {
  const double a = in.slope, mu = in.friction, h = in.thickness, D = in.waterline_diameter;
  if (!(a > 0 && a < kPi / 2))
    throw InputError(fmt::format("Ralston cone load: the slope {:.1f} deg is not between 0 and 90", a * 180 / kPi));
  const double g_r = (std::sin(a) + a / std::cos(a)) / (2 * mu * a * std::cos(a) + 0.5 * kPi * std::pow(std::sin(a), 2));
  const double lock = 1.0 - g_r * mu;
  if (lock <= 0)
    throw InputError(fmt::format("Ralston cone load: friction mu = {:.2f} on a {:.1f} deg slope locks the ice on it "
                                 "(1 - g mu = {:.3f}); the method does not apply",
                                 mu, a * 180 / kPi, lock));
  constexpr double Y = 2.711;  // Tresca's yield criterion
  // what resists the sheet's bending: its weight on an upward slope, the water under it on a downward one
  const double bending_density = in.downward ? in.water_density : in.ice_density;
  const double ride_density = in.downward ? in.water_density - in.ice_density : in.ice_density;
  RalstonLoad r{};
  r.weight_ratio = bending_density * in.gravity * D * D / (4 * in.flexural_strength * h);
  const double G = r.weight_ratio, x = 1.0 + 1.0 / std::sqrt(3 * G + 0.5 * Y);
  r.breaking = in.flexural_strength * h * h / 3 * std::tan(a) / lock *
               (G * (x - 1) * (x + 2) + (1 + Y * x * std::log(x)) / (x - 1));
  const double W = ride_density * in.gravity * h * (D * D - in.end_diameter * in.end_diameter) / (4 * std::cos(a));
  const double f = mu * elliptic_k(a) * std::cos(a) + std::sin(a);
  r.ride = W * (std::tan(a) + mu * (elliptic_e(a) - f * g_r * std::cos(a))) / lock;
  r.total = r.breaking + r.ride;
  return r;
}

}  // namespace icedem
