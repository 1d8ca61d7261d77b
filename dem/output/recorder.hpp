// The HDF5 recorder: writes one run's output file (out.h5). What the file holds, path by path
// with shapes, units and meanings, is declared once in dem/output/schema.hpp (and printed by
// `icedem schema`); this class only writes it.
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

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "dem/output/rows.hpp"

namespace icedem {

/// Writes one run's HDF5 output file in the layout of dem/output/schema.hpp.
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

  /// Creates (truncates) the file at `path`, writes /meta (status "running"), /bodies and
  /// /joints (`joints`' bodies index `bodies`), and creates the empty time-series datasets. The body order of `bodies` is the order of every
  /// snapshot. Throws std::runtime_error naming the path if the file cannot be created.
  Recorder(const std::string& path, const RunMeta& meta, const std::vector<BodyOutline>& bodies,
           const std::vector<JointRecord>& joints = {});

  /// Opens the output file at `path`, written by an earlier Recorder up to some row (a
  /// checkpoint's copy of a run's output), to append after its rows: a resumed run. Sets /meta
  /// status "running" again and records the time of the resumption in /meta resumed_utc.
  /// Throws OutputError naming the path if the file cannot be opened or is not laid out as
  /// dem/output/schema.hpp says.
  struct Reopen {};
  Recorder(const std::string& path, Reopen);

  /// Buffers one load sample (call every step).
  void append(const LoadSample& sample);

  /// Buffers one snapshot; `poses` must hold one pose per body, in the order of /bodies, and
  /// `mooring_points` a moored run's lines, line by line, kMooringShapePoints each (none when towed)
  /// (std::invalid_argument otherwise).
  void append_snapshot(double time, const std::vector<BodyPose>& poses,
                       const std::vector<Eigen::Vector3d>& mooring_points = {});

  /// Adds bodies after those the file was made with (the pieces of a floe that split), written
  /// at once: later snapshots hold one pose per body, these included. Throws OutputError if
  /// they cannot be written.
  void add_bodies(const std::vector<BodyOutline>& bodies);

  /// The bodies of the file so far (the constructor's, then those added).
  std::size_t body_count() const;

  /// Buffers one fracture event.
  void append_fracture(const FractureEvent& event);

  /// Writes the analytic level sheet's outline at the start (a file made with RunMeta::level_sheet), at once.
  void append_sheet_outline(const std::vector<Eigen::Vector2d>& outline);

  /// Writes one break of the sheet and its outline after it, at once (the outline first: a file cut between the
  /// writes holds an outline no break names).
  void append_sheet_break(const SheetBreakRecord& record, const std::vector<Eigen::Vector2d>& outline_after);

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
