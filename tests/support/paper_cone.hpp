// The design methods' inputs for the paper's cone (Table 2) and ice (Table 3), from the default
// scenario, at a chosen ice-structure friction: the level-ice load tests' common case
// (test_iso19906.cpp, test_ralston.cpp).
#pragma once

#include "dem/validation/iso19906.hpp"
#include "tests/support/scenes.hpp"

namespace icedem::testing {

inline ConeLoadInputs paper_cone(double friction) {
  ConeLoadInputs in = cone_load_inputs(scene_from(""));
  in.friction = friction;
  return in;
}

}  // namespace icedem::testing
