// coupling.mode = "probe": the drag on the floes computed by the OpenFOAM
// partner (coupling/foam_partner.py) from the flow it samples at the floes,
// exchanged through files every coupling.exchange_steps steps
// (coupling/PROTOCOL.md) and held in between.
#pragma once

#include <sys/types.h>

#include <memory>
#include <vector>

#include "coupling/exchange_protocol.hpp"
#include "dem/water/drag_exchange.hpp"

namespace icedem {

class ProbeDragExchange : public DragExchange {
 public:
  /// Solves the case if it is not cached, opens the exchange directory, starts
  /// the partner (coupling.partner = "spawn") and waits for its hello.
  explicit ProbeDragExchange(const Scene& scene);
  ~ProbeDragExchange() override;

  void update(const Scene& scene, const State& state) override;
  Eigen::Vector3d drag(int body) const override;
  void finish(bool succeeded) noexcept override;

  /// Exchanges so far and their total wall time, s (for the benchmark).
  int exchanges() const { return exchanges_; }

 private:
  std::unique_ptr<ExchangeChannel> channel_;
  pid_t partner_ = -1;
  std::vector<Eigen::Vector3d> drag_;  // N, per World::floes() index
  int exchanges_ = 0;
  bool finished_ = false;
  std::string temporary_dir_;  // the exchange directory when icedem made it (no coupling.exchange_dir)
};

/// The drag exchange of a scene: a ProbeDragExchange for flow.model = "coupled"
/// with coupling.mode = "probe", else nullptr.
std::unique_ptr<DragExchange> make_drag_exchange(const Scene& scene);

}  // namespace icedem
