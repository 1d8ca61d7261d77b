// The rows a run writes to its output file: body outlines, run metadata, snapshot poses,
// load samples and joint breaks. Where each goes in the file, with units, is declared in
// dem/output/schema.hpp.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <string>
#include <vector>

#include "dem/core/diagnostics.hpp"
#include "dem/fracture/fracture_state.hpp"  // FractureEvent
#include "dem/fracture/sheet_break_record.hpp"

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
  std::string build;           // the build that made the run (BuildId::text(), dem/core/build_id.hpp)
  std::string bullet_version;  // Bullet version (e.g. "3.24")
  std::string precision;       // "double" or "float"
  uint64_t seed = 0;           // random seed of the layout
  int mooring_lines = 0;       // a moored structure's lines (1 for the linear mooring); 0: towed
  bool level_sheet = false;    // level ice cut by closed forms: the file has /sheet
};

/// What a body is doing at a snapshot (/snapshots/rows/awake).
enum BodyActivity : uint8_t {
  kBodyAsleep = 0,  // at rest, not solved
  kBodyAwake = 1,   // being solved
  kBodyGone = 2,    // split into pieces (later bodies whose /bodies/parent names it): no longer in the run
  kBodyLeft = 3,    // left behind the structure (activation.leave_behind): no longer in the run, where it lay
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
  // a moored structure (structure.motion = "moored"): its motion and its mooring's load at the step's end
  Eigen::Vector3d structure_rotation = Eigen::Vector3d::Zero();          // rad, rotation vector
  Eigen::Vector3d structure_velocity = Eigen::Vector3d::Zero();          // m/s, of the reference point
  Eigen::Vector3d structure_angular_velocity = Eigen::Vector3d::Zero();  // rad/s
  Eigen::Vector3d mooring_force = Eigen::Vector3d::Zero();               // N, on the structure
  Eigen::Vector3d mooring_moment = Eigen::Vector3d::Zero();              // N m, about the reference point
  std::vector<double> mooring_tension{};                                 // N, each line's at its fairlead

  /// The surge load, N: the load resisting towing (+x), positive when the ice pushes back,
  /// as the paper plots it. The one place its sign is decided (/load/surge, statistics, progress).
  double surge() const { return -force.x(); }
};

}  // namespace icedem
