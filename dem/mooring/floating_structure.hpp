// A moored structure as a floating rigid body (structure.motion = "moored"): what it is, made once from
// the scene. Its motion is dem/mooring/structure_motion.hpp's.
//
// Body: the mass (structure.mass; 0: what floats at the still-water line with its mooring's pull), the
// centre of gravity on the axis (by default the default hull's as a uniform solid from keel to deck)
// and the moments of inertia about it (0: the hull as that solid, scaled to the mass).
// Water: the hull's exact heave buoyancy (its displaced volume at each heave offset, upright:
// dem/water/hull_hydrostatics.hpp) and the linear roll and pitch restoring rho g V GM; constant added
// mass and inertia (keys, or the estimate below); linear damping at a set fraction of each motion's
// critical damping.
// The added-mass estimate (a few tens of per cent, for want of a radiation solver's numbers; the
// keys take those): surge and sway, strips of circular sections, each adding the water it displaces
// (2-D added-mass coefficient 1, DNV-RP-C205, Appendix D), so the displaced water's mass; heave, the
// waterline disc's (4/3) rho a^3, half the open-water disc's (8/3) rho a^3 (one side wetted, as the
// floes' added mass: dem/water/added_mass.hpp); roll and pitch, the strips' added mass moving about
// the centre of gravity, int rho pi r^2 (y - y_G)^2 dy, plus the disc's (8/45) rho a^5; none in yaw
// (a round hull moves no water turning about its axis).
#pragma once

#include <memory>
#include <string>

#include <Eigen/Dense>

#include "dem/input/scene.hpp"
#include "dem/mooring/mooring.hpp"

namespace icedem {

/// The hull's profile as a uniform solid of revolution (keel to deck) of unit density: volume,
/// centroid height and moments of inertia per unit mass about the centroid (about a horizontal axis,
/// and about the axis of revolution).
struct HullSolid {
  double volume = 0;          // m^3
  double centroid_y = 0;      // m
  double tilt_gyration2 = 0;  // m^2, I / m about a horizontal axis through the centroid
  double axial_gyration2 = 0; // m^2, I / m about the axis
};
HullSolid hull_solid(const std::vector<ProfileStation>& profile);

/// The estimate of the water's added mass (surge, heave, sway: kg) and added inertia (roll, yaw,
/// pitch about a centre of gravity at `gravity_centre_y`: kg m^2) of the hull floating upright.
struct AddedMass6 {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
};
AddedMass6 hull_added_mass(const std::vector<ProfileStation>& profile, double water_density, double gravity_centre_y);

struct FloatingStructure {
  double mass = 0;                                          // kg
  double gravity_centre_y = 0;                              // m, above the waterline, on the axis
  double solid_centroid_y = 0;  // m, the hull's as a uniform solid (what structure.gravity_centre_y defaults to for the default hull)
  Eigen::Vector3d inertia = Eigen::Vector3d::Zero();        // kg m^2 about the centre of gravity (x, y, z)
  Eigen::Vector3d added_mass = Eigen::Vector3d::Zero();     // kg
  Eigen::Vector3d added_inertia = Eigen::Vector3d::Zero();  // kg m^2
  Eigen::Vector3d damping = Eigen::Vector3d::Zero();        // N s/m, along x, y, z
  Eigen::Vector3d angular_damping = Eigen::Vector3d::Zero();// N m s/rad, about x, y, z
  double displaced_volume = 0;                              // m^3, at rest, upright
  double tilt_stiffness = 0;                                // N m/rad, rho g V GM (roll and pitch)
  double heave_stiffness = 0;                               // N/m, rho g A_wp at rest
  double rest_heave = 0;      // m, the reference point's height at rest (weight, buoyancy and mooring balanced)
  Eigen::Vector3d start = Eigen::Vector3d::Zero();  // m, the reference point at rest at t = 0
  std::shared_ptr<const Mooring> mooring;

  /// The largest natural frequency of the body's six motions, rad/s (the step's stability bound).
  double highest_frequency = 0;
  /// The natural frequencies in surge, heave, sway and roll, yaw, pitch, rad/s (0 where unrestrained).
  Eigen::Vector3d linear_frequency = Eigen::Vector3d::Zero(), angular_frequency = Eigen::Vector3d::Zero();
};

/// The moored structure `scene` describes. Throws std::invalid_argument when it cannot float upright
/// (GM not positive; mass beyond what the hull can float) or a mooring line has no solution.
FloatingStructure make_floating_structure(const Scene& scene);

/// The moored structure of `scene`, refused with an InputError naming the scenario and the key when it
/// cannot be (make_floating_structure's refusals), when an anchor lies beyond the tank's side, or when
/// the Bullet step is too long for its stiffest motion: w_n h above 1, where the semi-implicit step,
/// stable to 2, errs by (w_n h)^2 / 24 in period.
FloatingStructure checked_floating_structure(const Scene& scene);

/// What `icedem check` says of a moored structure: its mass, centre of gravity, inertia, added mass,
/// stiffnesses, damping and natural periods, a few lines.
std::string describe(const FloatingStructure& body);

/// The upward force of the water on the hull (its buoyancy) when its reference point is `heave` m above
/// the still-water line, upright, N.
double hull_buoyancy(const Scene& scene, double heave);

}  // namespace icedem
