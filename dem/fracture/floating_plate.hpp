// The constants of a floating ice plate that every closed form of its bending uses: the flexural rigidity and
// the characteristic length (thin-plate theory on a Winkler foundation, the water).
#pragma once

#include <cmath>

namespace icedem {

/// D = E h^3 / (12 (1 - nu^2)), N m.
inline double flexural_rigidity(double thickness, double elastic_modulus, double poisson_ratio) {
  return elastic_modulus * std::pow(thickness, 3) / (12.0 * (1.0 - poisson_ratio * poisson_ratio));
}

/// l = (D / (rho_w g))^(1/4), m.
inline double characteristic_length(double thickness, double elastic_modulus, double poisson_ratio,
                                    double water_density, double gravity) {
  return std::pow(flexural_rigidity(thickness, elastic_modulus, poisson_ratio) / (water_density * gravity), 0.25);
}

}  // namespace icedem
