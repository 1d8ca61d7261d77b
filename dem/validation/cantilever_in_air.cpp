// The cantilever in air (dem/validation/cantilever.hpp).
#include <btBulletDynamicsCommon.h>

#include "dem/validation/cantilever.hpp"

namespace icedem {

CantileverInAir::CantileverInAir(const Scene& scene, State& state) {
  // the beam 1 m up in the air, its root element clamped
  for (FloeBody& f : state.world->floes()) {
    btTransform t = f.body->getWorldTransform();
    t.getOrigin() += btVector3(0, 1.0, 0);
    f.body->setWorldTransform(t);
  }
  clamp_root(state);
  after_step(scene, state);  // the weight supports from the first step on
}

void CantileverInAir::after_step(const Scene& scene, State& state) {
  note_first_break(state, tip_load_);
  if (!broken_) {
    // the root joint's bending stress as the model sees it, beside the applied load
    last_root_stress_ = root_stress(scene, state);
    history_time_.push_back(state.time);
    history_load_.push_back(tip_load_);
    history_root_stress_.push_back(last_root_stress_);
  }
  // the tip load of the next step grows linearly (quasi-static: slow against the beam's response)
  tip_load_ = broken_ ? 0.0 : scene.validation.load_rate * state.time;
  set_loads(scene);
}

void CantileverInAir::set_loads(const Scene& scene) {
  // each free element's weight is carried by an upward force, as buoyancy carries a floating
  // beam (the P_b of eq. 6), so the tip load alone bends the beam
  loads_.forces.clear();
  for (int i = 1; i < static_cast<int>(x0_.size()); ++i)
    loads_.forces.emplace_back(i, Eigen::Vector3d(0, element_mass_ * scene.water.gravity, 0));
  loads_.forces.emplace_back(static_cast<int>(x0_.size()) - 1, Eigen::Vector3d(0, -tip_load_, 0));
}

}  // namespace icedem
