// Water velocity models: still and uniform water, and the strip-wise cylinder potential
// flow around the towed structure (docs/model/validation_targets.md §5).
#include "dem/core/constants.hpp"
#include "dem/water/flow_field.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dem/core/errors.hpp"

namespace icedem {
namespace {

constexpr double kTow = 0.07;  // m/s, towing speed of the NMRI tests

// a straight 45-degree cone: radius 0.614 m at the waterline (Dw = 1.228 m), 0.171 m at the
// keel 0.443 m below, 0.736 m at the deck 0.122 m above (docs/model/validation_targets.md, inputs)
ConePotentialFlow nmri_cone() {
  return ConePotentialFlow({{-0.443, 0.171}, {0.0, 0.614}, {0.122, 0.736}});
}

Eigen::Vector3d at(double r, double theta, double y, const Eigen::Vector3d& axis) {
  // polar position about the axis; theta from +x towards +z
  return axis + Eigen::Vector3d(r * std::cos(theta), y, r * std::sin(theta));
}

TEST(FlowField, StillWaterIsAtRestEverywhere) {
  StillWater still;
  EXPECT_EQ(still.velocity({1, -0.01, 2}), Eigen::Vector3d::Zero());
}

TEST(FlowField, UniformFlowIsTheSameEverywhere) {
  const Eigen::Vector3d u(0.05, 0.0, -0.02);
  UniformFlow uniform(u);
  EXPECT_EQ(uniform.velocity({1, -0.01, 2}), u);
  EXPECT_EQ(uniform.velocity({-30, -1, 0}), u);
}

TEST(ConePotentialFlow, WaterIsStillWhileTheStructureIsAtRest) {
  ConePotentialFlow flow = nmri_cone();
  flow.set_structure({2, 0, 0}, Eigen::Vector3d::Zero());
  for (double r : {0.0, 0.5, 0.62, 1.0, 10.0}) {
    EXPECT_EQ(flow.velocity(at(r, 0.7, -0.01, {2, 0, 0})), Eigen::Vector3d::Zero()) << "r " << r;
  }
}

TEST(ConePotentialFlow, DisturbanceDecaysAsRadiusSquaredFarAway) {
  ConePotentialFlow flow = nmri_cone();
  const Eigen::Vector3d axis(5, 0, 0.3);
  flow.set_structure(axis, {kTow, 0, 0});
  const double a = 0.614;
  for (double theta : {0.0, 1.0, 2.0, 3.0}) {
    // |w| = (a/r)^2 |V| exactly for the cylinder doublet; round-off only
    EXPECT_NEAR(flow.velocity(at(100 * a, theta, 0.0, axis)).norm(), 1e-4 * kTow, 1e-15);
    EXPECT_NEAR(flow.velocity(at(1000 * a, theta, 0.0, axis)).norm(), 1e-6 * kTow, 1e-17);
  }
}

TEST(ConePotentialFlow, RelativeSpeedAtTheShoulderIsTwiceTheTowingSpeed) {
  // structure frame: 2U at the shoulder; tank frame: the water there moves at -V (backwards
  // past the hull at the towing speed), and at the bow it is pushed ahead at +V
  ConePotentialFlow flow = nmri_cone();
  const Eigen::Vector3d axis(2, 0, 0);
  const Eigen::Vector3d v(kTow, 0, 0);
  flow.set_structure(axis, v);
  const double a = 0.614;
  for (double side : {-1.0, 1.0}) {
    const Eigen::Vector3d w = flow.velocity(at(a, side * kPi / 2, 0.0, axis));
    EXPECT_NEAR((w - v).norm(), 2 * kTow, 1e-15);  // round-off
    EXPECT_NEAR((w + v).norm(), 0.0, 1e-15);
  }
  EXPECT_NEAR((flow.velocity(at(a, 0.0, 0.0, axis)) - v).norm(), 0.0, 1e-15);
  // the sheet's shoulder speed-up u_th/U = 1 + a^2/r^2 = 1.45 at 0.3 m from the hull
  const Eigen::Vector3d w = flow.velocity(at(a + 0.3, kPi / 2, 0.0, axis));
  EXPECT_NEAR((w - v).norm() / kTow, 1.45, 0.005);  // the sheet's rounding
}

TEST(ConePotentialFlow, NoWaterCrossesTheHullSurface) {
  ConePotentialFlow flow = nmri_cone();
  const Eigen::Vector3d axis(3, 0, -0.5);
  for (const Eigen::Vector3d& v : {Eigen::Vector3d(kTow, 0, 0), Eigen::Vector3d(0.03, 0, -0.05)}) {
    flow.set_structure(axis, v);
    for (double y : {-0.4, -0.2, -0.01, 0.0, 0.1}) {
      const double a = flow.radius_at(y);
      for (int k = 0; k < 12; ++k) {
        const double theta = 2 * kPi * (k + 0.3) / 12;
        const Eigen::Vector3d e_r(std::cos(theta), 0, std::sin(theta));
        // relative normal velocity (w - V) . e_r at r = a: round-off only
        EXPECT_NEAR((flow.velocity(at(a, theta, y, axis)) - v).dot(e_r), 0.0, 1e-15)
            << "y " << y << " theta " << theta;
      }
    }
  }
}

TEST(ConePotentialFlow, FlowIsDivergenceFreeAndIrrotational) {
  ConePotentialFlow flow = nmri_cone();
  const Eigen::Vector3d axis(0, 0, 0);
  flow.set_structure(axis, {kTow, 0, 0.02});
  const double h = 1e-5;  // m, central-difference step
  for (const Eigen::Vector3d& p : {at(0.8, 0.4, -0.02, axis), at(1.5, 2.5, -0.02, axis)}) {
    const Eigen::Vector3d dx = (flow.velocity(p + Eigen::Vector3d(h, 0, 0)) -
                                flow.velocity(p - Eigen::Vector3d(h, 0, 0))) / (2 * h);
    const Eigen::Vector3d dz = (flow.velocity(p + Eigen::Vector3d(0, 0, h)) -
                                flow.velocity(p - Eigen::Vector3d(0, 0, h))) / (2 * h);
    // gradients are ~V/a ~ 0.1 1/s; central differences are accurate to ~(h/a)^2 ~ 1e-10
    // relative plus round-off 1e-16/h ~ 1e-11 1/s
    EXPECT_NEAR(dx.x() + dz.z(), 0.0, 1e-9);
    EXPECT_NEAR(dz.x() - dx.z(), 0.0, 1e-9);
  }
}

TEST(ConePotentialFlow, RadiusFollowsTheStationsAndIsZeroOutsideThem) {
  ConePotentialFlow flow = nmri_cone();
  // linear between stations: half-way between keel and waterline
  EXPECT_NEAR(flow.radius_at(-0.2215), 0.5 * (0.171 + 0.614), 1e-15);  // round-off
  EXPECT_EQ(flow.radius_at(0.0), 0.614);
  EXPECT_EQ(flow.radius_at(0.122), 0.736);
  EXPECT_EQ(flow.radius_at(-0.5), 0.0);
  EXPECT_EQ(flow.radius_at(0.2), 0.0);

  // below the keel and above the deck the water is undisturbed, even right under the axis
  const Eigen::Vector3d axis(2, 0, 0);
  flow.set_structure(axis, {kTow, 0, 0});
  EXPECT_EQ(flow.velocity(at(0.2, 1.0, -0.5, axis)), Eigen::Vector3d::Zero());
  EXPECT_EQ(flow.velocity(at(0.2, 1.0, 0.2, axis)), Eigen::Vector3d::Zero());
  // at mid-depth the shoulder is at the interpolated radius
  const double a = 0.5 * (0.171 + 0.614);
  EXPECT_NEAR((flow.velocity(at(a, kPi / 2, -0.2215, axis)) + Eigen::Vector3d(kTow, 0, 0)).norm(), 0.0, 1e-15);
}

TEST(ConePotentialFlow, WaterInsideTheHullMovesWithIt) {
  ConePotentialFlow flow = nmri_cone();
  const Eigen::Vector3d axis(2, 0, 0);
  flow.set_structure(axis, {kTow, 0.01, 0});
  // only the horizontal part of the structure's velocity moves the water
  EXPECT_EQ(flow.velocity(at(0.3, 1.0, -0.01, axis)), Eigen::Vector3d(kTow, 0, 0));
  EXPECT_EQ(flow.velocity(axis), Eigen::Vector3d(kTow, 0, 0));
}

TEST(ConePotentialFlow, RejectsStationsThatDoNotDescribeAProfile) {
  EXPECT_THROW(ConePotentialFlow({{0.0, 0.6}}), InputError);
  EXPECT_THROW(ConePotentialFlow({{0.0, 0.6}, {-0.4, 0.2}}), InputError);
  EXPECT_THROW(ConePotentialFlow({{-0.4, 0.2}, {-0.4, 0.6}}), InputError);
  EXPECT_THROW(ConePotentialFlow({{-0.4, -0.2}, {0.0, 0.6}}), InputError);
  try {
    ConePotentialFlow({{0.0, 0.6}, {-0.4, 0.2}});
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("station 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace icedem
