// The other design method for level ice failing in bending on a cone: Ralston's plastic-limit
// analysis ("Ice force design considerations for conical offshore structures", POAC 1977), as
// IEC 61400-3 gives it for offshore wind turbines and the IceFloe module of OpenFAST codes it.
// Beside ISO 19906's (dem/validation/iso19906.hpp) it is the second reference a reviewer asks a
// level-ice load on a cone to be checked against.
//
// The horizontal load is a breaking part and a ride part, H = H_B + H_R:
//   H_B = sigma_f h^2 / 3 tan a / (1 - g mu) (G (x - 1)(x + 2) + (1 + Y x ln x) / (x - 1))
//   H_R = W (tan a + mu (E(a) - f g cos a)) / (1 - g mu)
// with Y = 2.711 (Tresca's yield criterion for the sheet), G = dr_b g D^2 / (4 sigma_f h) the
// weight of the ice over its strength, x = 1 + 1 / sqrt(3 G + Y / 2),
//   g = (sin a + a / cos a) / (2 mu a cos a + pi/2 sin^2 a),
//   W = dr g t_r (D^2 - D_T^2) / (4 cos a),   f = mu K(a) cos a + sin a,
// K and E the complete elliptic integrals of the first and second kind of modulus sin a
// (Abramowitz and Stegun's polynomial approximations, 17.3.34 and 17.3.36). D is the waterline
// diameter, D_T the diameter where the slope ends, a the slope from the horizontal, mu the
// ice-structure friction, t_r the thickness of the ice that rides: h. For a downward-breaking
// cone the ice is pushed down against the water: dr_b = rho_w (the water under the sheet
// resists its bending, as ice's weight does for an upward cone: IceFloe takes rho_i, which
// changes the paper's cone's load by about 2 %) and dr = rho_w - rho_i in the ride, as in the
// ISO method's downward-breaking form.
//
// For the paper's cone (45 degrees, D 1.228 m, D_T 0.342 m at the keel) and ice these give 171,
// 214 and 267 N at mu 0.1, 0.2 and 0.3 (docs/model/validation_targets.md, 4a).
#pragma once

#include "dem/validation/iso19906.hpp"

namespace icedem {

/// Ralston's terms and total, N.
struct RalstonLoad {
  double weight_ratio;  // -, G
  double breaking;      // N, H_B
  double ride;          // N, H_R
  double total;         // N, H
};

/// The load by the equations above, from the same inputs as ISO's (`in.rubble` unused: the
/// method has no pile). Throws InputError when 1 - g mu <= 0 (the friction too high for the
/// slope: the ice would lock on it) or the slope is not between 0 and 90 degrees.
RalstonLoad ralston_cone_load(const ConeLoadInputs& in);

}  // namespace icedem
