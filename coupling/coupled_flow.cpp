#include "coupling/coupled_flow.hpp"

#include <iostream>

#include "coupling/foam_runner.hpp"
#include "dem/errors.hpp"
#include "dem/initial_state.hpp"

namespace icedem {

std::unique_ptr<FlowField> make_coupled_flow(const Scene& scene) {
  if (scene.coupling.mode == CouplingMode::kProbe)
    throw InputError("coupling.mode = \"probe\": the per-exchange OpenFOAM sampling is not available yet; "
                     "use coupling.mode = \"field\"");
  return std::make_unique<GridFlowField>(solved_flow_grid(scene, std::cerr));
}

void register_coupled_flow() { coupled_flow_factory() = make_coupled_flow; }

}  // namespace icedem
