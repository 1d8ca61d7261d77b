// The water velocity of flow.model = "coupled": the OpenFOAM potential flow
// around the structure (coupling.mode = "field": solved once, sampled on a grid,
// interpolated every step).
#pragma once

#include <memory>

#include "dem/input/scene.hpp"
#include "dem/water/flow_coupling.hpp"
#include "dem/water/flow_field.hpp"

namespace icedem {

/// The coupled flow of a scene; solves the OpenFOAM case first if it is not in
/// the cache (progress on stderr). Throws CouplingError if OpenFOAM fails.
std::unique_ptr<FlowField> make_coupled_flow(const Scene& scene);

/// The OpenFOAM coupling for a run: make_coupled_flow and the probe-mode drag exchange
/// (dem/water/flow_coupling.hpp).
FlowCoupling openfoam_coupling();

}  // namespace icedem
