// The Scene: the immutable, validated, SI input of one run.
//
// Built once from the scenario file (dem/input/scenario.hpp) and never changed while
// stepping; everything that changes lives in the State (dem/step/state.hpp). Field
// meanings and defaults are declared in dem/input/scenario_keys.cpp.
#pragma once

#include <algorithm>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dem/contact/solver_settings.hpp"

namespace icedem {

/// One station of the structure's hull profile.
struct ProfileStation {
  double y;       // m, height above the still-water line (negative below)
  double radius;  // m
};

struct TimeSettings {
  double dt;        // s, output and control step
  double duration;  // s, simulated time
  int substeps;     // Bullet steps per dt
};

// towed at a prescribed speed (the paper's), or floating and held by a mooring (dem/mooring/)
enum class StructureMotion { kTowed, kMoored };
struct StructureSettings {
  StructureMotion motion;
  double speed;                         // m/s, surge, prescribed (moored: the carriage's, which the mooring follows)
  double start_x;                       // m, axis position at t = 0
  double start_z;                       // m
  std::vector<ProfileStation> profile;  // keel to deck, y increasing
  int segments;                         // polygon sides per station
  double collision_margin;              // m, Bullet's margin on the hull's pieces (grows them by it)
  // structure.motion = "moored" (dem/mooring/floating_structure.hpp); 0 or negative where derived from the hull
  double mass;                            // kg; 0: the water the hull displaces at its waterline
  double gravity_centre_y;                // m, on the axis above the waterline
  Eigen::Vector3d inertia;                // kg m^2 about the centre of gravity (roll x, yaw y, pitch z); 0: the solid's
  Eigen::Vector3d added_mass;             // kg (surge x, heave y, sway z); negative: the estimate
  Eigen::Vector3d added_inertia;          // kg m^2 (roll, yaw, pitch); negative: the estimate
  Eigen::Vector3d damping_ratio;          // -, of critical, in surge, heave and sway
  Eigen::Vector3d angular_damping_ratio;  // -, in roll, yaw and pitch
};

// what holds a moored structure (dem/mooring/mooring.hpp)
enum class MooringModel { kLinear, kCatenary };
struct MooringSettings {
  MooringModel model;
  double attachment_y;                // m, linear: height of the attachment point on the axis
  Eigen::Vector3d stiffness;          // N/m, linear, along x, y, z
  Eigen::Vector3d angular_stiffness;  // N m/rad, linear, about x, y, z
  int lines;                          // catenary: lines, spread evenly
  double first_line_angle;            // rad, catenary: the first line's direction from +x towards +z
  double fairlead_radius;             // m, from the axis
  double fairlead_y;                  // m, above the waterline
  double anchor_radius;               // m, from the axis, on the seabed
  double line_length;                 // m, unstretched
  double line_weight;                 // N/m, submerged
  double line_stiffness;              // N, EA
  double seabed_friction;             // -
};

struct ChannelSettings {
  double start_x;    // m, floes in x >= start_x
  double length;     // m
  double width;      // m, centred on z = 0
  bool end_wall;     // mother ice at x = start_x + length
  double edge_friction_factor;  // -, the mother ice's friction against floes over friction.ice_ice
  double tank_width; // m
  double tank_depth; // m, water depth
};

// what covers the channel: a field of floes, or one continuous sheet (dem/fracture/level_ice.hpp)
enum class IceCover { kFloes, kLevel };
struct IceSettings {
  IceCover cover;
  double floe_size;             // m, side of square floes
  double thickness;             // m
  double concentration;         // -, area fraction
  double density;               // kg/m^3
  double elastic_modulus;       // Pa
  double bending_strength;      // Pa
  double compressive_strength;  // Pa
  double shear_strength;        // Pa
  double poisson_ratio;         // -
  bool contact_crushing;        // a contact's normal force limited to the crushing force
  // derived once by make_scene, not keys:
  double draft = 0;              // m, floating draft h rho_i / rho_w (Archimedes, a flat floe)
  double flexural_rigidity = 0;  // N m, D = E h^3 / (12 (1 - nu^2)), thin-plate theory
};

/// Largest normal force of one contact with crushing on: the compressive strength
/// over a patch as wide as the ice is thick (ice.contact_crushing), N.
inline double crushing_force(const IceSettings& ice) {
  return ice.compressive_strength * ice.thickness * ice.thickness;
}

struct LayoutSettings {
  std::string file;  // absolute path of a floe file, or "" to generate
  double max_yaw;    // rad
  int sweeps;        // Monte-Carlo sweeps
  double min_gap;    // m
  double size_spread;  // -, generated floes' sides uniform in ice.floe_size (1 +- size_spread)
  int layers;        // generated floe layers stacked at t = 0 (1: one floating layer)
};

// How the ice's contacts bear load (dem/contact/crushing.hpp)
enum class ContactModel { kRigid, kCrushing };
// which contacts of ice crush with ContactModel::kCrushing: those with the structure, those with the structure and
// the held level sheet (ice.cover = "level", fracture.mode = "analytic"), or every one
enum class CrushingContacts { kStructure, kStructureAndSheet, kAll };
struct ContactSettings {
  ContactModel model;
  double pressure_area_exponent;  // -, ex in p = sigma_c (A / h^2)^ex
  CrushingContacts crushing_contacts;
};

// Coulomb coefficients: kinetic, and static for contacts that stick (dem/world/static_friction.hpp)
struct FrictionSettings {
  double ice_ice;        // -, also floe against mother ice
  double ice_structure;  // -
  double ice_ice_static;        // -, 0: none (ice_ice throughout)
  double ice_structure_static;  // -, 0: none
  double stick_speed;           // m/s, slip speed below which a contact sticks
};

struct WaterSettings {
  double density;                    // kg/m^3
  double gravity;                    // m/s^2
  double drag_coefficient;           // -
  double skin_friction_coefficient;  // -
  double heave_damping_ratio;        // -
  double roll_pitch_damping_ratio;   // -
  bool added_mass;                   // the water's added mass in heave, roll and pitch (dem/water/added_mass.hpp)
  bool linear_buoyancy;              // water.buoyancy = "linear": an ablation (dem/water/water_forces.hpp)
};

enum class FlowModel { kStill, kUniform, kPotential, kCoupled };
struct FlowSettings {
  FlowModel model;
  Eigen::Vector3d velocity;  // m/s, uniform current
};

enum class CouplingMode { kField, kProbe };
/// flow.model = "coupled": the OpenFOAM potential-flow case (coupling/, foam_case/).
struct CouplingSettings {
  CouplingMode mode;
  std::string mesh;       // "coarse" | "medium" | "fine"
  std::string cache_dir;  // absolute; solved cases by hash of their inputs
  double domain_length;   // m, along x, centred on the structure axis
  double grid_spacing;    // m, of the sampled velocity grid
  double grid_depth;      // m, the grid spans y from -grid_depth to the still-water line
  int exchange_steps;          // probe mode: steps between exchanges
  double timeout;              // s, probe mode: longest wait for the partner
  std::string exchange_dir;    // probe mode: absolute, or "" for a temporary directory
  bool spawn_partner;          // probe mode: start coupling/foam_partner.py ourselves
};

// off: rigid floes; on / auto: floes of breakable elements (all, or those at least l_c);
// analytic: rigid floes that split when the structure's load reaches the breaking edge load
// of a floating beam (dem/fracture/fracture_split.hpp)
enum class FractureMode { kOff, kOn, kAuto, kAnalytic };
// the ice elements' shape (dem/fracture/outline_lattice.hpp): squares (the paper's), or hexagons
enum class ElementShape { kSquare, kHexagon };
// where the element tiling is anchored on an outline (dem/fracture/outline_lattice.hpp): at its
// lower corner, or shifted to cut the fewest small parts
enum class Tiling { kCorner, kFitted };
struct FractureSettings {
  FractureMode mode;
  double element_size;  // m: a square's side, or the distance between neighbouring hexagons' centres
  ElementShape element_shape;
  Tiling tiling = Tiling::kCorner;
  double lattice_angle;  // rad, the element grid's turn from a floe's principal axes (yaw)
  double cfm;           // -, Bullet units
  double erp;           // -
  bool elastic_joints;  // joint rows are springs of the ice's modulus (fracture.joint_stiffness = "elastic")
  double stiffness_scale;  // -, factor on the elastic rows' stiffness
  double strength_scale;   // -, factor on every joint's bending capacity (eq. 3)
  double characteristic_length;  // m, l_c = (D / (rho_w g))^(1/4) of the ice ("auto")
  int joint_iterations;          // PGS iterations of the joints; 0: solver.iterations
  double load_filter_time;       // s, low-pass time constant of joint loads; 0: raw
  double lattice_radius;         // m, breakable floes are lattices only this near the structure; 0: always
};

enum class IslandMode { kContact, kBullet };
struct ActivationSettings {
  bool sleeping;             // bodies at rest may sleep
  IslandMode islands;        // how sleeping islands are formed
  bool skip_asleep;          // water forces and joint checks on awake bodies only
  double linear_threshold;   // m/s
  double angular_threshold;  // rad/s
  double time;               // s below thresholds before sleeping
  bool unreached_out_of_world;  // floes nothing reached stay out of Bullet's world (dem/world/unreached_floes.hpp)
  bool freeze_outside_region;  // resting floes outside the region become fixed obstacles
  double region_ahead;         // m ahead of the structure axis
  double region_behind;        // m behind it
  double leave_behind;         // m behind the structure axis past which rigid floes leave the run; 0: never
};

struct OutputSettings {
  double snapshot_interval;  // s, 0 = no snapshots
  double checkpoint_interval;  // s, simulated, between checkpoints (dem/output/checkpoint.hpp); 0 = none
  double stop_grace;           // s, wall: how long a signalled run may go on to its next checkpoint
};

struct StatsSettings {
  double window_start_travel;  // m beyond first contact
  double window_end_travel;    // m beyond first contact, 0 = end of run
  double lowpass_hz;           // Hz, 0 = unfiltered
  bool include_squeeze;        // keep the steps of a squeeze against the end wall (dem/input/structure_path.hpp)
};

enum class ValidationKind { kNone, kPlateDeflection, kCantilever, kWideCantilever };
/// Where the wide cantilever's load points: down (the plate bends) or along the plate towards
/// its clamped edge (in-plane compression)
enum class PlateLoad { kDown, kAlong };
struct ValidationSettings {
  ValidationKind kind;
  double plate_size;  // m
  double load;        // N, downward at the plate centre
  double tolerance;   // -, relative
  int beam_elements;  // cantilever: elements along the beam
  double beam_length;  // m, wide cantilever: clamped edge to loaded edge (x)
  double beam_width;   // m, wide cantilever: across (z)
  double load_rate;   // N/s, cantilever tip load growth
  double tip_speed;   // m/s, floating cantilever pushed down at the tip; 0: load ramp in air
  PlateLoad plate_load;  // wide cantilever: bending (down) or in-plane compression (along)
};

/// Everything one run needs, validated and in SI units.
struct Scene {
  std::string source_path;    // scenario file as given
  std::string resolved_text;  // every key with its resolved value, as TOML
  std::uint64_t seed;
  TimeSettings time;
  SolverSettings solver;
  StructureSettings structure;
  MooringSettings mooring;
  ChannelSettings channel;
  IceSettings ice;
  LayoutSettings layout;
  ContactSettings contact;
  FrictionSettings friction;
  WaterSettings water;
  FlowSettings flow;
  CouplingSettings coupling;
  FractureSettings fracture;
  ActivationSettings activation;
  OutputSettings output;
  StatsSettings stats;
  ValidationSettings validation;
};

/// Time steps of a run (each of scene.time.dt).
inline long step_count(const Scene& s) { return std::lround(s.time.duration / s.time.dt); }

/// The largest generated floe's side, m: ice.floe_size, or its (1 + layout.size_spread) with a spread.
inline double largest_generated_floe(const Scene& s) { return s.ice.floe_size * (1 + s.layout.size_spread); }

/// Whether generated (square) floes are made of breakable elements: fracture.mode "on", or
/// "auto" with the largest of them at least the characteristic length.
inline bool generated_floes_breakable(const Scene& s) {
  return s.fracture.mode == FractureMode::kOn ||
         (s.fracture.mode == FractureMode::kAuto && largest_generated_floe(s) >= s.fracture.characteristic_length);
}

/// Whether rigid floes split under the structure's load (fracture.mode "analytic").
inline bool floes_split(const Scene& s) { return s.fracture.mode == FractureMode::kAnalytic; }

/// PGS sweeps the element joints get per step: Bullet solves a constraint
/// max(its override, solver.iterations) times (fracture.joint_iterations).
inline int joint_sweeps(const Scene& s) {
  return s.fracture.joint_iterations > s.solver.iterations ? s.fracture.joint_iterations : s.solver.iterations;
}

/// Level ice cut by closed forms needs a sloping hull: its radius must change across the ice's thickness by at
/// least this fraction of the thickness, or it is a wall that crushes the ice and does not bend it.
constexpr double kSteepestSheetFlare = 0.05;

/// Level ice cut by closed forms (dem/fracture/analytic_sheet.hpp), not a lattice.
inline bool analytic_level_ice(const Scene& s) {
  return s.ice.cover == IceCover::kLevel && s.fracture.mode == FractureMode::kAnalytic;
}

/// Radius of the profile at height y (linear between stations, as the hull is built; 0 outside).
inline double profile_radius(const std::vector<ProfileStation>& profile, double y) {
  if (profile.empty() || y < profile.front().y || y > profile.back().y) return 0.0;
  for (std::size_t i = 1; i < profile.size(); ++i) {
    if (y <= profile[i].y) {
      const ProfileStation& a = profile[i - 1];
      const ProfileStation& b = profile[i];
      const double s = (y - a.y) / (b.y - a.y);
      return a.radius + s * (b.radius - a.radius);
    }
  }
  return profile.back().radius;
}

/// The hull's largest radius between heights y0 and y1 (m; 0 where the hull is not): its stations
/// there and the profile interpolated linearly at y0 and y1, as the hull is built between stations.
inline double hull_radius_over(const std::vector<ProfileStation>& hull, double y0, double y1) {
  double r = std::max(profile_radius(hull, y0), profile_radius(hull, y1));
  for (const ProfileStation& p : hull)
    if (p.y >= y0 && p.y <= y1) r = std::max(r, p.radius);
  return r;
}

/// The hull's largest radius where it meets the floating ice (from y = -draft to thickness - draft).
inline double hull_radius_in_ice(const Scene& s) {
  return hull_radius_over(s.structure.profile, -s.ice.draft, s.ice.thickness - s.ice.draft);
}

}  // namespace icedem
