// What a run's output file and the checkpoint beside it say of the run, for the commands that look
// before they write or resume (icedem run -o, resume, info).
//
// A run killed at any moment (SIGKILL, a node failure, a full disk) leaves its checkpoint whole
// (it is written aside and renamed) and its output possibly torn, cut short or lost: the checkpoint
// is a copy of the output as it stood then, so the run is resumable whatever became of the output.
// A torn output is never deleted: `icedem resume` keeps it aside (OUT.damaged) before the
// checkpoint's copy takes its place.
#pragma once

#include <optional>
#include <string>

#include "dem/output/checkpoint.hpp"

namespace icedem {

struct RunFiles {
  std::string output;                // the run's output file, as named
  std::string checkpoint;            // checkpoint_path(output)
  bool output_exists = false;        // a non-empty file at `output`
  bool checkpoint_exists = false;
  std::optional<OutputMeta> meta;    // the output's /meta, if it can be read
  std::string damage;                // why a non-empty output cannot be read as an icedem output ("" if it can)

  /// A killed or interrupted run that `icedem resume` continues: its checkpoint is there and its
  /// output does not say it ended (complete, or failed: a failed run fails again where it did).
  bool resumable() const;
  /// The output is there but cannot be read, and a checkpoint is beside it: a torn output.
  bool damaged() const { return output_exists && !damage.empty(); }
};

/// Looks at `output` and its checkpoint (reading /meta in a child process: a torn file may crash
/// HDF5). Reads nothing of the checkpoint itself: read_checkpoint verifies it.
RunFiles look_at_run(const std::string& output);

/// Copies `path` to the first free name of PATH.damaged, PATH.damaged.2, ... and returns it.
/// Throws OutputError naming the file if it cannot.
std::string keep_aside(const std::string& path);

/// The output whose checkpoint `path` is, if `path` is named as checkpoints are (OUT.checkpoint).
std::optional<std::string> output_of_checkpoint(const std::string& path);

}  // namespace icedem
