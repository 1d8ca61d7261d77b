// What an outside flow solver provides to a run: the water velocity of flow.model = "coupled"
// and the exchanged drag of coupling.mode = "probe". The OpenFOAM coupling lives in coupling/,
// which depends on dem/ and not the reverse: a program that links it passes
// openfoam_coupling() (coupling/coupled_flow.hpp) in RunOptions and to initial_state(); without
// it, a coupled scene is an InputError.
#pragma once

#include <functional>
#include <memory>

#include "dem/input/scene.hpp"
#include "dem/water/drag_exchange.hpp"
#include "dem/water/flow_field.hpp"

namespace icedem {

struct FlowCoupling {
  /// The flow of flow.model = "coupled" (empty: none available).
  std::function<std::unique_ptr<FlowField>(const Scene&)> flow;
  /// The drag exchange of a scene, or nullptr if the scene has none (empty: none available).
  std::function<std::unique_ptr<DragExchange>(const Scene&)> drag_exchange;
};

}  // namespace icedem
