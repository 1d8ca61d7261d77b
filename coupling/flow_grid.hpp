// The OpenFOAM velocity sampled once on a regular grid (field mode): stored in
// HDF5, interpolated in memory by the DEM every step.
//
// The grid is in the structure frame (axis = y through the origin, y = 0 the
// still-water line) and holds the water velocity relative to the structure
// for a tow at 1 m/s along +x: far away it is (-1, 0, 0). Potential flow is
// linear in the speed, so one grid serves every tow speed.
//
// File layout (flow_grid.h5):
//   /velocity  [ny x nz x nx x 3] f8  1 (m/s per m/s of tow speed), structure frame
//   /solid     [ny x nz x nx]     u1  1 where the point is not in the water (inside the hull)
//   attributes on /: x0, dx, nx, y0, dy, ny, z0, dz, nz (m, counts; point (i, j, k) is
//   (x0 + i dx, y0 + j dy, z0 + k dz)), case_hash, mesh, source.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "dem/water/flow_field.hpp"

namespace icedem {

/// A regular grid: point (i, j, k) = (x0 + i dx, y0 + j dy, z0 + k dz).
struct GridAxes {
  double x0, dx;
  int nx;
  double y0, dy;
  int ny;
  double z0, dz;
  int nz;

  int count() const { return nx * ny * nz; }
  /// Index of point (i, j, k) in the storage order (y slowest, then z, then x).
  int index(int i, int j, int k) const { return (j * nz + k) * nx + i; }
  Eigen::Vector3d point(int i, int j, int k) const { return {x0 + i * dx, y0 + j * dy, z0 + k * dz}; }
};

class FlowGrid {
 public:
  FlowGrid(GridAxes axes, std::vector<Eigen::Vector3d> velocity, std::vector<unsigned char> solid);

  /// Relative velocity per unit tow speed at a point of the structure frame:
  /// trilinear between the water points of its grid cell (weights renormalised
  /// over them; 0, moving with the structure, if the cell has none); beyond the
  /// grid in x or z the undisturbed (-1, 0, 0); y is clamped to the grid's levels.
  Eigen::Vector3d relative_velocity(const Eigen::Vector3d& p) const;

  const GridAxes& axes() const { return axes_; }
  const std::vector<Eigen::Vector3d>& velocity() const { return velocity_; }
  const std::vector<unsigned char>& solid() const { return solid_; }

  /// Writes the grid (layout above) with the case's hash and mesh level.
  void write(const std::string& path, const std::string& case_hash, const std::string& mesh) const;

  /// Reads a grid file; throws std::runtime_error naming the file if it is not one.
  static FlowGrid read(const std::string& path);

 private:
  GridAxes axes_;
  std::vector<Eigen::Vector3d> velocity_;
  std::vector<unsigned char> solid_;
};

/// The tank-frame water velocity of a grid towed along +x: w = V_x (g(x - axis) + e_x),
/// with g the grid's relative velocity per unit speed.
class GridFlowField : public FlowField {
 public:
  explicit GridFlowField(FlowGrid grid);
  Eigen::Vector3d velocity(const Eigen::Vector3d& x) const override;
  void set_structure(const Eigen::Vector3d& axis_point, const Eigen::Vector3d& velocity) override;

 private:
  FlowGrid grid_;
  Eigen::Vector3d axis_point_ = Eigen::Vector3d::Zero();  // m, tank frame
  double speed_ = 0;                                      // m/s, surge speed of the structure
};

}  // namespace icedem
