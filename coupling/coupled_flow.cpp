#include "coupling/coupled_flow.hpp"

#include <iostream>

#include "coupling/foam_runner.hpp"
#include "coupling/probe_exchange.hpp"
#include "dem/core/errors.hpp"
#include "dem/step/initial_state.hpp"

namespace icedem {

std::unique_ptr<FlowField> make_coupled_flow(const Scene& scene) {
  // probe mode: the partner's exchanged drag carries the flow (coupling/probe_exchange.hpp);
  // the DEM's own water stage sees still water for what it still computes (damping)
  if (scene.coupling.mode == CouplingMode::kProbe) return std::make_unique<StillWater>();
  return std::make_unique<GridFlowField>(solved_flow_grid(scene, std::cerr));
}

FlowCoupling openfoam_coupling() { return FlowCoupling{make_coupled_flow, make_drag_exchange}; }

}  // namespace icedem
