// The bending of a wedge of floating ice loaded at its apex: the statics of level ice broken by a
// structure, where the sheet's first radial cracks have cut wedges from its edge (docs/model/breakage.md,
// "The edge and the wedges of level ice").
//
// A narrow wedge of opening angle theta is a beam whose width grows from its apex, b(x) = 2 x tan(theta/2),
// on the water, an elastic (Winkler) foundation of stiffness rho_w g per unit area (Nevel's narrow infinite
// wedge, 1961, in the beam idealisation):
//   d^2/dx^2 ( D b(x) w'' ) + rho_w g b(x) w = p(x),   D = E h^3 / (12 (1 - nu^2)),
// the apex free, the wedge long enough that its far end does not matter (w -> 0). The stress at a section,
// 6 M / (b h^2) = 6 D w'' / h^2, does not depend on the width; under a point load at the apex it is largest
// there, 3 P / (h^2 tan(theta/2)), so the load is taken as spread in uniform pressure over the wedge's
// first length a (the contact's patch). Then the wedge breaks, across, at the section of the largest
// moment, at
//   P_f = sigma_b h^2 tan(theta/2) / (3 S(a / l)),   l = (D / (rho_w g))^(1/4) the characteristic length,
// with S and the crack's distance x* / l functions of a / l alone (S -> 1 as a -> 0; the angle cancels).
// With a constant width the same equation is Hetenyi's semi-infinite beam: M_max = 0.3224 P / beta at
// x = pi / (4 beta), beta = (rho_w g b / (4 D b))^(1/4) (the project's fracture_analytic.hpp).
//
// Solved by cubic Hermite beam elements (the width and the foundation linear along each, integrated
// exactly), the wedge cut at 12 l, where the deflection has decayed by e^-8.
#pragma once

namespace icedem {

/// The wedge's breaking in units of its characteristic length: S (the largest stress is
/// 3 S P / (h^2 tan(theta/2))) and the distance of its section from the apex over l.
struct WedgeBending {
  double stress_factor = 0;    // S
  double crack_distance = 0;   // x* / l
};

/// S and x* / l for a load spread in uniform pressure over the first `patch` (a / l > 0) of the wedge;
/// `elements` per characteristic length. Throws std::invalid_argument for a patch not in (0, 6].
WedgeBending wedge_bending(double patch, int elements = 400);

/// The same beam with a constant width, loaded by a point load at its free end: the largest |M| / P in units of
/// 1 / beta (Hetenyi: 0.3224) and its distance from the end in units of 1 / beta (pi / 4): the solver's check.
WedgeBending constant_width_bending(int elements = 400);

/// P_f = sigma_b h^2 tan(theta/2) / (3 S), N: the load that breaks a wedge of opening angle `opening_angle` (rad)
/// whose S is `w`'s, of ice of thickness h (m) and bending strength sigma_b (Pa).
double wedge_load(double opening_angle, const WedgeBending& w, double thickness, double bending_strength);

/// Where and at what load a wedge breaks.
struct WedgeBreak {
  double load;            // N, spread over the patch
  double crack_distance;  // m, from the apex
};

/// The breaking load of a wedge of opening angle `opening_angle` (rad, in (0, pi)) of ice of thickness h (m),
/// modulus E (Pa), Poisson ratio nu, bending strength sigma_b (Pa) on water of density rho_w (kg/m^3) under
/// gravity g (m/s^2), loaded over its first `patch_length` m.
WedgeBreak wedge_breaking_load(double opening_angle, double patch_length, double thickness, double elastic_modulus,
                               double poisson_ratio, double bending_strength, double water_density, double gravity);

}  // namespace icedem
