// Forces a run prescribes on bodies besides water and contacts (the loads of validation cases,
// and of tests): applied in the step's "point loads" stage before every Bullet step, because
// Bullet clears applied forces after each.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace icedem {

class World;

struct PointLoads {
  // (body index into World::floes(), force N in the tank frame at the body's centre of mass)
  std::vector<std::pair<int, Eigen::Vector3d>> forces;

  /// Wakes each loaded body and applies its force for the coming Bullet step.
  void apply(World& world) const;
};

}  // namespace icedem
