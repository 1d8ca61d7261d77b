// Drag computed outside the DEM and exchanged every few steps: the OpenFOAM
// partner of coupling.mode = "probe" (coupling/probe_exchange.hpp, protocol in
// coupling/PROTOCOL.md). While a scene has one, the DEM's own form drag and
// skin friction are off and the exchanged force is applied at each floe's
// centre of mass instead, held between exchanges; buoyancy and damping stay
// the DEM's.
#pragma once

#include <functional>
#include <memory>

#include <Eigen/Core>

#include "dem/input/scene.hpp"

namespace icedem {

struct State;

class DragExchange {
 public:
  virtual ~DragExchange() = default;

  /// Called once per step before the water forces: exchanges with the partner
  /// when one is due. Throws CouplingError if the partner fails or times out.
  virtual void update(const Scene& scene, const State& state) = 0;

  /// The drag on body `body` (index into World::floes()), N, tank frame, from
  /// the last exchange; zero for a body the last exchange did not include.
  virtual Eigen::Vector3d drag(int body) const = 0;

  /// Ends the exchange (tells the partner to stop); called once at the end of
  /// the run, also after a failure (succeeded false: files kept for the
  /// post-mortem). Never throws.
  virtual void finish(bool succeeded) noexcept = 0;
};

// A run gets its exchange from the FlowCoupling it is given (dem/water/flow_coupling.hpp).

}  // namespace icedem
