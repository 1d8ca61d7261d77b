// Scenes and bodies the breakable-ice tests share: joints that never break, a strip of
// elements, and lifting a world into the air.
#pragma once

#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "dem/layout/floe_layout.hpp"
#include "dem/world/world.hpp"
#include "tests/support/scenes.hpp"

namespace icedem::testing {

// joints that never break
inline const std::vector<std::string> kUnbreakable{"fracture.mode=on", "fracture.element_size=0.15",
                                                   "ice.bending_strength=1e9", "ice.compressive_strength=1e9",
                                                   "ice.shear_strength=1e9"};

inline Scene bench(std::vector<std::string> extra = {}) {
  extra.insert(extra.begin(), kUnbreakable.begin(), kUnbreakable.end());
  return bench_scene(extra);
}

inline Floe strip(double length, double width) {
  const double a = length / 2, b = width / 2;
  return Floe{Eigen::Vector2d(10.0, 0.0), 0.0, {{-a, -b}, {a, -b}, {a, b}, {-a, b}}};
}

// lift every element of the world 1 m into the air
inline void lift(World& world) {
  for (FloeBody& f : world.floes()) {
    btTransform t = f.body->getWorldTransform();
    t.getOrigin() += btVector3(0, 1.0, 0);
    f.body->setWorldTransform(t);
  }
}

}  // namespace icedem::testing
