// The water's added mass of a floe: the water a floe must set moving when it heaves, rolls or
// pitches, which a thin plate has in large measure (a 0.6 m floe's heave added mass is about 4.7
// times its mass). Frequency-independent, impulsive-limit coefficients of a disc of equal area
// (potential flow, the classical results), for any outline:
//   heave       m_a = (4/3) rho_w a^3   (one wetted side: half the (8/3) rho a^3 of a disc in open water)
//   roll, pitch I_a = (8/45) rho_w a^5  (the same half)
// with a = sqrt(A / pi). A square plate's (DNV-RP-C205, C_A = 0.579) is within 6 % of the disc's.
// Surge and sway of a thin floe add little and none is added. A lattice's elements share their floe's
// heave added mass by area (the intact plate moves the water as one), and each gets the pitch inertia
// of its share spread over its own area.
//
// Bullet applies it (dem/world/world.cpp) by scaling the body's response to vertical forces and to
// torques about the horizontal axes (btRigidBody::setLinearFactor, setAngularFactor): the body then
// accelerates as one of mass m + m_a under every force on it, gravity and buoyancy included, while
// those forces stay what they are, so its equilibrium does not move and its heave period becomes
// 2 pi sqrt((m + m_a) / (rho_w g A)). Implicit in the step, it costs no stability: the explicit
// alternative, a force -m_a a, is unstable at m_a / m near 5.
#pragma once

namespace icedem {

struct AddedMass {
  double heave = 0;       // kg
  double roll_pitch = 0;  // kg m^2, about a horizontal axis through the centre
};

/// The added mass of a thin floating plate of `area` (m^2) in water of `water_density` (kg/m^3).
AddedMass plate_added_mass(double area, double water_density);

/// A lattice element's part of its floe's: the heave added mass in proportion to its area, and the
/// pitch inertia of that part spread over the element's own square of side sqrt(element_area).
AddedMass element_added_mass(const AddedMass& floe, double floe_area, double element_area);

/// The factors Bullet scales a body's vertical velocity changes and its roll and pitch changes by,
/// for a body of `mass` (kg) and roll-pitch moment of inertia `inertia` (kg m^2) with `added`:
/// m / (m + m_a) and I / (I + I_a).
struct MotionFactors {
  double vertical = 1, roll_pitch = 1;
};
MotionFactors added_mass_factors(double mass, double inertia, const AddedMass& added);

}  // namespace icedem
