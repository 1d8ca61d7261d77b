#include "dem/calibration.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/errors.hpp"
#include "dem/validation/case.hpp"
#include "dem/validation/plate_theory.hpp"

namespace icedem {

double measure_plate_compliance(const Scene& scene) {
  if (scene.validation.kind != ValidationKind::kPlateDeflection)
    throw InputError(fmt::format("{}: calibration needs validation.case = \"plate_deflection\"", scene.source_path));
  const ValidationResult r = run_validation_case(scene);
  if (!r.value) throw InputError(fmt::format("{}: the plate gave no deflection: {}", scene.source_path, r.note));
  return *r.value / 1e3;  // mm/N -> m/N
}

CalibrationResult calibrate_cfm(const Scene& plate_scene, double target, double tolerance, double cfm_min,
                                double cfm_max, int max_evaluations) {
  CalibrationResult result;
  Scene scene = plate_scene;
  const double factor = plate_finite_factor(scene);
  auto evaluate = [&](double cfm) {
    scene.fracture.cfm = cfm;
    const double w = measure_plate_compliance(scene);
    const CalibrationPoint p{cfm, w, modulus_from_compliance(scene, w, factor)};
    result.points.push_back(p);
    return p;
  };

  // a larger CFM is a softer joint: E falls as the CFM grows
  const CalibrationPoint stiff = evaluate(cfm_min);
  if (stiff.modulus < target) {
    result.note = fmt::format("even the stiffest joints (fracture.cfm = {:g}) give E = {:.1f} MPa < {:.1f} MPa at "
                              "{} joint iterations: the plate's softness is PGS non-convergence; raise "
                              "fracture.joint_iterations (or solver.iterations)", cfm_min, stiff.modulus / 1e6,
                              target / 1e6, joint_sweeps(scene));
    result.cfm = cfm_min;
    result.modulus = stiff.modulus;
    return result;
  }
  const CalibrationPoint soft = evaluate(cfm_max);
  if (soft.modulus > target) {
    result.note = fmt::format("even fracture.cfm = {:g} gives E = {:.1f} MPa > {:.1f} MPa", cfm_max,
                              soft.modulus / 1e6, target / 1e6);
    result.cfm = cfm_max;
    result.modulus = soft.modulus;
    return result;
  }
  // bisection in log10(cfm)
  double lo = std::log10(cfm_min), hi = std::log10(cfm_max);
  CalibrationPoint best = std::abs(stiff.modulus - target) < std::abs(soft.modulus - target) ? stiff : soft;
  for (int i = 2; i < max_evaluations && std::abs(best.modulus - target) > tolerance * target; ++i) {
    const double mid = (lo + hi) / 2;
    const CalibrationPoint p = evaluate(std::pow(10.0, mid));
    if (std::abs(p.modulus - target) < std::abs(best.modulus - target)) best = p;
    (p.modulus > target ? lo : hi) = mid;
  }
  result.reached = std::abs(best.modulus - target) <= tolerance * target;
  result.cfm = best.cfm;
  result.modulus = best.modulus;
  if (!result.reached)
    result.note = fmt::format("stopped after {} evaluations at E = {:.1f} MPa", result.points.size(),
                              best.modulus / 1e6);
  return result;
}

}  // namespace icedem
