// A run's state, the same state rebuilt in a fresh world from its WorldState (as a checkpoint's
// resume does, dem/output/world_state.hpp), and how far the two then part: the checkpoint tests'
// shared steps (test_world_state.cpp, test_level_ice.cpp).
#pragma once

#include <algorithm>

#include "dem/output/world_state.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"

namespace icedem::testing {

/// A run's state after `steps` steps.
inline State advanced(const Scene& scene, long steps) {
  State state = initial_state(scene, scene_layout(scene).floes);
  while (state.step < steps) step(scene, state);
  return state;
}

/// A fresh world of the scene with `from`'s state, and the run's clock.
inline State rebuilt(const Scene& scene, const State& from) {
  State state = initial_state(scene, scene_layout(scene).floes);
  restore_world(*state.world, capture_world(*from.world));
  state.time = from.time;
  state.step = from.step;
  state.structure_position = from.structure_position;
  state.structure_velocity = from.structure_velocity;
  state.flow->set_structure(state.structure_position, state.structure_velocity);
  return state;
}

/// The largest distance between the bodies of two runs after `steps` more steps of each.
inline double gap_after(const Scene& scene, State& run, State& copy, int steps) {
  for (int k = 0; k < steps; ++k) {
    step(scene, run);
    step(scene, copy);
  }
  double gap = 0;
  for (std::size_t i = 0; i < run.world->floes().size(); ++i)
    gap = std::max(gap, (run.world->floes()[i].body->getCenterOfMassPosition() -
                         copy.world->floes()[i].body->getCenterOfMassPosition())
                            .length());
  return gap;
}

}  // namespace icedem::testing
