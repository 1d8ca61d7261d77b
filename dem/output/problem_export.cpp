#include "dem/output/problem_export.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "dem/contact/problem_file.hpp"
#include "dem/core/errors.hpp"

namespace icedem {

ProblemExport::ProblemExport(ProblemExportSettings settings, std::string source)
    : settings_(std::move(settings)), source_(std::move(source)) {
  std::error_code error;
  std::filesystem::create_directories(settings_.directory, error);
  if (error || !std::filesystem::is_directory(settings_.directory))
    throw InputError(fmt::format("--export-problems {}: cannot make the directory ({})", settings_.directory,
                                 error ? error.message() : "not a directory"));
}

void ProblemExport::begin_step(long step, double t_end, double h) {
  step_ = step;
  time_ = t_end;
  h_ = h;
  at_time_ = false;
  // the step (t_end - h, t_end] holds the time
  for (double t : settings_.times) at_time_ = at_time_ || (t > t_end - h && t <= t_end);
}

bool ProblemExport::wants_problems() const {
  const bool capped_open =
      capped_written_ < settings_.capped && time_ - last_capped_time_ >= settings_.capped_spacing;
  return at_time_ || capped_open;
}

void ProblemExport::solved(const ContactProblem& problem, const SolverAnswer& answer) {
  if (static_cast<int>(problem.contacts.size()) < settings_.min_contacts) return;
  const bool capped_open =
      answer.capped && capped_written_ < settings_.capped && time_ - last_capped_time_ >= settings_.capped_spacing;
  if (!at_time_ && !capped_open) return;
  if (capped_open) {
    ++capped_written_;
    last_capped_time_ = time_;
  }
  ContactProblem p = problem;
  p.time = time_;
  p.step = step_;
  p.source = source_;
  const std::string path = (std::filesystem::path(settings_.directory) /
                            fmt::format("{}_t{:08.3f}_i{:02d}.hdf5", settings_.name, time_, problem.island))
                               .string();
  write_problem_file(path, p, answer);
  files_.push_back(path);
}

}  // namespace icedem
