// What holds a moored structure (mooring.model): its one interface, and the two models behind it.
//
//   linear    springs between an attachment point on the structure's axis and the same point's place
//             on the carriage: F = -K (a - a0), M = -K_rot theta (a diagonal 6 x 6 stiffness, the
//             usual idealisation of a tank model's spring mooring; cross terms are not modelled)
//   catenary  lines from anchors on the tank's floor to fairleads on the hull, each an elastic catenary
//             lying on the floor where it does (catenary.hpp, spread.hpp), quasi-static
//
// The anchors and the springs' far ends move with the carriage (the attachment follows structure.speed:
// a moored model towed through the ice, as in a tank test). Tank frame: x surge, y up, z sway.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "dem/input/scene.hpp"
#include "dem/mooring/spread.hpp"

namespace icedem {

class Mooring {
 public:
  virtual ~Mooring() = default;

  /// The mooring's load on the structure whose reference point (its axis at the waterline) is at
  /// `reference` with orientation `rotation`, when the carriage has moved `carriage` m along x from
  /// the start: force and moment about the reference point, tank frame, and each line's tension.
  virtual MooringLoad load(const Eigen::Vector3d& reference, const Eigen::Matrix3d& rotation, double carriage) const = 0;

  /// What the views draw of it for the same pose: per line, `points` points from its far end (an anchor;
  /// the linear mooring's attachment point at rest on the carriage) to the structure, tank frame.
  virtual std::vector<std::vector<Eigen::Vector3d>> shape(const Eigen::Vector3d& reference,
                                                          const Eigen::Matrix3d& rotation, double carriage,
                                                          int points) const = 0;
};

/// The mooring scene.mooring describes, for a structure whose reference point starts at `start`
/// (its axis at the waterline, floating upright): anchors at tank.depth below the still-water line.
std::unique_ptr<Mooring> make_mooring(const Scene& scene, const Eigen::Vector3d& start);

/// The lines a run of `scene` records tensions of: 0 for a towed structure, 1 for the linear mooring
/// (its force's magnitude), mooring.lines for the catenary.
int mooring_line_count(const Scene& scene);

/// The catenary model's lines (mooring.lines, spread evenly from mooring.first_line_angle) for a
/// structure whose reference point starts at `start`.
std::vector<MooringLine> catenary_lines(const Scene& scene, const Eigen::Vector3d& start);

/// The mooring's stiffness at `reference` (upright, carriage at 0) along and about x, y and z, by
/// central differences of its load (dem/mooring/floating_structure.cpp sets the damping from it):
/// {k_x, k_y, k_z} N/m, {k_rx, k_ry, k_rz} N m/rad.
struct DiagonalStiffness {
  Eigen::Vector3d linear = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular = Eigen::Vector3d::Zero();
};
DiagonalStiffness mooring_stiffness(const Mooring& mooring, const Eigen::Vector3d& reference);

}  // namespace icedem
