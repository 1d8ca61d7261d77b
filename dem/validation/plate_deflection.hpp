// The plate-deflection case (seed paper Fig. 6): a floating square plate of elements under a
// central point load P. Reference: Hertz's infinite plate on a Winkler foundation,
// w0 / P = 1 / (8 sqrt(D rho_w g)) = 0.0889 mm/N for the paper's ice, times the finite-plate
// factor of docs/model/validation_targets.md §2 (free-edge circular plate of equal area;
// 1.04-1.06 for 2.7 m). The deflection is averaged over the second half of the run, after the
// plate has settled.
#pragma once

#include <vector>

#include "dem/validation/case.hpp"

namespace icedem {

class PlateDeflection : public ValidationCase {
 public:
  /// Loads the element(s) at the plate's centre: one for an odd count across, four for even.
  PlateDeflection(const Scene& scene, const State& state);
  void after_step(const Scene& scene, State& state) override;
  ValidationResult result(const Scene& scene) const override;

 private:
  std::vector<int> centre_;  // loaded bodies
  double y0_ = 0;            // m, their mean initial height
  double sum_ = 0;           // m, summed centre deflection over the measuring half
  long samples_ = 0;
};

/// Why the scene's plate case cannot give its reference, "" if it can: a load whose reference
/// deflection sinks the loaded elements below the water (beyond the plate's freeboard), where
/// the plate no longer floats as the linear theory assumes and the elements under the load are
/// thrown about in the first step.
std::string plate_load_warning(const Scene& scene);

}  // namespace icedem
