// Validation cases run by `icedem run` (scenarios/validation/): they set up their
// loads, measure during the run, and add a `validation` block to the summary
// JSON: {metric, value, reference, rel_error, tolerance, passed} (DESIGN.md).
//
// plate_deflection (seed paper Fig. 6): a floating square plate of elements
// under a central point load P. Reference: Hertz's infinite plate on a Winkler
// foundation, w0 / P = 1 / (8 sqrt(D rho_w g)) = 0.0889 mm/N for the paper's
// ice, times the finite-plate factor of physics-targets.md 2 (free-edge circular
// plate of equal area; 1.04-1.06 for 2.7 m).
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "dem/scene.hpp"
#include "dem/state.hpp"

namespace icedem {

/// Centre deflection of a free-edge floating plate of equal-area radius a,
/// relative to the infinite plate, against a / l_c (physics-targets.md 2).
double finite_plate_factor(double a_over_lc);

/// Hertz's infinite floating plate: centre deflection per unit central load, m/N.
double hertz_plate_compliance(const Scene& scene);

/// Elastic modulus inverted from a measured compliance w0/P (m/N) of a plate
/// with the given finite-plate factor: E = 3 (1 - nu^2) f^2 / (16 rho_w g h^3 (w0/P)^2).
double modulus_from_compliance(const Scene& scene, double compliance, double factor);

class Validation {
 public:
  /// Set up the case's loads on the initial state (nothing for "none").
  Validation(const Scene& scene, State& state);

  /// Measure after a step.
  void after_step(const Scene& scene, const State& state);

  /// The summary block, or null for "none".
  nlohmann::json result(const Scene& scene) const;

 private:
  std::vector<int> centre_;  // loaded bodies
  double y0_ = 0;            // m, their mean initial height
  double sum_ = 0;           // m s / dt: summed centre deflection over the measuring half
  long samples_ = 0;
};

}  // namespace icedem
