#include "dem/water/added_mass.hpp"

#include <cmath>

namespace icedem {

AddedMass plate_added_mass(double area, double water_density) {
  const double a = std::sqrt(area / M_PI);  // the disc of equal area
  return AddedMass{4.0 / 3.0 * water_density * a * a * a, 8.0 / 45.0 * water_density * std::pow(a, 5)};
}

AddedMass element_added_mass(const AddedMass& floe, double floe_area, double element_area) {
  const double heave = floe.heave * element_area / floe_area;
  return AddedMass{heave, heave * element_area / 12.0};  // a square's m s^2 / 12
}

MotionFactors added_mass_factors(double mass, double inertia, const AddedMass& added) {
  return MotionFactors{mass / (mass + added.heave), inertia / (inertia + added.roll_pitch)};
}

}  // namespace icedem
