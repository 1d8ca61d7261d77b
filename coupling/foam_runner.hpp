// Running the OpenFOAM case: solve once per geometry and mesh, keep the result
// in a cache keyed by the hash of the case inputs (coupling/foam_case.hpp),
// and turn OpenFOAM's probe samples into the DEM's flow grid.
#pragma once

#include <ostream>
#include <string>

#include "coupling/flow_grid.hpp"
#include "coupling/foam_case.hpp"
#include "dem/input/scene.hpp"

namespace icedem {

/// The scene's flow grid: read from <coupling.cache_dir>/<hash>/flow_grid.h5 if
/// this case was solved before, else the case is written there, Allrun run
/// (mesh, potentialFoam, U = -grad(Phi), probes) and the samples converted.
/// Concurrent runs of the same case are safe: each solves in its own directory
/// and the first to finish publishes it by an atomic rename. Progress lines go
/// to `log`. Throws CouplingError naming the failed step and its log.
FlowGrid solved_flow_grid(const Scene& scene, std::ostream& log);

/// The solved case directory of a spec in a cache (it may not exist yet).
std::string foam_case_dir(const FoamCaseSpec& spec, const std::string& cache_dir);

/// Reads OpenFOAM's probes output of gradPhi at the points of `axes` (in their
/// order) into a grid of U = -grad(Phi); a probe outside the water (OpenFOAM
/// writes -1e300) is solid. Throws CouplingError if the file does not hold
/// exactly one sample per point.
FlowGrid grid_from_probes(const std::string& probes_file, const GridAxes& axes);

}  // namespace icedem
