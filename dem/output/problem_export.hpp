// Writing the contact problems of chosen steps of a run to files
// (dem/contact/problem_file.hpp), for the problem library the contact solvers
// are measured on (docs/model/contact_problems.md).
//
// A step is chosen by its time (every island of the step that holds the time), or
// because its solve stopped at the sweep cap unconverged ("capped"), at most a
// given number of those and no two closer in time than a given spacing. Islands
// with fewer contacts than a minimum are left out: they are not the problems a
// solver struggles with.
#pragma once

#include <string>
#include <vector>

#include "dem/world/contact_solver.hpp"

namespace icedem {

struct ProblemExportSettings {
  std::string directory;        // where the files go (made if missing)
  std::string name = "problem"; // file names: <name>_t<time>_i<island>.hdf5
  std::vector<double> times;    // s: export every island of the steps holding these times
  int capped = 0;               // export up to this many islands that stopped at the cap
  double capped_spacing = 1.0;  // s, least time between two capped exports
  int min_contacts = 1;         // leave out islands with fewer contacts
};

class ProblemExport : public ProblemObserver {
 public:
  /// Throws InputError if the directory cannot be made.
  ProblemExport(ProblemExportSettings settings, std::string source);

  void begin_step(long step, double t_end, double h) override;

  bool wants_problems() const override;
  void solved(const ContactProblem& problem, const SolverAnswer& answer) override;

  /// The files written so far.
  const std::vector<std::string>& files() const { return files_; }

 private:
  ProblemExportSettings settings_;
  std::string source_;
  long step_ = 0;
  double time_ = 0, h_ = 0;
  bool at_time_ = false;             // this step holds one of the times
  int capped_written_ = 0;
  double last_capped_time_ = -1e300;
  std::vector<std::string> files_;
};

}  // namespace icedem
