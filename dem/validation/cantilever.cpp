// What both cantilever cases share: the first break, eq. 6 and the result (dem/validation/cantilever.hpp).
#include "dem/validation/cantilever.hpp"

#include <cmath>

#include <btBulletDynamicsCommon.h>

#include "dem/fracture/fracture.hpp"
#include "dem/fracture/joint_loads.hpp"

namespace icedem {

void Cantilever::clamp_root(State& state) {
  std::vector<FloeBody>& bodies = state.world->floes();
  for (FloeBody& f : bodies) x0_.push_back(f.body->getCenterOfMassPosition().x());
  element_mass_ = bodies.front().shape->mass;
  bodies.front().body->setMassProps(0, btVector3(0, 0, 0));
  bodies.front().body->updateInertiaTensor();
}

void Cantilever::note_first_break(const State& state, double tip_load) {
  if (broken_ || state.fracture.events.empty()) return;
  broken_ = true;
  first_break_ = state.fracture.events.front();
  load_at_break_ = tip_load;
}

double Cantilever::root_stress(const Scene& scene, const State& state) {
  const double Le = scene.fracture.element_size, h = scene.ice.thickness;
  const JointLoads root = joint_loads(*state.world, state.world->joints().front());
  return 6 * std::abs(root.bending_out_of_plane) / (Le * h * h) / 1e3;
}

ValidationResult Cantilever::result(const Scene& scene) const {
  ValidationResult r;
  r.case_name = "cantilever";
  r.metric = "bending stress at failure, kPa";
  r.reference = scene.ice.bending_strength / 1e3;
  r.tolerance = scene.validation.tolerance;
  if (!broken_) {
    r.note = "the beam did not break within time.duration";
    return r;
  }
  const std::optional<double> buoyancy = fragment_buoyancy();
  if (!buoyancy) {
    r.note = "the run ended less than 0.5 s after the break: no fragment buoyancy P_b";
    return r;
  }
  // joint k joins elements k and k+1 of the beam; its midpoint is half an element past k
  const int k = first_break_.joint;
  const double Le = scene.fracture.element_size, h = scene.ice.thickness;
  const double lever = x0_.back() - (x0_[k] + Le / 2);  // m, joint to the load point (the tip element's centre)
  // eq. 6: sigma' = 6 (P_c - P_b) l / (L_e T_e^2)
  const double sigma = 6 * (load_at_break_ - *buoyancy) * lever / (Le * h * h);
  r.value = sigma / 1e3;
  r.rel_error = (sigma - scene.ice.bending_strength) / scene.ice.bending_strength;
  r.passed = std::abs(*r.rel_error) <= r.tolerance && k == 0 &&
             first_break_.mode == static_cast<int>(FailureMode::kBending);
  nlohmann::json& d = r.details;
  d["failure_mode"] = failure_mode_name(static_cast<FailureMode>(first_break_.mode));
  d["failed_joint"] = k;
  d["at_root"] = k == 0;
  d["load_at_failure_N"] = load_at_break_;
  d["time_of_failure_s"] = first_break_.time;
  d["lever_m"] = lever;
  d["fragment_buoyancy_N"] = *buoyancy;
  d["root_joint_stress_at_failure_kPa"] = last_root_stress_;
  d["floating"] = floating();
  d["history"] = {{"time_s", history_time_}, {"tip_load_N", history_load_},
                  {"root_joint_stress_kPa", history_root_stress_}};
  if (floating()) d["history"]["tip_depth_m"] = history_depth_;
  return r;
}

}  // namespace icedem
