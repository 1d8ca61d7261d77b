// The design standard's analytic load of level ice failing in bending on a sloping
// structure: ISO 19906 (A.8.2.4.4.3), the method of Croasdale and Cammaert ("An improved
// method for the calculation of ice loads on sloping structures", Hydrotechnical
// Construction 28(3), 1994). A designer checks any simulated load against it.
//
// The horizontal load is the sum of named terms, amplified because the sheet must also
// carry the breaking load over its crack width:
//   H = (H_B + H_P + H_R + H_L + H_T) / (1 - H_B / (sigma_f w h)),  w = D + pi^2 L_c / 4,
//   xi   = (sin a + mu cos a) / (cos a - mu sin a)                    slope and friction
//   L_c  = (E h^3 / (12 rho_w g (1 - nu^2)))^(1/4)                   characteristic length
//   H_B  = 0.68 xi sigma_f (rho_w g h^5 / E)^(1/4) w                   breaking the sheet
//   H_P  = D h_R^2 mu_i dr g (1 - e) k^2 / (2 tan t)                   pushing the sheet
//          through the rubble pile
//   H_R  = D P / (cos a - mu sin a)                                    pushing the broken ice
//          along the slope, under the pile, to the height h_R, with
//     P  = 1/2 mu_i (mu_i + mu) dr g (1 - e) h_R^2 sin a (cot t - cot a) k
//        + 1/2 (mu_i + mu) dr g (1 - e) h_R^2 cos a cot a k
//        + h_R h dr g (sin a + mu cos a) / sin a
//   H_L  = xi D h_R k (1/2 h_R dr g (1 - e) (cot t - cot a + tan phi k) + c)  lifting the
//          pile's wedge on the slope
//   H_T  = 1.5 D h^2 dr g cos a / (sin a - mu cos a)                   turning the blocks
//          where the slope ends
// with a the slope from the horizontal, mu the ice-structure friction, D the waterline
// diameter, and dr the density that drives the ride: rho_i for an upward-breaking slope
// (the ice is lifted), rho_w - rho_i for a downward-breaking one (the ice is pushed under
// against its buoyancy: its buoyancy in place of its weight, as the method is applied to
// downward-breaking cones; the standard's own wording on this was not at hand). The rubble
// pile has the height h_R (from the waterline), porosity e, the angle t of its face, the
// internal friction angle phi and cohesion c, and ice-ice friction mu_i; k = 1 - tan t / tan a.
// Without a pile (h_R = 0, the default) H_P and H_L vanish and only H_R's last term stays,
// with h_R the height the ice rides: the slope's full height, an upper bound.
//
// For the paper's cone (Table 2: 45 degrees, downward-breaking, D 1.228 m, 0.443 m deep)
// and ice (Table 3) these give 132, 164 and 205 N at mu 0.1, 0.2 and 0.3 with h_r the cone's
// full depth (an upper bound), of which breaking alone 108, 134 and 168 N: the load of
// *level* ice, an upper reference for managed floes (docs/model/validation_targets.md, 4a).
// Against more than 50 events at the Confederation Bridge the method over-predicted by a
// factor of about 1.6 (Croasdale et al. 2016, OTC-27385-MS).
#pragma once

#include "dem/input/scene.hpp"

namespace icedem {

/// A rubble pile against the slope (ISO 19906's h_R, e, theta, phi, c). Not in a scenario:
/// the managed floes of the paper clear the cone, so the default is no pile.
struct RubblePile {
  double height = 0;          // m, h_R, from the waterline; 0: no pile
  double porosity = 0;        // -, e
  double angle = 0;           // rad, theta, the pile's face from the horizontal (0 < theta <= a)
  double friction_angle = 0;  // rad, phi, the rubble's internal friction
  double cohesion = 0;        // Pa, c
};

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
  double ice_friction;        // -, ice on ice, mu_i (the rubble terms only)
  RubblePile rubble;          // with a pile, the ice rides to its top: ride_height is unused
  double end_diameter = 0;    // m, the slope's diameter where the ride ends (Ralston's D_T, dem/validation/ralston.hpp)
};

/// The named terms and the total, N (and the lengths they use, m).
struct ConeLoad {
  double characteristic_length;  // m, L_c
  double crack_width;            // m, w = D + pi^2 L_c / 4
  double slope_factor;           // -, xi
  double ride_height;            // m, h_R: the pile's height, or without a pile the given ride height
  double breaking;               // N, H_B
  double pile_push;              // N, H_P (0 without a pile)
  double ride;                   // N, H_R
  double pile_lift;              // N, H_L (0 without a pile)
  double turning;                // N, H_T
  double total;                  // N, H
  double breaking_only;          // N, H_B / (1 - H_B / (sigma_f w h)): the sheet's failure alone
};

/// The load by the equations above. Throws InputError when the friction is too high for
/// the slope (cos a <= mu sin a, or sin a <= mu cos a: the ice would lock on the slope and
/// the method does not apply), or when a pile's values are out of their ranges.
ConeLoad iso19906_cone_load(const ConeLoadInputs& in);

/// The inputs for a scenario's structure and ice: D from the waterline radius; a and h_r
/// from the profile segment below (downward) or above (upward) the waterline, h_r the
/// segment's full height (an upper bound on how far the broken ice rides).
ConeLoadInputs cone_load_inputs(const Scene& scene);

}  // namespace icedem
