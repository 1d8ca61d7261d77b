// Validation cases: the result block, the factory and a case run to its end
// (dem/validation/case.hpp).
#include "dem/validation/case.hpp"

#include <cmath>

#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/validation/cantilever.hpp"
#include "dem/validation/plate_deflection.hpp"
#include "dem/validation/wide_cantilever.hpp"

namespace icedem {

nlohmann::json ValidationResult::to_json() const {
  nlohmann::json j = details;
  j["case"] = case_name;
  j["metric"] = metric;
  j["value"] = value ? nlohmann::json(*value) : nlohmann::json(nullptr);
  j["reference"] = reference;
  j["rel_error"] = rel_error ? nlohmann::json(*rel_error) : nlohmann::json(nullptr);
  j["tolerance"] = tolerance;
  j["passed"] = passed;
  if (!note.empty()) j["note"] = note;
  return j;
}

std::unique_ptr<ValidationCase> make_validation_case(const Scene& scene, State& state) {
  switch (scene.validation.kind) {
    case ValidationKind::kNone: return nullptr;
    case ValidationKind::kPlateDeflection: return std::make_unique<PlateDeflection>(scene, state);
    case ValidationKind::kCantilever:
      if (scene.validation.tip_speed > 0) return std::make_unique<FloatingCantilever>(scene, state);
      return std::make_unique<CantileverInAir>(scene, state);
    case ValidationKind::kWideCantilever: return std::make_unique<WideCantilever>(scene, state);
  }
  return nullptr;
}

ValidationResult run_validation_case(const Scene& scene) {
  State state = initial_state(scene, scene_layout(scene).floes);
  const std::unique_ptr<ValidationCase> validation = make_validation_case(scene, state);
  if (!validation) return {};
  const long steps = step_count(scene);
  while (state.step < steps) advance(scene, state, validation.get());
  return validation->result(scene);
}

}  // namespace icedem
