// Physical constants and numerical tolerances, each with its unit and reason.
// Scenario-dependent values (densities, friction, ...) live in the scenario keys,
// not here; this file holds what is not meant to be changed per run.
#pragma once

namespace icedem {

/// Bullet collision margin on ice and structure shapes, m. Bullet's default
/// (0.04 m) is larger than the 0.033 m ice thickness and would ruin contact
/// normals and freeboard (docs/model/bullet.md); a millimetre keeps GJK robust.
constexpr double kDefaultCollisionMargin = 0.001;

/// Speed above which a body is considered blown up, m/s. Nothing in a 0.07 m/s
/// tow test moves faster than ~1 m/s; 50 m/s is unambiguous divergence.
constexpr double kBlowUpSpeed = 50.0;

/// Distance from the origin beyond which a body is considered lost, m. The tank
/// is 35 m long and 1.8 m deep.
constexpr double kBlowUpDistance = 1000.0;  // m outside the tank

/// Angular speed above which a floe or element is rocking unstably, rad/s: a
/// 0.15 m element turning this fast moves its edge at over 1 m/s, 15 times the
/// tow speed, while stable runs stay below 2 rad/s (docs/model/physics.md, "Breakable ice").
/// A warning, not a blow-up: the run goes on.
constexpr double kRockingAngularSpeed = 15.0;

/// Standard gravity, m/s^2, for the impulse merit's floor (dem/contact/merit.hpp): a
/// contact's effective mass times it is the force below which its error is no error
/// that matters. A scale, not the run's gravity (water.gravity).
constexpr double kMeritGravity = 9.81;

constexpr double kPi = 3.14159265358979323846;

}  // namespace icedem
