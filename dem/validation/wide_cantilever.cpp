// The wide cantilever (dem/validation/wide_cantilever.hpp).
#include "dem/validation/wide_cantilever.hpp"

#include <algorithm>
#include <cmath>

#include <btBulletDynamicsCommon.h>

#include "dem/core/constants.hpp"
#include "dem/fracture/joint_loads.hpp"
#include "dem/world/bullet_eigen.hpp"

namespace icedem {

namespace {

// kg, a body's mass as the dynamics has it (an outline lattice's element: its true part's)
double mass_of(const FloeBody& f) { return f.body->getInvMass() > 0 ? 1.0 / f.body->getInvMass() : 0.0; }

}  // namespace

WideCantilever::WideCantilever(const Scene& scene, State& state) {
  std::vector<FloeBody>& bodies = state.world->floes();
  const double w = scene.fracture.element_size;
  // the plate's centre along x, its elements' centre of mass; its edges are half its length
  // either side
  double x_centre = 0, mass = 0;
  for (const FloeBody& f : bodies) {
    const double m = mass_of(f);
    x_centre += m * f.body->getCenterOfMassPosition().x();
    mass += m;
  }
  x_centre /= mass;
  const double x_root = x_centre - scene.validation.beam_length / 2 + w;  // clamped below
  const double x_tip = x_centre + scene.validation.beam_length / 2 - w;   // loaded above
  clamped_.assign(bodies.size(), 0);
  double tip_mass = 0;
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
    FloeBody& f = bodies[i];
    const double m = mass_of(f);
    btTransform t = f.body->getWorldTransform();
    t.getOrigin() += btVector3(0, 1.0, 0);  // in air
    f.body->setWorldTransform(t);
    const double x = f.body->getCenterOfMassPosition().x();
    if (x < x_root) {
      clamped_[i] = 1;
      f.body->setMassProps(0, btVector3(0, 0, 0));
      f.body->updateInertiaTensor();
      continue;
    }
    free_.push_back(i);
    free_mass_.push_back(m);
    if (x > x_tip) {
      tip_.push_back(i);
      tip_share_.push_back(m);
      tip_mass += m;
      load_x_ += m * x;
    }
  }
  load_x_ /= tip_mass;
  for (double& s : tip_share_) s /= tip_mass;
  // the root line: the joints between a clamped and a free element
  for (const IceJoint& j : state.world->joints()) {
    if (clamped_[j.body_a] == clamped_[j.body_b]) continue;
    const Eigen::Isometry3d pose_a = body_pose(*bodies[j.body_a].body);
    root_x_ += (pose_a * j.midpoint_a).x();
    root_face_length_ += j.face_length > 0 ? j.face_length : w;
    ++root_joints_;
  }
  if (root_joints_) root_x_ /= root_joints_;
  set_loads(scene);
}

void WideCantilever::after_step(const Scene& scene, State& state) {
  if (!broken_ && !state.fracture.events.empty()) {
    broken_ = true;
    first_break_ = state.fracture.events.front();
    load_at_break_ = tip_load_;
    // whether a joint of the root line broke first
    for (const IceJoint& j : state.world->joints())
      if (j.floe == first_break_.floe && j.index == first_break_.joint)
        first_at_root_ = clamped_[j.body_a] != clamped_[j.body_b];
  }
  // the load of the next step grows linearly (quasi-static: slow against the plate's response)
  tip_load_ = broken_ ? 0.0 : scene.validation.load_rate * state.time;
  set_loads(scene);
}

void WideCantilever::set_loads(const Scene& scene) {
  loads_.forces.clear();
  for (std::size_t k = 0; k < free_.size(); ++k)
    loads_.forces.emplace_back(free_[k], Eigen::Vector3d(0, free_mass_[k] * scene.water.gravity, 0));
  // down: bending; along: in-plane compression, towards the clamped edge at x = 0
  const Eigen::Vector3d direction =
      scene.validation.plate_load == PlateLoad::kAlong ? Eigen::Vector3d(-1, 0, 0) : Eigen::Vector3d(0, -1, 0);
  for (std::size_t k = 0; k < tip_.size(); ++k)
    loads_.forces.emplace_back(tip_[k], tip_load_ * tip_share_[k] * direction);
}

ValidationResult WideCantilever::result(const Scene& scene) const {
  const bool along = scene.validation.plate_load == PlateLoad::kAlong;
  // the strength the plate's first break is set against: bending (eq. 3) or compression (eq. 1)
  const double strength = along ? scene.ice.compressive_strength : scene.ice.bending_strength;
  ValidationResult r;
  r.case_name = "wide_cantilever";
  r.metric = along ? "compressive strength along the plate at its first break, kPa"
                   : "bending strength across the plate at its first break, kPa";
  r.reference = strength / 1e3;
  r.tolerance = scene.validation.tolerance;
  nlohmann::json& d = r.details;
  d["root_joints"] = root_joints_;
  d["root_face_length_m"] = root_face_length_;
  d["beam_width_m"] = scene.validation.beam_width;
  d["lattice_angle_deg"] = scene.fracture.lattice_angle * 180.0 / kPi;
  d["element_shape"] = scene.fracture.element_shape == ElementShape::kHexagon ? "hexagon" : "square";
  d["plate_load"] = along ? "along" : "down";
  if (!broken_) {
    r.note = "the plate did not break within time.duration";
    return r;
  }
  const double lever = load_x_ - root_x_, B = scene.validation.beam_width, T = scene.ice.thickness;
  // the stress of the first break: the root's bending stress (eq. 6 over the plate's width), or
  // the mean compressive stress of any section across the plate
  const double sigma = along ? load_at_break_ / (B * T) : 6 * load_at_break_ * lever / (B * T * T);
  r.value = sigma / 1e3;
  r.rel_error = (sigma - strength) / strength;
  // a compressed plate may break anywhere along it, and in compression or shear
  r.passed = std::abs(*r.rel_error) <= r.tolerance &&
             (along || (first_at_root_ && first_break_.mode == static_cast<int>(FailureMode::kBending)));
  d["failure_mode"] = failure_mode_name(static_cast<FailureMode>(first_break_.mode));
  d["break_x_from_root_m"] = first_break_.x - root_x_;
  d["break_ratios"] = {{"compression", first_break_.ratio_compression}, {"shear", first_break_.ratio_shear},
                       {"bending", first_break_.ratio_bending}};
  d["at_root"] = first_at_root_;
  d["load_at_failure_N"] = load_at_break_;
  d["time_of_failure_s"] = first_break_.time;
  d["lever_m"] = lever;
  return r;
}

}  // namespace icedem
