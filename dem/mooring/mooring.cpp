#include "dem/mooring/mooring.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "dem/core/constants.hpp"

namespace icedem {
namespace {

class LinearMooring : public Mooring {
 public:
  LinearMooring(const MooringSettings& m, const Eigen::Vector3d& start)
      : stiffness_(m.stiffness), angular_(m.angular_stiffness), arm_(0, m.attachment_y, 0), rest_(start + arm_) {}

  MooringLoad load(const Eigen::Vector3d& reference, const Eigen::Matrix3d& rotation, double carriage) const override {
    const Eigen::Vector3d arm = rotation * arm_;
    const Eigen::Vector3d offset = reference + arm - (rest_ + Eigen::Vector3d(carriage, 0, 0));
    const Eigen::AngleAxisd turn(rotation);
    const Eigen::Vector3d theta = turn.angle() * turn.axis();
    MooringLoad out;
    out.force = -stiffness_.cwiseProduct(offset);
    out.moment = arm.cross(out.force) - angular_.cwiseProduct(theta);
    out.tensions.push_back(out.force.norm());  // the springs' pull as one "line"
    return out;
  }

  // the springs as one straight "line" from the attachment's rest, on the carriage, to where it is
  std::vector<std::vector<Eigen::Vector3d>> shape(const Eigen::Vector3d& reference, const Eigen::Matrix3d& rotation,
                                                  double carriage, int points) const override {
    const Eigen::Vector3d from = rest_ + Eigen::Vector3d(carriage, 0, 0), to = reference + rotation * arm_;
    std::vector<Eigen::Vector3d> line;
    for (int i = 0; i < points; ++i) line.push_back(from + (to - from) * (points > 1 ? double(i) / (points - 1) : 1.0));
    return {line};
  }

 private:
  Eigen::Vector3d stiffness_, angular_;
  Eigen::Vector3d arm_;   // m, the attachment point from the reference point, body frame
  Eigen::Vector3d rest_;  // m, where the attachment point is at rest at the start, tank frame
};

class CatenaryMooring : public Mooring {
 public:
  explicit CatenaryMooring(std::vector<MooringLine> lines) : lines_(std::move(lines)) {}

  MooringLoad load(const Eigen::Vector3d& reference, const Eigen::Matrix3d& rotation, double carriage) const override {
    // the anchors move with the carriage: the same as the structure moved back by it
    return mooring_load(lines_, reference - Eigen::Vector3d(carriage, 0, 0), rotation);
  }

  std::vector<std::vector<Eigen::Vector3d>> shape(const Eigen::Vector3d& reference, const Eigen::Matrix3d& rotation,
                                                  double carriage, int points) const override {
    const Eigen::Vector3d moved(carriage, 0, 0);
    auto lines = mooring_shapes(lines_, reference - moved, rotation, points);
    for (auto& line : lines)
      for (Eigen::Vector3d& p : line) p += moved;  // back where the carriage has taken the anchors
    return lines;
  }

 private:
  std::vector<MooringLine> lines_;
};

}  // namespace

std::vector<MooringLine> catenary_lines(const Scene& scene, const Eigen::Vector3d& start) {
  const MooringSettings& m = scene.mooring;
  std::vector<MooringLine> lines;
  for (int i = 0; i < m.lines; ++i) {
    const double a = m.first_line_angle + 2 * kPi * i / m.lines;
    const Eigen::Vector3d out(std::cos(a), 0, std::sin(a));
    MooringLine l;
    l.fairlead = m.fairlead_radius * out + Eigen::Vector3d(0, m.fairlead_y, 0);
    l.anchor = Eigen::Vector3d(start.x(), -scene.channel.tank_depth, start.z()) + m.anchor_radius * out;
    l.line = CatenaryLine{m.line_length, m.line_weight, m.line_stiffness, m.seabed_friction};
    lines.push_back(l);
  }
  return lines;
}

int mooring_line_count(const Scene& scene) {
  if (scene.structure.motion != StructureMotion::kMoored) return 0;
  return scene.mooring.model == MooringModel::kLinear ? 1 : scene.mooring.lines;
}

std::unique_ptr<Mooring> make_mooring(const Scene& scene, const Eigen::Vector3d& start) {
  if (scene.mooring.model == MooringModel::kLinear) return std::make_unique<LinearMooring>(scene.mooring, start);
  return std::make_unique<CatenaryMooring>(catenary_lines(scene, start));
}

DiagonalStiffness mooring_stiffness(const Mooring& mooring, const Eigen::Vector3d& reference) {
  // central differences over a step small beside any line's sag and large beside round-off
  const double dx = 1e-5, da = 1e-5;
  DiagonalStiffness k;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    const MooringLoad plus = mooring.load(reference + dx * e, Eigen::Matrix3d::Identity(), 0);
    const MooringLoad minus = mooring.load(reference - dx * e, Eigen::Matrix3d::Identity(), 0);
    k.linear[i] = -(plus.force[i] - minus.force[i]) / (2 * dx);
    const Eigen::Matrix3d up = Eigen::AngleAxisd(da, e).toRotationMatrix();
    const Eigen::Matrix3d down = Eigen::AngleAxisd(-da, e).toRotationMatrix();
    k.angular[i] = -(mooring.load(reference, up, 0).moment[i] - mooring.load(reference, down, 0).moment[i]) / (2 * da);
  }
  return k;
}

}  // namespace icedem
