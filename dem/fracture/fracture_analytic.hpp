// The edge load that breaks a floating floe in bending: the statics of the analytic
// fracture model (a rigid floe that splits when the vertical load on one edge reaches it,
// along the section of the largest moment), and of docs/model/breakage.md.
//
// A floe of length L (along the load's direction) and width b is a beam of flexural
// rigidity EI = b E h^3 / (12 (1 - nu^2)) on the water, an elastic (Winkler) foundation
// of stiffness k = rho_w g b per metre (Hetenyi's beam on an elastic foundation, the
// strip form of Kerr's floating plate):
//   EI w'''' + k w = 0 on 0 < s < L, free ends (no moment, no shear), the edge load P at s = 0.
// Its limits: a floe much shorter than its characteristic length tilts as a rigid body,
// M(s) = P s (1 - s/L)^2, largest 4 P L / 27 at s = L / 3; a much longer one bends as a
// semi-infinite beam, M(s) = (P / beta) e^(-beta s) sin(beta s), largest 0.3224 P / beta at
// s = pi / (4 beta), beta = (k / (4 EI))^(1/4). It breaks where M reaches the section's
// capacity sigma_b b h^2 / 6 (eq. 3 summed over a joint line across the floe).
#pragma once

#include <vector>

namespace icedem {

/// The bending moment per unit edge load along a floating beam, |M(s)| / P (m), at n + 1
/// equally spaced sections s_i = i L / n, from the beam equation above (solved exactly up
/// to the integration's round-off by superposing three initial-value solutions).
std::vector<double> floating_beam_moment_per_load(double length, double flexural_rigidity,
                                                  double foundation_stiffness, int n = 2000);

/// Where and at what vertical edge load a floe breaks.
struct EdgeBreak {
  double load;            // N, the edge load at which the largest moment reaches the capacity
  double crack_distance;  // m, from the loaded edge, the section of the largest moment
};

/// The breaking edge load of a floe of `length` x `width` x `thickness` (m) of ice with
/// modulus E (Pa), Poisson ratio nu, bending strength sigma_b (Pa), on water of density
/// rho_w (kg/m^3) under gravity g (m/s^2).
EdgeBreak edge_breaking_load(double length, double width, double thickness, double elastic_modulus,
                             double poisson_ratio, double bending_strength, double water_density, double gravity);

}  // namespace icedem
