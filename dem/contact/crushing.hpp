// The crushing contact law: ice that fails at its edge under a contact.
//
// Real ice does not stop a floe within a step: its edge crushes at the compressive
// strength over a contact area that grows with the penetration, so an impact lasts a
// finite time (docs/model/crushing.md derives what follows and gives the sources).
// The normal force of a contact whose nominal contact area is A at penetration delta is
//
//   F(delta) = p(A) A(delta),   p(A) = sigma_c (A / A_ref)^ex            (Daley's pressure-area)
//
// with sigma_c the ice's compressive strength (ice.compressive_strength), ex the
// pressure-area exponent (0: a constant crushing pressure, the default) and A_ref = h^2 the
// reference area that makes p independent of the unit of A at model scale.
//
// Crushing is not elastic: crushed ice is gone and does not push back. The overlap of two
// bodies in contact is what has been crushed, so the ice at the contact carries any force up
// to F(delta) without moving, and above it crushes further. Over a step h the contact's
// normal impulse is therefore bounded by what the present overlap carries,
//
//   0 <= r_N <= c = h F(delta),    u_N >= 0 where r_N < c           (a rigid contact below c)
//
// a bound on the normal row inside the solve (each contact's friction cone cut at r_N = c),
// not a penalty force outside it. The force is the law's at the step's start, as Bullet's
// integrator (symplectic Euler: positions after velocities, a leapfrog) needs it to be second
// order: a floe's impact on the cone then meets the energy balance of crushing to 1-2 % at
// the 0.02 s step where it is resolved (tests/physics/test_crushing_impact.cpp). Where the law
// is stiffer than the step resolves, the bound cannot push the floe back (it only resists
// its closing), so the contact cannot become unstable: the peak is then the rigid contact's,
// the floe's momentum over the step. A rigid contact is c = infinity.
#pragma once

namespace icedem {

struct CrushingLaw {
  double strength = 0;        // Pa, sigma_c (ice.compressive_strength)
  double exponent = 0;        // -, ex in p = sigma_c (A / A_ref)^ex (contact.pressure_area_exponent)
  double reference_area = 0;  // m^2, A_ref (the ice thickness squared)
};

/// The crushing pressure over a nominal contact area `area` (m^2), Pa.
double crushing_pressure(const CrushingLaw& law, double area);

/// The crushing force over a nominal contact area `area` (m^2), N: p(A) A (0 for A <= 0).
double crushing_force(const CrushingLaw& law, double area);

}  // namespace icedem
