// Checkpoints: everything a run needs to continue, written beside its output so that a run
// killed at any moment (SIGKILL, the OOM killer, a node failure, a Slurm preemption) loses at
// most one checkpoint interval (output.checkpoint_interval) and `icedem resume` continues it.
//
// The checkpoint file, OUT.h5.checkpoint, is a copy of the run's output as it stood at the
// checkpoint (so a torn output file costs nothing) with one group more, /checkpoint: the State's
// values (/checkpoint/state, a dataset per field of StateValues, dem/step/state.hpp), the world's state
// (/checkpoint/world, dem/output/world_state.hpp) and what the run loop keeps for the statistics at the
// end (/checkpoint/history, RunHistory). The values and the history are written and read through
// their one list of fields (visit_fields), so a field added to them cannot be left out. It is written to a
// temporary file and renamed over the last one, so a kill during the write leaves the previous
// checkpoint whole. Its records are kept as this build lays them out in memory (bit-exact); a
// checkpoint is read back only by the version of icedem that wrote it (/checkpoint records it).
//
// A run rebuilds its world from each checkpoint it writes, as a resumed run does: the two then
// continue from the same world, and a resumed run ends bit for bit as the uninterrupted one.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "dem/core/diagnostics.hpp"
#include "dem/output/world_state.hpp"
#include "dem/step/state.hpp"

namespace icedem {

/// What the run loop accumulates for the summary at the end, step by step.
struct RunHistory {
  std::vector<double> time, surge, heave, sway;  // s, N: per step
  // a moored structure's, per step (empty when towed): the mooring's force along the travel (N, holding
  // the structure against the ice), the structure's surge offset from its attachment's rest (m,
  // negative: pushed back) and the largest line tension (N)
  std::vector<double> mooring_surge, surge_offset, max_tension;
  std::vector<StepDiagnostics> diagnostics;      // per step
  double awake_sum = 0;                          // awake floes summed over the steps
  DiagnosticExtremes health;                     // extremes of the diagnostics
  // s, what the run's earlier processes spent (a resumed run's), up to their last checkpoint: the
  // summary's wall and CPU time cover the whole run, as its stage times do
  double earlier_wall_s = 0, earlier_cpu_s = 0;
};

/// Calls `visit(name, field)` for every field of a RunHistory (as visit_fields of StateValues).
template <typename History, typename Visit>  // History: RunHistory or const RunHistory
std::enable_if_t<std::is_same_v<std::remove_const_t<History>, RunHistory>> visit_fields(History& h, Visit&& visit) {
  visit("time", h.time);
  visit("surge", h.surge);
  visit("heave", h.heave);
  visit("sway", h.sway);
  visit("mooring_surge", h.mooring_surge);
  visit("surge_offset", h.surge_offset);
  visit("max_tension", h.max_tension);
  visit("diagnostics", h.diagnostics);
  visit("awake_sum", h.awake_sum);
  visit("health", h.health);
  visit("earlier_wall_s", h.earlier_wall_s);
  visit("earlier_cpu_s", h.earlier_cpu_s);
}

/// The analytic level sheet's state (dem/fracture/analytic_sheet.hpp): its breaks, which a rebuilt sheet makes
/// again in order among the floes' splits, and the floes' loads on it so far.
struct SheetState {
  std::vector<SheetBreakRecord> breaks;
  AnalyticSheet::FloeLoadTotals floe_loads;
};

/// A run's state between two steps.
struct Checkpoint {
  std::string version;  // icedem's version that wrote it (ICEDEM_VERSION)
  StateValues values;   // the State's values, whole (dem/step/state.hpp)
  WorldState world;     // the world's bodies, lattices and contact points
  RunHistory history;   // the run loop's
  std::optional<SheetState> sheet;  // the analytic level sheet's, if the run has one
};

/// The checkpoint file of the output file `output`.
std::string checkpoint_path(const std::string& output);

/// `state` and `history` as a checkpoint.
Checkpoint take_checkpoint(const State& state, const RunHistory& history);

/// Writes `checkpoint` beside `output` (checkpoint_path): a copy of `output`, which the caller
/// has flushed, with /checkpoint added, replacing the last checkpoint atomically. Throws
/// OutputError naming the file if it cannot be written (the last checkpoint is then kept).
void write_checkpoint(const std::string& output, const Checkpoint& checkpoint);

/// Reads the /checkpoint group of `path` (a checkpoint file). Throws InputError naming the
/// file if it has none, or one another version of icedem wrote.
Checkpoint read_checkpoint(const std::string& path);

/// Deletes the /checkpoint group of `path` (a checkpoint file made the run's output again).
void remove_checkpoint_group(const std::string& path);

/// What an output file (or a checkpoint, its copy) says of its run in /meta.
struct OutputMeta {
  std::string status;         // "running" (or a killed run's), "complete", "interrupted", "failed", ...
  std::string scenario_text;  // the resolved scenario
  std::string scenario_path;  // where it was read from
  std::string message;        // why it stopped, if it did
  long rows = 0;              // steps recorded in /load/time
  double last_time = 0;       // s, the last of them (0 if none)
};

/// Reads /meta of `path`. Throws InputError naming the file if it is not an icedem output.
OutputMeta read_output_meta(const std::string& path);

/// Puts the checkpoint's values into `state`, a state the scene's initial_state() just built,
/// and rebuilds its world from the checkpoint's (restore_world), the analytic sheet's breaks made
/// again among the floes' splits in the order they happened.
void restore_state(const Checkpoint& checkpoint, State& state);

}  // namespace icedem
