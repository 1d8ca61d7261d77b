// Contact problems as files in FCLIB's HDF5 format, the format of the FCLIB
// benchmark collection of frictional contact problems, read by Siconos and other
// nonsmooth-mechanics codes (written and read with libfclib).
//
// One file holds one island of one step:
//  /fclib_global   the global form (FCLIB: M v = H r + G l + f, G^T v + b = 0,
//                  u = H^T v + w). FCLIB's equality rows are rigid; a soft joint row
//                  J v + b + c l = 0 is written exactly by one extra velocity s of mass
//                  1/c per soft row, with G's column (J, 1): then s = c l and the
//                  row reads J v + s + b = 0. M's first 6 n rows are the n bodies
//                  (v, w), then the extra velocities, in joint-row order.
//  /fclib_local    the Delassus form (W, q, mu), joints folded in (dem/contact/problem.hpp);
//                  left out if a joint row is rigid.
//  /guesses        one guess: the warm start the run's solver started from.
//  /icedem         what FCLIB has no place for: which bodies each contact and joint
//                  row acts on, the bodies' and joints' indices in the run, the contacts
//                  on the structure, where the problem came from, and the answer the
//                  run's own solver gave (impulses, sweeps, its residual).
#pragma once

#include <optional>
#include <string>

#include "dem/contact/problem.hpp"

namespace icedem {

/// Write `problem` (and the run's answer, if any) to a new file at `path`, replacing it.
/// Throws OutputError naming the path if it cannot be written.
void write_problem_file(const std::string& path, const ContactProblem& problem,
                        const std::optional<SolverAnswer>& answer = std::nullopt);

/// A problem file read back: the problem as written (from the global form and /icedem)
/// and the run's answer if the file has one. Throws InputError naming the path and what
/// is wrong.
struct ProblemFile {
  ContactProblem problem;
  std::optional<SolverAnswer> answer;
};
ProblemFile read_problem_file(const std::string& path);

}  // namespace icedem
