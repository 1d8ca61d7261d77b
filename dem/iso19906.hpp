// The design standard's analytic load of level ice failing in bending on a sloping
// structure: ISO 19906 (A.8.2.4.4.3), the method of Croasdale and Cammaert ("An improved
// method for the calculation of ice loads on sloping structures", Hydrotechnical
// Construction 28(3), 1994). A designer checks any simulated load against it.
//
// The horizontal load is the sum of named terms, amplified because the sheet must also
// carry the breaking load over its crack width:
//   H = (H_B + H_R + H_T) / (1 - H_B / (sigma_f w h)),  w = D + pi^2 L_c / 4,
//   xi   = (sin a + mu cos a) / (cos a - mu sin a)                    slope and friction
//   L_c  = (E h^3 / (12 rho_w g (1 - nu^2)))^(1/4)                   characteristic length
//   H_B  = 0.68 xi sigma_f (rho_w g h^5 / E)^(1/4) w                   breaking the sheet
//   H_R  = D h_r h dr g (sin a + mu cos a) / (sin a (cos a - mu sin a))  pushing the broken
//          ice along the slope over a height h_r (no rubble pile: its terms H_P and H_L are 0)
//   H_T  = 1.5 D h^2 dr g cos a / (sin a - mu cos a)                   turning the blocks
//          where the slope ends
// with a the slope from the horizontal, mu the ice-structure friction, D the waterline
// diameter, and dr the density that drives the ride: rho_i for an upward-breaking slope
// (the ice is lifted), rho_w - rho_i for a downward-breaking one (the ice is pushed under
// against its buoyancy: its buoyancy in place of its weight, as the method is applied to
// downward-breaking cones; the standard's own wording on this was not at hand).
//
// For the paper's cone (Table 2: 45 degrees, downward-breaking, D 1.228 m, 0.443 m deep)
// and ice (Table 3) these give 132, 164 and 205 N at mu 0.1, 0.2 and 0.3 with h_r the cone's
// full depth (an upper bound), of which breaking alone 108, 134 and 168 N: the load of
// *level* ice, an upper reference for managed floes (docs/model/validation_targets.md, 4a).
// Against more than 50 events at the Confederation Bridge the method over-predicted by a
// factor of about 1.6 (Croasdale et al. 2016, OTC-27385-MS).
#pragma once

#include "dem/scene.hpp"

namespace icedem {

/// What the method takes from a scenario, SI units.
struct ConeLoadInputs {
  double waterline_diameter;  // m, D
  double slope;               // rad, a, from the horizontal
  bool downward;              // the slope pushes the ice down (radius shrinking with depth)
  double ride_height;         // m, h_r: how far (vertically) the broken ice travels along the slope
  double thickness;           // m, h
  double flexural_strength;   // Pa, sigma_f
  double elastic_modulus;     // Pa, E
  double poisson_ratio;       // -, nu
  double ice_density;         // kg/m^3
  double water_density;       // kg/m^3
  double gravity;             // m/s^2
  double friction;            // -, ice on the structure, mu
};

/// The named terms and the total, N (and the lengths they use, m).
struct ConeLoad {
  double characteristic_length;  // m, L_c
  double crack_width;            // m, w = D + pi^2 L_c / 4
  double slope_factor;           // -, xi
  double breaking;               // N, H_B
  double ride;                   // N, H_R (the ice pushed along the slope, no rubble pile)
  double turning;                // N, H_T
  double total;                  // N, H
  double breaking_only;          // N, H_B / (1 - H_B / (sigma_f w h)): the sheet's failure alone
};

/// The load by the equations above. Throws InputError when the friction is too high for
/// the slope (cos a <= mu sin a, or sin a <= mu cos a: the ice would lock on the slope and
/// the method does not apply).
ConeLoad iso19906_cone_load(const ConeLoadInputs& in);

/// The inputs for a scenario's structure and ice: D from the waterline radius; a and h_r
/// from the profile segment below (downward) or above (upward) the waterline, h_r the
/// segment's full height (an upper bound on how far the broken ice rides).
ConeLoadInputs cone_load_inputs(const Scene& scene);

}  // namespace icedem
