// Error types and process exit codes shared by the whole solver.
//
// The kinds of failure that leave the program, each with its exit code:
//   InputError     : the user's input is wrong (scenario, layout file, --set); exit 2.
//                    The message names file, line, key, value and what was expected.
//   NumericalError : the simulation blew up; exit 3. The message names the step,
//                    the body and the quantity.
//   CouplingError  : the OpenFOAM side failed (missing, meshing, solver, exchange
//                    timeout, a floe outside the mesh); exit 4. The message names
//                    the step that failed and where its log is.
//   OutputError    : the output could not be written (disk full, file vanished);
//                    exit 5. The file is closed, marked failed, and holds the run
//                    up to the time the message names.
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
  kExitOutput = 5,      // OutputError
  kExitInterrupted = 130,  // Ctrl-C (SIGINT), file kept and marked interrupted
  kExitTerminated = 143,   // SIGTERM (kill, Slurm's preemption): as SIGINT, 128 + the signal
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

/// The output file could not be written (dem/output/recorder.hpp).
class OutputError : public std::runtime_error {
 public:
  explicit OutputError(const std::string& message) : std::runtime_error(message) {}
};

/// A failure of the OpenFOAM coupling (coupling/).
class CouplingError : public std::runtime_error {
 public:
  explicit CouplingError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace icedem
