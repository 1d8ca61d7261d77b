// The plate-deflection case (dem/validation/plate_deflection.hpp).
#include "dem/validation/plate_deflection.hpp"

#include <fmt/format.h>

#include <cmath>

#include <btBulletDynamicsCommon.h>

#include "dem/validation/plate_theory.hpp"

namespace icedem {

PlateDeflection::PlateDeflection(const Scene& scene, const State& state) {
  const std::vector<FloeBody>& bodies = state.world->floes();
  btVector3 centre(0, 0, 0);
  for (const FloeBody& f : bodies) centre += f.body->getCenterOfMassPosition();
  centre /= static_cast<double>(bodies.size());
  const double reach = 0.51 * scene.fracture.element_size;
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
    const btVector3 p = bodies[i].body->getCenterOfMassPosition();
    if (std::abs(p.x() - centre.x()) < reach + 1e-9 && std::abs(p.z() - centre.z()) < reach + 1e-9) {
      centre_.push_back(i);
      y0_ += p.y();
    }
  }
  y0_ /= static_cast<double>(centre_.size());
  for (int i : centre_) loads_.forces.emplace_back(i, Eigen::Vector3d(0, -scene.validation.load / centre_.size(), 0));
}

void PlateDeflection::after_step(const Scene& scene, State& state) {
  if (state.time < scene.time.duration / 2) return;
  double y = 0;
  for (int i : centre_) y += state.world->floes()[i].body->getCenterOfMassPosition().y();
  sum_ += y0_ - y / centre_.size();
  ++samples_;
}

ValidationResult PlateDeflection::result(const Scene& scene) const {
  ValidationResult r;
  r.case_name = "plate_deflection";
  r.metric = "centre deflection per unit load, mm/N";
  const double factor = plate_finite_factor(scene);
  const double reference = hertz_plate_compliance(scene) * factor;  // m/N
  r.reference = reference * 1e3;
  r.tolerance = scene.validation.tolerance;
  r.details["infinite_plate_mm_per_N"] = hertz_plate_compliance(scene) * 1e3;
  r.details["finite_plate_factor"] = factor;
  r.details["elastic_modulus_target_MPa"] = scene.ice.elastic_modulus / 1e6;
  if (samples_ == 0) {
    r.note = "the run ended before its second half, where the deflection is measured";
    return r;
  }
  const double compliance = sum_ / samples_ / scene.validation.load;  // m/N
  r.value = compliance * 1e3;
  r.rel_error = (compliance - reference) / reference;
  r.passed = std::abs(*r.rel_error) <= r.tolerance;
  r.details["elastic_modulus_MPa"] = modulus_from_compliance(scene, compliance, factor) / 1e6;
  return r;
}

std::string plate_load_warning(const Scene& scene) {
  if (scene.validation.kind != ValidationKind::kPlateDeflection) return "";
  const double compliance = hertz_plate_compliance(scene) * plate_finite_factor(scene);  // m/N
  const double deflection = scene.validation.load * compliance, freeboard = scene.ice.thickness - scene.ice.draft;
  if (deflection <= freeboard) return "";
  return fmt::format("validation.load = {} N deflects the plate's centre by {:.1f} mm by the reference ({:.4f} mm/N), "
                     "beyond its freeboard of {:.1f} mm: the loaded elements go under water, where the plate no "
                     "longer floats as the theory assumes (the first steps throw them about); a load below {:.1f} N "
                     "keeps them afloat",
                     scene.validation.load, 1e3 * deflection, 1e3 * compliance, 1e3 * freeboard, freeboard / compliance);
}

}  // namespace icedem
