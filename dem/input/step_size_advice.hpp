// Advice on the Bullet step h = time.dt / time.substeps, from the stress suite
// (scripts/stress, scenarios/stress) and the lattices' step study: limits a
// scenario can cross while every key is legal. `icedem check` prints the
// warnings and `icedem run` puts them in the summary.
#pragma once

#include <string>
#include <vector>

#include "dem/input/scene.hpp"

namespace icedem {

/// omega h above which the explicit water forces cost accuracy: omega =
/// sqrt(rho_w g / (rho_i h_ice)) is the heave and pitch frequency of a floe (no
/// added mass). Semi-implicit Euler with the damping ratio 0.5 is stable for omega h
/// below 1.24 (eigenvalues of the heave update). Measured on the short tow
/// (scenarios/stress/large_dt.toml at other steps, after the island fix): mean surge
/// load 14.4 N at omega h 0.36, 13.7 N (-5 %) at 0.54, 11.7 N (-19 %) at 0.72,
/// 8.1 N (-44 %) at 0.90 with floes spinning at 1.8 rad/s, a blow-up at 1.79.
constexpr double kMaxHeaveStep = 0.6;

/// Structure travel per Bullet step, as a fraction of the ice thickness, above
/// which ice is pushed into the hull: at 0.42 (0.7 m/s, dt 0.02 s) ice ended
/// 80 mm inside and the mean load was 25 % low; at 0.11 within 5 mm.
constexpr double kMaxTravelPerStep = 0.12;

/// The Bullet step above which lattices of elements smaller than kConvergedElementSize
/// break with the step: over 10 seeds of the paper's 0.6 m floes of 0.15 m squares, the mean
/// of maxima at 0.01 s was 38 % above that at 0.02 s (+6 to +78 %), and the breaks in the
/// rubble that 0.01 s has were missing at 0.02 s; from 0.01 s to 0.005 s, and with a fourfold tighter solve at 0.01 s,
/// nothing moved resolvably (docs/model/step_convergence_dt_half.md). The 0.20 m squares'
/// findings at 0.02 s were not seen to move at 0.01 s (max +10 %, -22 to +54 %).
constexpr double kMaxLatticeStep = 0.01;
constexpr double kConvergedElementSize = 0.2;

/// Warnings for a scene whose Bullet step crosses any of these limits, each naming the
/// keys and the number of substeps that would keep it within; empty if none.
std::vector<std::string> step_size_warnings(const Scene& scene);

}  // namespace icedem
