// The initial State of a run: floe layout, Bullet world and flow model built
// from the Scene.
#pragma once

#include <functional>
#include <memory>

#include "dem/floe_layout.hpp"
#include "dem/flow_field.hpp"
#include "dem/scene.hpp"
#include "dem/state.hpp"

namespace icedem {

/// The floe field of the scene's channel.
Channel scene_channel(const Scene& scene);

/// The floes: read from layout.file, or generated at ice.concentration.
Layout scene_layout(const Scene& scene);

/// The water velocity model of flow.model.
std::unique_ptr<FlowField> make_flow(const Scene& scene);

/// Makes the flow of flow.model = "coupled". The OpenFOAM coupling lives in
/// coupling/, which depends on dem/ and not the reverse: a program that links it
/// sets this factory once at start (the icedem command does); unset, a coupled
/// scene is an InputError.
using CoupledFlowFactory = std::function<std::unique_ptr<FlowField>(const Scene&)>;
CoupledFlowFactory& coupled_flow_factory();

/// World, flow and structure at t = 0 with the given floes.
State initial_state(const Scene& scene, const std::vector<Floe>& floes);

}  // namespace icedem
