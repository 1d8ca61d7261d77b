// The floating elastic plate in closed form (dem/validation/plate_theory.hpp).
#include "dem/validation/plate_theory.hpp"

#include <array>
#include <cmath>

#include "dem/core/constants.hpp"

namespace icedem {

double finite_plate_factor(double a_over_lc) {
  // docs/model/validation_targets.md §2: exact free-edge circular plate, w0 / w0_inf against a / l_c
  static const std::array<std::array<double, 2>, 10> table{{{1, 2.70}, {1.5, 1.46}, {2, 1.165}, {2.5, 1.106},
                                                            {3, 1.088}, {3.5, 1.064}, {4, 1.038}, {5, 1.008},
                                                            {6, 1.001}, {8, 1.000}}};
  if (a_over_lc <= table.front()[0]) return table.front()[1];
  if (a_over_lc >= table.back()[0]) return 1.0;
  for (std::size_t i = 1; i < table.size(); ++i) {
    if (a_over_lc <= table[i][0]) {
      const double s = (a_over_lc - table[i - 1][0]) / (table[i][0] - table[i - 1][0]);
      return table[i - 1][1] + s * (table[i][1] - table[i - 1][1]);
    }
  }
  return 1.0;
}

double plate_finite_factor(const Scene& s) {
  // the plate's equal-area radius over the characteristic length
  return finite_plate_factor(s.validation.plate_size / std::sqrt(kPi) / s.fracture.characteristic_length);
}

double hertz_plate_compliance(const Scene& s) {
  return 1.0 / (8.0 * std::sqrt(s.ice.flexural_rigidity * s.water.density * s.water.gravity));
}

double modulus_from_compliance(const Scene& s, double compliance, double factor) {
  const double h = s.ice.thickness, nu = s.ice.poisson_ratio;
  return 3 * (1 - nu * nu) * factor * factor / (16 * s.water.density * s.water.gravity * h * h * h * compliance * compliance);
}

}  // namespace icedem
