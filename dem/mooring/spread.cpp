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

}  // namespace icedem
