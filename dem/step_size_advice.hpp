// Advice on the Bullet step h = time.dt / time.substeps, from the stress suite
// (scripts/stress, scenarios/stress): two limits a scenario can cross while
// every key is legal. `icedem check` prints the warnings and `icedem run` puts
// them in the summary.
#pragma once

#include <string>
#include <vector>

#include "dem/scene.hpp"

namespace icedem {

/// omega h above which floating floes gain energy: omega = sqrt(rho_w g / (rho_i h_ice))
/// is the heave and pitch frequency of a floe (no added mass). Measured on the short
/// tow: omega h 0.54 (dt 0.03 s) clean, 0.72 (0.04 s) floes spin at 3.6 rad/s,
/// 0.90 (0.05 s) blow-up at 14.7 s.
constexpr double kMaxHeaveStep = 0.6;

/// Structure travel per Bullet step, as a fraction of the ice thickness, above
/// which ice is pushed into the hull: at 0.42 (0.7 m/s, dt 0.02 s) ice ended
/// 80 mm inside and the mean load was 25 % low; at 0.11 within 5 mm.
constexpr double kMaxTravelPerStep = 0.12;

/// Warnings for a scene whose Bullet step crosses either limit, each naming the
/// keys and the number of substeps that would keep it within; empty if none.
std::vector<std::string> step_size_warnings(const Scene& scene);

}  // namespace icedem
