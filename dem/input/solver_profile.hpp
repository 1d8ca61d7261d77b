// Solver profiles: named sets of solver settings (solver.profile).
//
// A profile gives the default of each solver key the scenario leaves unset; a key
// the scenario or --set gives keeps its value. The resolved scenario (/meta) shows
// the values used, each key's origin names the profile.
#pragma once

#include <string>

#include "dem/contact/solver_settings.hpp"
#include "dem/input/scenario.hpp"

namespace icedem {

/// Fill the solver keys still at their default from the profile that
/// `solver.profile` names.
void apply_solver_profile(Scenario& scenario);

/// The solver settings a scenario that sets no solver key gets from the profile `profile`
/// ("paper" or "converged"): the keys' one set of defaults, for the tests and benchmarks that
/// make a contact solver without a scenario. Throws InputError for an unknown profile.
SolverSettings solver_settings(const std::string& profile);

}  // namespace icedem
