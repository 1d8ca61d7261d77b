// Static against kinetic friction: a contact that is not slipping holds up to the static
// coefficient, one that slips carries the kinetic coefficient (the pair's Coulomb coefficient,
// friction.ice_ice and friction.ice_structure).
//
// Why: one Coulomb coefficient cannot hold a load and then let it go. A floe stuck on the cone,
// or held against its neighbours in a jammed pack, carries up to mu_s times its normal force
// until it slips and the force drops to mu_k times it; the peaks of the load are such moments.
// Metrikin's Bullet-based managed-ice simulator keeps both coefficients for this reason.
//
// How: a contact sticks in a step when the relative tangential speed of its two points at the
// start of the step (the velocities the last step ended with) is below `stick_speed`; its
// coefficient in the step's solve is then mu_s, else mu_k. A contact that held stays held
// (the solve leaves it at rest relative to its partner) until the load needs more than mu_s
// N, it then slips and carries mu_k N until it comes to rest again: stick-slip, decided by the
// velocities alone, so a run resumed from a checkpoint decides as the uninterrupted one.
// The solve itself stays Coulomb's with one coefficient per contact (dem/contact/problem.hpp).
#pragma once

class btCollisionObject;
class btManifoldPoint;

namespace icedem {

struct StaticFriction {
  double ice_ice = 0;        // mu_s of ice on ice and on the mother ice; 0: none (the kinetic)
  double ice_structure = 0;  // mu_s of ice on the structure; 0: none
  double stick_speed = 1e-3;  // m/s, slip speed below which a contact sticks

  bool any() const { return ice_ice > 0 || ice_structure > 0; }
};

/// The relative tangential speed of a contact's two points, m/s, from the bodies' velocities now.
double slip_speed(const btCollisionObject& a, const btCollisionObject& b, const btManifoldPoint& point);

/// The friction coefficient of a contact in this step: its kinetic coefficient `kinetic`, or the
/// pair's static one if it sticks (slip speed below the stick speed) and that is larger.
double contact_friction(const StaticFriction& law, double kinetic, bool on_structure, double slip);

}  // namespace icedem
