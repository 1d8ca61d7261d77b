// The moored structure's motion: its state, and one Bullet step of it.
//
// The structure stays a kinematic body in Bullet, moved by this integrator, and the ice's load on it
// (the load cell's impulses of the Bullet step just taken) drives it in the next: a staggered
// coupling of two rigid systems. The contact solve sees the structure moving at its velocity of the
// step, not recoiling within it; momentum is kept (the ice's impulse reaches the structure one step
// later, whole). The recoil a floe's impact would give within a step is m_floe / (M + M_a) of the
// floe's velocity change: 2 % for a paper 0.6 m floe (10 kg) on the cone (237 kg and as much added),
// which is the error the lag makes in that floe's rebound. A floe heavier than a tenth of the
// structure would want the structure inside the contact solve.
//
// Equations of motion about the centre of gravity, tank axes, with the added mass and inertia
// constant and diagonal (dem/mooring/floating_structure.hpp):
//   (M + M_a) dv/dt = F_ice + F_buoyancy - M g + F_mooring - B (v - v_carriage)
//   (I + I_a) dw/dt = M_ice + M_restoring + M_mooring - B_rot w
// The damping acts on the motion about the carriage's: a radiation damping, of oscillations; the hull's
// steady resistance in still water is not modelled (nor is it for the towed cone, whose load cell reads
// the ice's load alone, as a tank subtracts its calm-water run).
// integrated by the semi-implicit Euler step Bullet uses for the floes (the velocity first, the
// damping implicitly, then the position with the new velocity): stable for w_n h < 2 on each
// natural frequency w_n, which `icedem check` holds below 1 (dem/input/setting_warnings.cpp).
// Gyroscopic terms are left out (the structure turns slowly: |w| below 0.1 rad/s in the study).
#pragma once

#include <type_traits>
#include <vector>

#include <Eigen/Dense>

#include "dem/input/scene.hpp"
#include "dem/mooring/floating_structure.hpp"

namespace icedem {

/// What changes of a moored structure (a checkpoint keeps it with the State's values).
struct StructureMotionState {
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();          // rad, rotation vector (body to tank)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // m/s, of the centre of gravity
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // rad/s, tank frame
  Eigen::Vector3d ice_impulse = Eigen::Vector3d::Zero();       // N s, of the last Bullet step, on the structure
  Eigen::Vector3d ice_angular_impulse = Eigen::Vector3d::Zero();  // N m s, about the reference point then
};

template <typename M, typename Visit>  // M: StructureMotionState or const StructureMotionState
std::enable_if_t<std::is_same_v<std::remove_const_t<M>, StructureMotionState>> visit_fields(M& m, Visit&& visit) {
  visit("rotation", m.rotation);
  visit("velocity", m.velocity);
  visit("angular_velocity", m.angular_velocity);
  visit("ice_impulse", m.ice_impulse);
  visit("ice_angular_impulse", m.ice_angular_impulse);
}

/// The body's orientation as a rotation matrix.
Eigen::Matrix3d rotation_matrix(const StructureMotionState& m);

/// The mooring's load on the structure as it stands at `time` (the reference point at `reference`).
MooringLoad mooring_load_at(const Scene& scene, const FloatingStructure& body, const Eigen::Vector3d& reference,
                            const StructureMotionState& m, double time);

/// One step of `h` s of the structure whose reference point is at `reference` (moved in place),
/// driven by the ice impulses stored in `m` (the step before's), the forces taken at the step's start,
/// when the carriage has moved `carriage` m. Any external force `extra` (N, at the centre of gravity) is
/// added: the validations' steady pull. (The mooring's load on the pose it reaches: mooring_load_at.)
void advance_structure(const Scene& scene, const FloatingStructure& body, double h, double carriage,
                       Eigen::Vector3d& reference, StructureMotionState& m,
                       const Eigen::Vector3d& extra = Eigen::Vector3d::Zero());

}  // namespace icedem
