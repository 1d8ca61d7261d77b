// Health checks: stop a numerical blow-up with a message naming the step, the
// body and the quantity, instead of writing NaNs for the rest of the run; and
// measure, every step, what the stress suite bounds (dem/core/diagnostics.hpp).
#pragma once

#include "dem/core/diagnostics.hpp"
#include "dem/input/scene.hpp"
#include "dem/step/state.hpp"

namespace icedem {

/// Throws NumericalError if an awake floe's position or velocity is not finite,
/// its speed exceeds kBlowUpSpeed or it is farther than kBlowUpDistance from the
/// origin, or if the structure load is not finite. Returns the step's
/// diagnostics: speeds and kinetic energy of the awake ice, the ice mass in the
/// tank, the widest intact joint and the deepest ice vertex in the structure.
StepDiagnostics check_health(const Scene& scene, const State& state);

}  // namespace icedem
