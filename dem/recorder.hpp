// The HDF5 recorder: writes one run's output file (out.h5).
//
// File layout (a stable interface, DESIGN.md "Interfaces other tools rely on"). Every dataset
// carries a `units` attribute ("1" for counts and flags) and a `description` attribute.
// n = load samples (one per solver step), nb = bodies, nv = outline vertices, k = snapshots.
//
//   /load/time                 [n]          f8  s     simulation time of the sample
//   /load/force                [n x 3]      f8  N     force by the ice ON the structure, tank frame
//   /load/moment               [n x 3]      f8  N m   moment of that force about the cone axis at
//                                                     the waterline, tank frame
//   /load/surge                [n]          f8  N     -force_x: the load resisting towing, positive
//                                                     when the ice pushes back (as the paper plots)
//   /load/cone_contacts        [n]          i4  1     contact points on the structure
//   /structure/position        [n x 3]      f8  m     structure reference point, tank frame
//   /diagnostics/awake_bodies  [n]          i4  1     bodies being solved (not sleeping)
//   /diagnostics/contact_points [n]         i4  1     contact points in the whole world
//   /diagnostics/max_angular_speed [n]      f8  rad/s fastest-turning awake floe or element
//   /diagnostics/max_speed     [n]          f8  m/s   fastest awake floe or element
//   /diagnostics/kinetic_energy [n]         f8  J     kinetic energy of the awake ice
//   /diagnostics/ice_mass      [n]          f8  kg    ice in the world inside the tank
//   /diagnostics/max_joint_gap [n]          f8  m     widest separation of an intact joint's anchors
//   /diagnostics/max_cone_penetration [n]   f8  m     deepest ice vertex inside the structure hull
//   /bodies/floe_id            [nb]         i4  1     floe of body i (body order = snapshot order)
//   /bodies/thickness          [nb]         f8  m
//   /bodies/vertex_offset      [nb+1]       i8  1     body i's outline: vertices[off[i]:off[i+1]]
//   /bodies/vertices           [nv x 2]     f8  m     outline vertices in the body frame (x, z)
//   /snapshots/time            [k]          f8  s
//   /snapshots/position        [k x nb x 3] f8  m     body origin, tank frame
//   /snapshots/orientation     [k x nb x 4] f8  1     body-to-tank rotation, quaternion w,x,y,z
//   /snapshots/awake           [k x nb]     u1  1     1 if the body was awake
//   /fracture/events           [e]          compound, one row per joint break (may be empty):
//                                                     time f8 s, floe i4, joint i4, mode i4,
//                                                     ratio f8 = load / threshold, x f8 m, z f8 m
//                                                     (joint midpoint, tank frame), mechanism i4,
//                                                     touching_structure i4, depth f8 m,
//                                                     distance f8 m, structure_force f8 N,
//                                                     press_down f8 N, press_toward f8 N,
//                                                     ratio_<criterion> f8 (the FractureEvent
//                                                     fields); attributes mode_names and
//                                                     mechanism_names (code -> name)
//   /fracture/floe_max_ratio   [f]          f8  1     per layout floe: largest joint load ratio
//   /fracture/floe_min_distance [f]         f8  m     per layout floe: closest approach of its
//                                                     joints to the structure (horizontal) (inf: never awake)
//   /meta   attributes: scenario (resolved TOML text), scenario_path, command_line, version,
//           bullet_version, precision, seed (u8), format_version (i4), started_utc (ISO 8601),
//           status, message, wall_time_s, finished_utc (after finish()).
//           status: "running" while running (a file left "running" was killed), then
//           "complete" | "interrupted" | "failed" (finish()) or "incomplete" (the Recorder was
//           destroyed without finish(), e.g. during stack unwinding).
//   /stats, /layout, ...: attributes written by set_attributes() / set_attribute().
//
// Time series are chunked with an unlimited first dimension. Appends go to memory buffers,
// written in blocks (every kBlockRows load rows, or when the snapshot buffer exceeds
// kSnapshotBufferBytes, or on flush()); every block write is followed by H5Fflush, and the
// file is touched only then. A process killed (even by SIGKILL) outside a write therefore
// leaves a consistent file holding everything up to the last block write or flush(), which
// h5py and the HDF5 tools open as usual.
//
// Format choices for that robustness: the file uses the HDF5 1.8 format (libver bounds
// V18..V18). The 1.10 format (superblock v3) marks the file "open for write" and refuses to
// open it after a crash until `h5clear -s` is run. The writer takes no file lock, so another
// process may read the file during a run; it sees the state at the last flush, and a read that
// races a flush may fail and should be retried.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dem/diagnostics.hpp"

