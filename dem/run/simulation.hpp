// One run: initial state, the step loop with recording and progress, and the
// statistics and summary at the end. A run stopped by Ctrl-C or a numerical
// blow-up still leaves a readable HDF5 file, marked "interrupted" or "failed".
#pragma once

#include <string>
#include <vector>

#include "dem/input/scene.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/output/checkpoint.hpp"
#include "dem/output/problem_export.hpp"
#include "dem/output/summary.hpp"
#include "dem/water/flow_coupling.hpp"

namespace icedem {

struct RunOptions {
  std::string output = "out.h5";  // HDF5 file to write
  bool progress = true;           // progress line on stderr
  std::string command_line;       // recorded in /meta
  FlowCoupling coupling;          // the OpenFOAM coupling, if the program links it (dem/water/flow_coupling.hpp)
  ProblemExportSettings problems; // contact problems to write (directory empty: none)
  const Checkpoint* resume = nullptr;  // continue from this checkpoint (its output file already
                                       // restored to `output`: dem/output/checkpoint.hpp); null: from t = 0
};

/// Run the scene to the end (or until interrupted). Throws NumericalError after
/// marking the file "failed"; returns status "interrupted" after Ctrl-C.
RunSummary run_simulation(const Scene& scene, const RunOptions& options);

/// Every warning about a scene, in the order `icedem check` prints them and a run's summary keeps
/// them: its step size, settings that cannot be meant, a validation plate's load, its layout.
std::vector<std::string> scene_warnings(const Scene& scene, const Layout& layout);

}  // namespace icedem
