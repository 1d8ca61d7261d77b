#include "dem/contact/crushing.hpp"

#include <cmath>

namespace icedem {

double crushing_pressure(const CrushingLaw& law, double area) {
  if (law.exponent == 0.0) return law.strength;
  return law.strength * std::pow(area / law.reference_area, law.exponent);
}

double crushing_force(const CrushingLaw& law, double area) {
  return area > 0.0 ? crushing_pressure(law, area) * area : 0.0;
}

}  // namespace icedem
