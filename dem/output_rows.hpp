// The rows a run writes to its output file: body outlines, run metadata, snapshot poses,
// load samples and joint breaks. Where each goes in the file, with units, is declared in
// dem/output_schema.hpp.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

#include "dem/diagnostics.hpp"

namespace icedem {

/// The outline of one body (floe or floe element) as it is stored under /bodies.
struct BodyOutline {
  int floe_id;                            // id of the floe this body belongs to
  std::vector<Eigen::Vector2d> outline;   // m, polygon vertices in the body frame (x, z)
  double thickness;                       // m
  int parent = -1;                        // a piece of a split floe: the body it was split from, else -1
  double born = 0;                        // s, when the body came into the run (0: from the start)
};

/// A joint of a breakable floe as it is stored under /joints: the two bodies it glues
/// (output body indices, the /bodies order) and where, so that a reader can draw the
/// glued face at any snapshot and mark it once /fracture/events says it broke.
struct JointRecord {
  int body_a, body_b;          // output body indices
  int floe;                    // floe id (as /bodies/floe_id)
  int index;                   // joint index within its floe (as the `joint` field of /fracture/events)
  Eigen::Vector3d midpoint_a;  // m, joint midpoint in body A's frame
};

/// Run metadata written under /meta when the file is created.
struct RunMeta {
  std::string scenario_text;   // resolved scenario (TOML text, overrides applied)
  std::string scenario_path;   // path of the scenario file as given
  std::string command_line;    // full command line
  std::string version;         // icedem version
  std::string bullet_version;  // Bullet version (e.g. "3.24")
  std::string precision;       // "double" or "float"
  uint64_t seed = 0;           // random seed of the layout
};

/// What a body is doing at a snapshot (/snapshots/rows/awake).
enum BodyActivity : uint8_t {
  kBodyAsleep = 0,  // at rest, not solved
  kBodyAwake = 1,   // being solved
  kBodyGone = 2,    // split into pieces (later bodies whose /bodies/parent names it): no longer in the run
};

/// The pose of one body at a snapshot.
struct BodyPose {
  Eigen::Vector3d position;        // m, body origin in the tank frame
  Eigen::Quaterniond orientation;  // body-to-tank rotation
  uint8_t awake;                   // BodyActivity
};

/// One row of the per-step load time series.
struct LoadSample {
  double time;                         // s
  Eigen::Vector3d force;               // N, by the ice on the structure, tank frame
  Eigen::Vector3d moment;              // N m, about the cone axis at the waterline, tank frame
  Eigen::Vector3d structure_position;  // m, tank frame
  int cone_contacts;                   // contact points on the structure
  int awake_bodies;                    // bodies being solved
  int contact_points = 0;              // contact points in the whole world (solver load)
  StepDiagnostics diagnostics;         // speeds, energy, ice mass, joint gap, cone penetration

  /// The surge load, N: the load resisting towing (+x), positive when the ice pushes back,
  /// as the paper plots it. The one place its sign is decided (/load/surge, statistics, progress).
  double surge() const { return -force.x(); }
};

/// One joint break, with what its floe was doing (dem/break_context.hpp).
struct FractureEvent {
  double time;   // s
  int floe;      // floe id
  int joint;     // joint index within the floe
  int mode;      // failure mode code (FailureMode, dem/joint_loads.hpp)
  double ratio;  // 1, load / threshold of the criterion that fired (>= 1)
  double x = 0;  // m, joint midpoint at the break, tank frame
  double z = 0;  // m
  int mechanism = 0;             // BreakMechanism code
  int touching_structure = 0;    // 1 if an element of the floe touched the structure
  double depth = 0;              // m, joint midpoint below the waterline (+ down)
  double distance = 0;           // m, horizontally from the structure's section at its height
  double structure_force = 0;    // N, the structure's contact force on the floe
  double press_down = 0;         // N, other floes' contact force on it, downward
  double press_toward = 0;       // N, the same, towards the structure axis
  double ratio_compression = 0;  // 1, load / capacity of each criterion (eq. 1-3)
  double ratio_shear = 0;
  double ratio_bending = 0;
  double ratio_tension = 0;
  double ratio_in_plane_bending = 0;
};

}  // namespace icedem
