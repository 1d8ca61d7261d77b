// Validation cases (validation.case; scenarios/validation/): runs with a known answer. Each
// case sets up its loads on the initial state, applies them in the step's point-load stage,
// measures after every step, and ends with a typed result, which the summary carries as its
// `validation` block. One file per case: plate_deflection, cantilever_in_air,
// floating_cantilever, wide_cantilever. advance() (dem/step/step.hpp) is the one step of every run, with its case or
// without.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "dem/input/scene.hpp"
#include "dem/step/state.hpp"
#include "dem/step/step.hpp"

namespace icedem {

/// What a validation case measured, against its reference.
struct ValidationResult {
  std::string case_name;          // validation.case
  std::string metric;             // what was measured, with its unit
  std::optional<double> value;    // in the metric's unit; none if the run gave no result
  double reference = 0;           // the same, from theory
  std::optional<double> rel_error;
  double tolerance = 0;           // validation.tolerance
  bool passed = false;
  std::string note;               // why there is no value
  nlohmann::json details = nlohmann::json::object();  // the case's own figures (histories, inputs)

  /// The summary's `validation` block: case, metric, value, reference, rel_error, tolerance,
  /// passed, note (if any), and the details' keys beside them.
  nlohmann::json to_json() const;
};

/// One validation case: a case attached to the steps (dem/step/step.hpp) with a result.
class ValidationCase : public StepCase {
 public:
  /// The result at the end of the run.
  virtual ValidationResult result(const Scene& scene) const = 0;
};

/// The case of scene.validation.kind, set up on the initial state (nullptr for "none").
std::unique_ptr<ValidationCase> make_validation_case(const Scene& scene, State& state);

/// A validation scene run to its end without output: its case's result (calibration, tests).
ValidationResult run_validation_case(const Scene& scene);

}  // namespace icedem
