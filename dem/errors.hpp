// Error types and process exit codes shared by the whole solver.
//
// Two kinds of failure leave the program (DESIGN.md, "Exit codes"):
//   InputError     : the user's input is wrong (scenario, layout file, --set); exit 2.
//                    The message names file, line, key, value and what was expected.
//   NumericalError : the simulation blew up; exit 3. The message names the step,
//                    the body and the quantity.
//   CouplingError  : the OpenFOAM side failed (missing, meshing, solver, exchange
//                    timeout, a floe outside the mesh); exit 4. The message names
//                    the step that failed and where its log is.
// Internal invariants use assert(); they are bugs, not user errors.
#pragma once

#include <stdexcept>
#include <string>

namespace icedem {

enum ExitCode : int {
  kExitOk = 0,
  kExitRuntime = 1,     // anything unexpected (I/O failure, bug)
  kExitBadInput = 2,    // InputError
  kExitNumerical = 3,   // NumericalError
  kExitCoupling = 4,    // CouplingError
  kExitInterrupted = 130,  // Ctrl-C, file kept and marked incomplete
};

/// A problem with user input. `what()` is the full, user-facing message.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

/// A numerical blow-up detected during stepping.
class NumericalError : public std::runtime_error {
 public:
  explicit NumericalError(const std::string& message) : std::runtime_error(message) {}
};

/// A failure of the OpenFOAM coupling (coupling/).
class CouplingError : public std::runtime_error {
 public:
  explicit CouplingError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace icedem
