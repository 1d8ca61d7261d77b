// Health checks: stop a numerical blow-up with a message naming the step, the
// body and the quantity, instead of writing NaNs for the rest of the run.
#pragma once

#include "dem/scene.hpp"
#include "dem/state.hpp"

namespace icedem {

/// Throws NumericalError if an awake floe's position or velocity is not finite,
/// its speed exceeds kBlowUpSpeed or it is farther than kBlowUpDistance from the
/// origin, or if the structure load is not finite. Returns the largest angular
/// speed of an awake floe or element (rad/s), a diagnostic recorded every step.
double check_health(const Scene& scene, const State& state);

}  // namespace icedem
