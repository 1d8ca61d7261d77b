// The water velocity of flow.model = "coupled": the OpenFOAM potential flow
// around the structure (coupling.mode = "field": solved once, sampled on a grid,
// interpolated every step).
#pragma once

#include <memory>

#include "dem/flow_field.hpp"
#include "dem/scene.hpp"

namespace icedem {

/// The coupled flow of a scene; solves the OpenFOAM case first if it is not in
/// the cache (progress on stderr). Throws CouplingError if OpenFOAM fails.
std::unique_ptr<FlowField> make_coupled_flow(const Scene& scene);

/// Makes make_coupled_flow the factory of flow.model = "coupled" (dem/initial_state.hpp).
void register_coupled_flow();

}  // namespace icedem
