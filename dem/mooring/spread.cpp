#include "dem/mooring/spread.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace icedem {

MooringLoad mooring_load(const std::vector<MooringLine>& lines, const Eigen::Vector3d& position,
                         const Eigen::Matrix3d& rotation) {
  MooringLoad out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const MooringLine& m = lines[i];
    const Eigen::Vector3d arm = rotation * m.fairlead;
    const Eigen::Vector3d d = position + arm - m.anchor;  // anchor to fairlead
    const double xf = std::hypot(d.x(), d.z()), zf = d.y();
    CatenaryState s;
    try {
      s = solve_catenary(m.line, xf, zf);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("mooring line {}: {}", i + 1, e.what()));
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(fmt::format("mooring line {}: {}", i + 1, e.what()));
    }
    // horizontally towards the anchor (none for a fairlead straight above it), and down
    const Eigen::Vector3d towards = xf > 0 ? Eigen::Vector3d(-d.x() / xf, 0, -d.z() / xf) : Eigen::Vector3d::Zero();
    const Eigen::Vector3d f = s.horizontal * towards - s.vertical * Eigen::Vector3d::UnitY();
    out.force += f;
    out.moment += arm.cross(f);
    out.tensions.push_back(std::hypot(s.horizontal, s.vertical));
    out.lines.push_back(s);
  }
  return out;
}

std::vector<std::vector<Eigen::Vector3d>> mooring_shapes(const std::vector<MooringLine>& lines,
                                                         const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation,
                                                         int points) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (const MooringLine& m : lines) {
    const Eigen::Vector3d d = position + rotation * m.fairlead - m.anchor;  // anchor to fairlead
    const double xf = std::hypot(d.x(), d.z());
    const Eigen::Vector3d along = xf > 0 ? Eigen::Vector3d(d.x() / xf, 0, d.z() / xf) : Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> line;
    for (const Eigen::Vector2d& p : catenary_profile(m.line, solve_catenary(m.line, xf, d.y()), xf, points))
      line.push_back(m.anchor + p.x() * along + p.y() * Eigen::Vector3d::UnitY());
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace icedem
