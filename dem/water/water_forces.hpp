// The hydrostatic and hydrodynamic wrench of the water on one rigid floe or ice element.
//
// Components, summed (docs/model/physics.md):
//   buoyancy       rho g V_sub, upward, at the centre of buoyancy (hydrostatics.hpp), so a
//                  heeled floe feels the right righting moment;
//   form drag      on every wetted face advancing into the water, -1/2 rho C_d A (v_r.n)^2 n,
//                  at the face centroid (docs/model/validation_targets.md §5: 1/2 rho C_d L d v^2
//                  for a floe moving edge-first);
//   skin friction  on every wetted face, -1/2 rho C_f A |v_t| v_t, v_t the tangential part
//                  of the relative velocity, at the face centroid;
//   damping        heave -c_h v_y and roll/pitch -c_rp (omega_x, 0, omega_z), a stand-in for
//                  the radiation damping of a floe (docs/model/validation_targets.md §1), scaled by
//                  the submerged fraction so a body out of the water is not damped.
// Gravity is not included (the physics engine applies it). The relative velocity is that
// of the body at the face centroid minus the water velocity there (flow_field.hpp). Each
// face is lumped at its centroid: a floe spinning about y feels no bottom skin friction
// (the bottom centroid does not move), only friction on its submerged edges.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dem/input/scene.hpp"
#include "dem/water/flow_field.hpp"
#include "dem/water/hydrostatics.hpp"

namespace icedem {

/// Water properties and hydrodynamic coefficients.
struct WaterParams {
  double water_density = 1000.0;  // kg/m^3, fresh water of the NMRI tank (seed paper)
  double gravity = 9.81;          // m/s^2
  // -, form drag C_d on wetted faces facing the relative flow: 1.0 for a bluff edge,
  // within the 0.5-1.0 range of docs/model/validation_targets.md §5 [U: an assumption]
  double drag_coefficient = 1.0;
  // -, skin friction C_f on wetted faces: laminar Blasius flat plate 1.328/sqrt(Re) = 0.0092
  // at Re = v L / nu = 0.07 * 0.3 / 1e-6 = 2.1e4 (docs/model/validation_targets.md §5)
  double skin_friction_coefficient = 0.0092;
  // -, fraction of critical damping in heave. An assumption [U]: the radiation damping of a
  // floe is large at its natural frequency (omega^2 a / g ~ 1.7, docs/model/validation_targets.md
  // section 1), so free decay looks close to critically damped; 0.5 is a middle value
  double heave_damping_ratio = 0.5;
  // -, fraction of critical damping in roll and pitch; same argument and assumption as heave
  double roll_pitch_damping_ratio = 0.5;
  // water.buoyancy = "linear", an ablation, not water: every upward-facing wetted face also
  // carries the water column above it, rho g (depth at its centroid) (its horizontal
  // projection), at its centroid. The support then grows with depth past full submergence, as
  // the Winkler foundation of a floating beam's formulas does (docs/model/breakage.md); the
  // exact buoyancy stops at the reserve buoyancy once the top floods
  bool linear_buoyancy = false;
};

/// The scene's water properties and hydrodynamic coefficients.
WaterParams water_params(const WaterSettings& water);

/// The state of a rigid body.
struct BodyMotion {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();          // body frame -> world; origin = COM
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();       // m/s, of the COM (pose origin)
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();      // rad/s, world
};

/// Linear damping coefficients of one body, computed once from its geometry at rest.
struct DampingCoefficients {
  double heave = 0.0;             // N s/m
  double roll_pitch = 0.0;        // N m s/rad
  double displaced_volume = 0.0;  // m^3, at equilibrium (floating freely)
};

/// Returns the damping coefficients of a body of `mass` (kg) and horizontal moment of
/// inertia `horizontal_inertia` (kg m^2, about a horizontal axis through the COM), from its
/// waterplane when floating freely and upright:
///   heave      c_h  = 2 zeta_h sqrt(m rho g A_wp),
///   roll/pitch c_rp = 2 zeta_rp sqrt(I_h rho g I_wp),
/// with I_wp the smaller principal second moment of the waterplane area about its centroid
/// (rho g I_wp is the restoring stiffness of a thin floe: GM ~ BM = I_wp / V). The displaced
/// volume is m / rho, capped at the body's volume; a body denser than water (no waterplane)
/// takes the section through its centre of mass.
DampingCoefficients damping_coefficients(const ConvexPolyhedron& body, double mass,
                                         double horizontal_inertia, const WaterParams& p);

/// A force and a torque.
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, world
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  // N m, world, about the COM
};

/// Returns the water's wrench on `body` in state `motion` (water plane y = 0), with the
/// water velocity taken from `flow`. Allocation-free after the first call on a thread.
Wrench water_wrench(const ConvexPolyhedron& body, const BodyMotion& motion, const FlowField& flow,
                    const WaterParams& p, const DampingCoefficients& d);

}  // namespace icedem
