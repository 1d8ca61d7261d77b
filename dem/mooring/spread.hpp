// A spread of mooring lines on a floating body: each line from its anchor on the seabed to its fairlead
// on the body, solved as an elastic catenary (catenary.hpp) in the vertical plane through the two, and
// the lines' forces summed into the force and moment on the body. Tank frame: x surge, y up, z sway.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "dem/mooring/catenary.hpp"

namespace icedem {

struct MooringLine {
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();    // m, on the seabed, tank frame
  Eigen::Vector3d fairlead = Eigen::Vector3d::Zero();  // m, on the body, from its reference point, body frame
  CatenaryLine line;
};

struct MooringLoad {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, on the body, tank frame
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // N m, about the body's reference point, tank frame
  std::vector<CatenaryState> lines;                  // each line's state, in order
  std::vector<double> tensions;                      // N, each line's tension at its fairlead, |(HF, VF)|
};

/// The lines' load on a body whose reference point is at `position` and whose orientation turns its
/// frame into the tank's by `rotation`. Each line pulls its fairlead towards its anchor with its
/// horizontal tension and down with its vertical one. Throws what solve_catenary throws, naming the line.
MooringLoad mooring_load(const std::vector<MooringLine>& lines, const Eigen::Vector3d& position,
                         const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity());

/// Each line's shape for the body at `position` with `rotation` (as mooring_load takes them): `points`
/// points from its anchor to its fairlead, tank frame (catenary_profile in the line's vertical plane).
std::vector<std::vector<Eigen::Vector3d>> mooring_shapes(const std::vector<MooringLine>& lines,
                                                         const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation,
                                                         int points);

}  // namespace icedem