namespace icedem {

/// The outline of one body (floe or floe element) as it is stored under /bodies.
struct BodyOutline {
  int floe_id;                            // id of the floe this body belongs to
  std::vector<Eigen::Vector2d> outline;   // m, polygon vertices in the body frame (x, z)
  double thickness;                       // m
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

/// The pose of one body at a snapshot.
struct BodyPose {
  Eigen::Vector3d position;        // m, body origin in the tank frame
  Eigen::Quaterniond orientation;  // body-to-tank rotation
  bool awake;                      // true if the body is being solved
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

/// Writes one run's HDF5 output file; see the layout at the top of this header.
///
/// Call order: construct, then any number of append*/set_attribute*/flush calls, then
/// finish() once. After finish() the file is closed and further calls throw std::logic_error.
/// Not thread-safe.
class Recorder {
 public:
  /// Load rows buffered before a block is written, rows.
  static constexpr std::size_t kBlockRows = 500;
  /// Snapshot buffer size that triggers a block write, bytes.
  static constexpr std::size_t kSnapshotBufferBytes = std::size_t(4) << 20;

  /// Creates (truncates) the file at `path`, writes /meta (status "running") and /bodies, and
  /// creates the empty time-series datasets. The body order of `bodies` is the order of every
  /// snapshot. Throws std::runtime_error naming the path if the file cannot be created.
  Recorder(const std::string& path, const RunMeta& meta, const std::vector<BodyOutline>& bodies);

  /// Buffers one load sample (call every step).
  void append(const LoadSample& sample);

  /// Buffers one snapshot; `poses` must hold one pose per body, in the constructor's order
  /// (std::invalid_argument otherwise).
  void append_snapshot(double time, const std::vector<BodyPose>& poses);

  /// Buffers one fracture event.
  void append_fracture(const FractureEvent& event);

  /// Writes /fracture/floe_max_ratio and /fracture/floe_min_distance (one value per layout
  /// floe; call once, at the end of a run with breakable floes).
  void write_floe_margins(const std::vector<double>& max_ratio, const std::vector<double>& min_distance);

  /// Writes numeric attributes (f8) on `group` (e.g. "/stats", "/layout"), creating the group
  /// if needed and replacing attributes of the same name. `group` may also name a dataset.
  void set_attributes(const std::string& group, const std::map<std::string, double>& values);

  /// Writes one string attribute on `group`, as set_attributes() does for numbers.
  void set_attribute(const std::string& group, const std::string& name, const std::string& value);

  /// Writes all buffers, updates /meta wall_time_s (wall time since construction) and flushes
  /// the file: from now on a reader sees everything appended so far, even if the process dies.
  void flush();

  /// Writes all buffers, sets /meta status ("complete", "interrupted", "failed"), message and
  /// wall_time_s, and closes the file.
  void finish(const std::string& status, const std::string& message, double wall_time_s);

  /// True if some file could not be closed (disk full mid-close): HDF5 would crash
  /// cleaning it up at exit, so the program should end with std::_Exit after its messages.
  static bool left_a_file_open();

  /// True once finish() has succeeded.
  bool finished() const;

  /// Rows appended so far (buffered or written), for progress reports and tests.
  std::size_t load_rows() const;

  /// If finish() was not called: writes the buffers, sets status "incomplete" and closes the
  /// file. Never throws (errors are reported on stderr).
  ~Recorder();

  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace icedem
