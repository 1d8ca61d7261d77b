// The floating elastic plate under a central point load, in closed form: Hertz's infinite
// plate on a Winkler foundation, the finite free-edge plate's correction, and the elastic
// modulus a measured compliance implies. The plate-deflection case and the CFM calibration
// share them (docs/model/validation_targets.md §2).
#pragma once

#include "dem/input/scene.hpp"

namespace icedem {

/// Centre deflection of a free-edge floating plate of equal-area radius a, relative to the
/// infinite plate, against a / l_c (docs/model/validation_targets.md §2).
double finite_plate_factor(double a_over_lc);

/// The finite-plate factor of the scene's plate-deflection case (its plate's equal-area
/// radius over the characteristic length).
double plate_finite_factor(const Scene& scene);

/// Hertz's infinite floating plate: centre deflection per unit central load, m/N:
/// w0 / P = 1 / (8 sqrt(D rho_w g)).
double hertz_plate_compliance(const Scene& scene);

/// Elastic modulus inverted from a measured compliance w0/P (m/N) of a plate with the given
/// finite-plate factor: E = 3 (1 - nu^2) f^2 / (16 rho_w g h^3 (w0/P)^2).
double modulus_from_compliance(const Scene& scene, double compliance, double factor);

}  // namespace icedem
