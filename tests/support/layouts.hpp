// The layout tests' channel and generator settings (dem/layout/floe_layout.hpp).
#pragma once

#include <cstdint>

#include "dem/layout/floe_layout.hpp"

namespace icedem::testing {

// the design channel: x in [6, 30] m, z in [-2.4, 2.4] m (docs/model/architecture.md, seed paper Figure 4)
inline const Channel kDesignChannel{6.0, 30.0, -2.4, 2.4};

/// Square floes of `floe_size` (m) at `concentration` in the design channel: 0.2 rad of yaw,
/// 30 Monte Carlo sweeps, 2 mm gaps.
inline LayoutParams layout_params(double floe_size, double concentration, uint64_t seed = 1) {
  LayoutParams p;
  p.channel = kDesignChannel;
  p.floe_size = floe_size;
  p.concentration = concentration;
  p.seed = seed;
  p.max_yaw = 0.2;
  p.sweeps = 30;
  p.min_gap = 0.002;
  return p;
}

}  // namespace icedem::testing
