// The run summary: a one-screen table and the JSON file that sweeps read.
//
// The JSON keys are declared once, in summary_fields(): sweeps and scripts rely on them,
// so keys are added, none renamed or removed. "fx" is the surge load as the paper plots it:
// the force resisting towing, positive.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dem/core/build_id.hpp"
#include "dem/core/diagnostics.hpp"
#include "dem/output/statistics.hpp"
#include "dem/step/state.hpp"

namespace icedem {

/// What the contact solver did over a run (from the per-step solver diagnostics).
struct SolverSummary {
  std::string method = "pgs";     // solver.method
  int cap = 0;                    // solver.iterations (pgs), solver.method_iterations (newton)
  double tolerance = 0;           // solver.tolerance (pgs), solver.merit_tolerance (newton)
  double joint_tolerance = 0;     // islands with joints (methods other than pgs): the smaller merit tolerance
  double structure_tolerance = 0; // islands touching the structure: likewise
  double iterations_mean = 0;     // per step, the most sweeps an island used, averaged over the run
  int iterations_max = 0;
  long capped_steps = 0;          // steps in which an island reached the cap unconverged
  double capped_window_fraction = 0;  // of the analysis window's steps (the whole run without one)
  double residual_max = 0;
  double breaking_tolerance = 0;  // the merit breaking solves were solved to (0: off)
  // the island solve's counts (the diagnostics' columns of Reduction::kCount) summed over the run:
  // breaking solves, hand-overs, runaways, ... (dem/core/diagnostics.hpp)
  StepDiagnostics totals;
  std::string handover_method;    // solver.handover_method
  /// More than this fraction of capped steps in the window: the summary warns.
  static constexpr double kCappedWarning = 0.01;
};

/// A moored structure's mooring and motion over the analysis window (structure.motion = "moored").
struct MooringSummary {
  bool present = false;     // false: a towed structure (the summary's "mooring" is null)
  LoadStatistics force{};   // the mooring's force along the travel (holding the structure against the ice)
  double offset_mean_m = 0; // the structure's surge offset from its attachment's rest (negative: pushed back)
  double offset_std_m = 0;
  double offset_min_m = 0;  // the farthest back
  double tension_max_N = 0; // the largest line tension
};

struct RunSummary {
  std::string scenario;  // scenario path
  std::string output;    // HDF5 path
  std::string status;    // complete | interrupted | failed
  std::string message;   // error or note, "" if none
  int signal = 0;        // the signal that interrupted the run (SIGINT, SIGTERM), else 0

  bool has_statistics = false;  // false if the window held no data
  std::string statistics_note;  // why there are no statistics
  LoadStatistics surge{};       // surge load over the analysis window
  double mean_fy_N = 0.0;       // mean heave load over the window (ice on structure, + up)
  double mean_fz_N = 0.0;       // mean sway load over the window
  double first_contact_s = -1;  // s, first ice contact (-1: none)
  MooringSummary mooring;       // a moored structure's, over the same window

  long steps = 0;
  double sim_time_s = 0.0;
  double bullet_step_s = 0.0;   // time.dt / time.substeps: the step the dynamics took
  BuildId build{"unknown", false, "", ""};  // the build of the process that wrote the summary
  double wall_time_s = 0.0;
  double cpu_time_s = 0.0;   // user + system CPU time of the process (a shared machine's fair cost)
  int floes = 0;
  double achieved_concentration = 0.0;
  double mean_awake = 0.0;  // floes simulated per step, averaged over the run
  int breaks = 0;           // joint failures (0 with rigid floes)
  std::array<int, kFailureModes> breaks_by_mode{};  // by FailureMode: compression, shear, bending, tension,
                                                   // in-plane bending
  std::array<int, kBreakMechanisms> breaks_by_mechanism{};  // by BreakMechanism
  // per floe with joints that came within kNearStructureDistance of the structure: the largest
  // load / capacity ratio of its joints over the run (dem/fracture/break_context.hpp)
  std::vector<double> near_structure_max_ratio;
  long held_edge_overloads = 0;  // level ice: joint-steps at the held edge over capacity (/diagnostics/held_edge_overloads)
  long sheet_holds = 0;  // analytic level ice: zone-steps at the breaking load not cut (/diagnostics/sheet_holds)
  StageTimes stage_times;   // s of wall time per stage of step()
  SolverSummary solver;     // sweeps, residuals and capped steps of the contact solver
  // the fixed boundaries (dem/world/boundary_load.hpp) over the analysis window: the share of the
  // surge load they carry (sum of boundary load / sum of surge load) and of the steps locked
  double boundary_share = 0;
  double locked_window_fraction = 0;
  // the structure squeezing the ice against the channel's end wall (dem/input/structure_path.hpp):
  // from when (-1: not in this run), against the wall at x, the largest surge load from then on, and
  // whether the statistics left those steps out (stats.include_squeeze false)
  double squeeze_start_s = -1;
  double squeeze_wall_x = 0;
  double squeeze_max_fx_N = 0;
  bool squeeze_excluded = false;
  DiagnosticExtremes health;  // extremes of the per-step diagnostics (speeds, energy, ice mass, ...)
  std::vector<std::string> warnings;  // scene warnings (step_size_warnings), printed first
  nlohmann::json validation;  // validation block of a validation case, null otherwise
  std::vector<std::string> problem_files;  // contact problems written (--export-problems); not in the JSON
};

/// One key of the summary JSON. The numeric keys marked `stats` are also written as
/// attributes of /stats in the HDF5 file (when not null).
struct SummaryField {
  const char* key;
  const char* unit;  // "" for text and objects
  bool stats;
  bool omit_if_null;  // left out of the JSON when null (the validation block)
  const char* description;
  std::function<nlohmann::json(const RunSummary&)> value;
};

/// Every key of the summary JSON, in the order docs/user/output.md lists them.
const std::vector<SummaryField>& summary_fields();

/// A short human-readable table.
std::string summary_table(const RunSummary& s);

/// The summary as JSON (NaN becomes null).
nlohmann::json summary_json(const RunSummary& s);

}  // namespace icedem
