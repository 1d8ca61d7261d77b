// One run: initial state, the step loop with recording and progress, and the
// statistics and summary at the end. A run stopped by Ctrl-C or a numerical
// blow-up still leaves a readable HDF5 file, marked "interrupted" or "failed".
#pragma once

#include <string>

#include "dem/checkpoint.hpp"
#include "dem/contact_problem_export.hpp"
#include "dem/flow_coupling.hpp"
#include "dem/scene.hpp"
#include "dem/summary.hpp"

namespace icedem {

struct RunOptions {
  std::string output = "out.h5";  // HDF5 file to write
  bool progress = true;           // progress line on stderr
  std::string command_line;       // recorded in /meta
  FlowCoupling coupling;          // the OpenFOAM coupling, if the program links it (dem/flow_coupling.hpp)
  ProblemExportSettings problems; // contact problems to write (directory empty: none)
  const Checkpoint* resume = nullptr;  // continue from this checkpoint (its output file already
                                       // restored to `output`: dem/checkpoint.hpp); null: from t = 0
};

/// Run the scene to the end (or until interrupted). Throws NumericalError after
/// marking the file "failed"; returns status "interrupted" after Ctrl-C.
RunSummary run_simulation(const Scene& scene, const RunOptions& options);

}  // namespace icedem
