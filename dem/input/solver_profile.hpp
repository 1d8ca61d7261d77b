// Solver profiles: named sets of solver settings (solver.profile).
//
// A profile gives the default of each solver key the scenario leaves unset; a key
// the scenario or --set gives keeps its value. The resolved scenario (/meta) shows
// the values used, each key's origin names the profile.
#pragma once

#include "dem/input/scenario.hpp"

namespace icedem {

/// Fill the solver keys still at their default from the profile that
/// `solver.profile` names.
void apply_solver_profile(Scenario& scenario);

}  // namespace icedem
