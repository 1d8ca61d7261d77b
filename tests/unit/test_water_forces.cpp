// Water wrench on a floe: buoyancy (reserve buoyancy, equilibrium, righting moment), form
// drag and skin friction with their torque arms, damping, and the damping coefficients,
// against docs/model/validation_targets.md §1 and §5 and hand-computed per-face sums.
#include "dem/core/constants.hpp"
#include "dem/water/water_forces.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace icedem {
namespace {

// the NMRI small floe (docs/model/validation_targets.md §1)
constexpr double kL = 0.3;         // m, side
constexpr double kH = 0.033;       // m, thickness
constexpr double kRhoIce = 930.0;  // kg/m^3
constexpr double kTow = 0.07;      // m/s, towing speed

std::vector<Eigen::Vector2d> rectangle(double lx, double lz) {
  return {{-lx / 2, -lz / 2}, {lx / 2, -lz / 2}, {lx / 2, lz / 2}, {-lx / 2, lz / 2}};
}

struct Floe {
  ConvexPolyhedron body = make_prism(rectangle(kL, kL), kH);
  double mass = kRhoIce * kL * kL * kH;                  // kg
  double inertia = mass * (kL * kL + kH * kH) / 12;      // kg m^2, about a horizontal axis
  double draft = kRhoIce / 1000.0 * kH;                  // m
  // the centre of mass when floating upright at rest
  Eigen::Vector3d floating_com(double x = 0, double z = 0) const {
    return {x, kH / 2 - draft, z};
  }
};

BodyMotion at_rest(const Eigen::Vector3d& com, const Eigen::Matrix3d& rot = Eigen::Matrix3d::Identity()) {
  BodyMotion m;
  m.pose.linear() = rot;
  m.pose.translation() = com;
  return m;
}

TEST(WaterForces, HoldingAFloeUnderwaterTakesItsReserveBuoyancy) {
  // docs/model/validation_targets.md §1: (rho_w - rho_i) g L^2 h = 2.04 N for the 0.3 m floe
  const Floe floe;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  const Wrench w = water_wrench(floe.body, at_rest({4, -0.2, 1}), StillWater(), p, d);
  const double net_up = w.force.y() - floe.mass * p.gravity;
  EXPECT_NEAR(net_up, (1000.0 - kRhoIce) * p.gravity * kL * kL * kH, 1e-12);  // round-off
  EXPECT_NEAR(net_up, 2.04, 0.001 * 2.04);  // the sheet's value to 0.1 %
  EXPECT_NEAR(w.force.x(), 0.0, 1e-12);
  EXPECT_NEAR(w.force.z(), 0.0, 1e-12);
  EXPECT_NEAR(w.torque.norm(), 0.0, 1e-12);  // buoyancy acts through the COM
}

TEST(WaterForces, LinearWaterKeepsPushingUpPastFullSubmergence) {
  // water.buoyancy = "linear" (an ablation): held 0.2 m under, the floe also carries the column of
  // water above its top face, rho g L^2 (depth of the top) = 162 N on top of its 2.04 N of reserve
  // buoyancy, through the COM; floating at its draft (top dry) it is the exact buoyancy
  const Floe floe;
  WaterParams p;
  p.linear_buoyancy = true;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  const Wrench under = water_wrench(floe.body, at_rest({4, -0.2, 1}), StillWater(), p, d);
  const double top_depth = 0.2 - kH / 2;
  EXPECT_NEAR(under.force.y() - floe.mass * p.gravity,
              (1000.0 - kRhoIce) * p.gravity * kL * kL * kH + 1000.0 * p.gravity * kL * kL * top_depth, 1e-9);
  EXPECT_NEAR(under.torque.norm(), 0.0, 1e-9);
  const Wrench afloat = water_wrench(floe.body, at_rest(floe.floating_com(7, -1)), StillWater(), p, d);
  EXPECT_NEAR(afloat.force.y(), floe.mass * p.gravity, 1e-12 * floe.mass * p.gravity);
}

TEST(WaterForces, FloeAtItsDraftIsInEquilibrium) {
  const Floe floe;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  const Wrench w = water_wrench(floe.body, at_rest(floe.floating_com(7, -1)), StillWater(), p, d);
  // round-off of the submerged volume (the draft is exact here)
  EXPECT_NEAR(w.force.y(), floe.mass * p.gravity, 1e-12 * floe.mass * p.gravity);
  EXPECT_NEAR(w.torque.norm(), 0.0, 1e-12);
}

TEST(WaterForces, HeeledFloeFeelsTheRightingMomentOfBuoyancy) {
  // docs/model/validation_targets.md §1: moment rho g V GM sin(phi), GM = L^2/(12 d) + d/2 - h/2
  const Floe floe;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  const double phi = 0.5 * kPi / 180;  // small enough that no edge emerges (< 0.88 deg)
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Wrench w = water_wrench(floe.body, at_rest(rot * floe.floating_com(), rot), StillWater(), p, d);
  const double gm = kL * kL / (12 * floe.draft) + floe.draft / 2 - kH / 2;
  const double expected = -floe.mass * p.gravity * gm * std::sin(phi);  // opposes the heel
  // small-angle formula; the exact wall-sided value differs by 4e-5 relative
  EXPECT_NEAR(w.torque.z(), expected, 1e-3 * std::abs(expected));
  EXPECT_NEAR(w.torque.x(), 0.0, 1e-12);
}

TEST(WaterForces, FloeTowedEdgeFirstFeelsFormDragPlusSkinFriction) {
  const Floe floe;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  BodyMotion m = at_rest(floe.floating_com(10, 0));
  m.linear_velocity = Eigen::Vector3d(kTow, 0, 0);
  const Wrench w = water_wrench(floe.body, m, StillWater(), p, d);

  // per face: form drag on the leading edge (L d); friction on the bottom (L^2) and on the
  // two edges parallel to the motion (2 L d); the trailing edge feels neither
  const double q = 0.5 * p.water_density * kTow * kTow;  // Pa, dynamic pressure
  const double f_form = q * p.drag_coefficient * kL * floe.draft;
  const double f_bottom = q * p.skin_friction_coefficient * kL * kL;
  const double f_edge = q * p.skin_friction_coefficient * kL * floe.draft;
  const double expected = f_form + f_bottom + 2 * f_edge;
  EXPECT_NEAR(w.force.x(), -expected, 1e-12 * expected);  // round-off
  EXPECT_NEAR(w.force.z(), 0.0, 1e-15);
  EXPECT_NEAR(w.force.y(), floe.mass * p.gravity, 1e-12 * floe.mass * p.gravity);
  // docs/model/validation_targets.md §5: form drag ~23 mN (22.6) and Blasius friction ~2.0 mN
  EXPECT_NEAR(f_form, 0.023, 0.0005);    // the sheet's rounding
  EXPECT_NEAR(f_bottom, 0.0020, 0.00005);

  // torque about z: each force acts at its face centroid, below the COM by
  // d/2 - (d - h/2) on the edges and h/2 at the bottom; the arm y r_y with force -f x gives
  // tau_z = r_y f
  const double edge_arm = -floe.draft / 2 - floe.floating_com().y();
  const double bottom_arm = -kH / 2;
  const double tau_z = (f_form + 2 * f_edge) * edge_arm + f_bottom * bottom_arm;
  EXPECT_NEAR(w.torque.z(), tau_z, 1e-12 * std::abs(tau_z));  // round-off
  EXPECT_NEAR(w.torque.x(), 0.0, 1e-15);
  EXPECT_NEAR(w.torque.y(), 0.0, 1e-15);
}

TEST(WaterForces, SpinningFloeFeelsFrictionTorqueFromItsEdgeCentroids) {
  // yaw rate omega on an Lx x Lz floe: each edge centroid moves tangentially at omega * arm,
  // so friction 1/2 rho C_f (edge area) (omega arm)^2 acts at that arm; no form drag, no net
  // force, and the bottom centroid does not move (faces are lumped at their centroids)
  const double lx = 0.3, lz = 0.2, omega = 0.5;
  const ConvexPolyhedron body = make_prism(rectangle(lx, lz), kH);
  const double mass = kRhoIce * lx * lz * kH;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(body, mass, 1e-3, p);
  const double draft = kRhoIce / 1000.0 * kH;
  BodyMotion m = at_rest({1, kH / 2 - draft, 2});
  m.angular_velocity = Eigen::Vector3d(0, omega, 0);
  const Wrench w = water_wrench(body, m, StillWater(), p, d);
  const double k = 0.5 * p.water_density * p.skin_friction_coefficient * draft * omega * omega;
  const double expected = -(2 * (lx / 2) * k * lz * std::pow(lx / 2, 2) +
                            2 * (lz / 2) * k * lx * std::pow(lz / 2, 2));
  EXPECT_NEAR(w.torque.y(), expected, 1e-12 * std::abs(expected));  // round-off
  EXPECT_NEAR(w.force.x(), 0.0, 1e-15);
  EXPECT_NEAR(w.force.z(), 0.0, 1e-15);
}

TEST(WaterForces, DragDependsOnlyOnVelocityRelativeToTheWater) {
  const Floe floe;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  const Eigen::Vector3d v(kTow, 0, -0.03);
  BodyMotion towed = at_rest(floe.floating_com());
  towed.linear_velocity = v;
  const Wrench in_still = water_wrench(floe.body, towed, StillWater(), p, d);

  // a current -v past a floe at rest drags it like towing through still water
  const Wrench in_current = water_wrench(floe.body, at_rest(floe.floating_com()), UniformFlow(-v), p, d);
  EXPECT_NEAR((in_current.force - in_still.force).norm(), 0.0, 1e-15);   // round-off
  EXPECT_NEAR((in_current.torque - in_still.torque).norm(), 0.0, 1e-15);
  EXPECT_GT(std::abs(in_still.force.x()), 0.01);  // and that drag is not zero (~30 mN)

  // a floe drifting with the current feels no drag
  const Wrench drifting = water_wrench(floe.body, towed, UniformFlow(v), p, d);
  EXPECT_NEAR(drifting.force.x(), 0.0, 1e-15);
  EXPECT_NEAR(drifting.force.z(), 0.0, 1e-15);
}

TEST(WaterForces, FloeAtTheConeShoulderIsDraggedBackwards) {
  // tank frame: the water at the shoulder moves at -V (flow_field.hpp), so a floe at rest
  // there is pushed against the towing direction
  const Floe floe;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  ConePotentialFlow flow({{-0.443, 0.171}, {0.0, 0.614}, {0.122, 0.736}});
  flow.set_structure({2, 0, 0}, {kTow, 0, 0});
  const Wrench w = water_wrench(floe.body, at_rest(floe.floating_com(2, 0.614 + kL / 2 + 0.01)), flow, p, d);
  EXPECT_LT(w.force.x(), 0.0);
}

TEST(WaterForces, FloePushedDownFeelsFormDragOnItsBottom) {
  const Floe floe;
  WaterParams p;
  p.skin_friction_coefficient = 0.0;
  p.heave_damping_ratio = 0.0;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  const double v = 0.05;
  BodyMotion m = at_rest(floe.floating_com());
  m.linear_velocity = Eigen::Vector3d(0, -v, 0);
  const Wrench down = water_wrench(floe.body, m, StillWater(), p, d);
  const double form = 0.5 * p.water_density * p.drag_coefficient * kL * kL * v * v;
  EXPECT_NEAR(down.force.y() - floe.mass * p.gravity, form, 1e-12);  // round-off
  // rising, the bottom retreats from the water: no form drag
  m.linear_velocity = Eigen::Vector3d(0, v, 0);
  const Wrench up = water_wrench(floe.body, m, StillWater(), p, d);
  EXPECT_NEAR(up.force.y() - floe.mass * p.gravity, 0.0, 1e-12);
}

TEST(WaterForces, DampingOpposesHeaveRollAndPitchInProportionToSubmersion) {
  const Floe floe;
  WaterParams p;
  p.drag_coefficient = 0.0;  // isolate the damping terms
  p.skin_friction_coefficient = 0.0;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  BodyMotion m = at_rest(floe.floating_com());
  m.linear_velocity = Eigen::Vector3d(0.02, 0.1, -0.03);
  m.angular_velocity = Eigen::Vector3d(0.2, 0.3, -0.4);
  const Wrench w = water_wrench(floe.body, m, StillWater(), p, d);
  const double weight = floe.mass * p.gravity;
  // round-off relative to the terms (the submerged fraction is 1 to 1e-12)
  EXPECT_NEAR(w.force.y(), weight - d.heave * 0.1, 1e-10);
  EXPECT_NEAR(w.force.x(), 0.0, 1e-15);
  EXPECT_NEAR(w.torque.x(), -d.roll_pitch * 0.2, 1e-12);
  EXPECT_NEAR(w.torque.y(), 0.0, 1e-15);  // yaw is not damped by this term
  EXPECT_NEAR(w.torque.z(), d.roll_pitch * 0.4, 1e-12);

  // half the displaced volume under water: half the damping
  m.pose.translation().y() += floe.draft / 2;
  const Wrench half = water_wrench(floe.body, m, StillWater(), p, d);
  EXPECT_NEAR(half.force.y(), 0.5 * weight - 0.5 * d.heave * 0.1, 1e-10);
  EXPECT_NEAR(half.torque.x(), -0.5 * d.roll_pitch * 0.2, 1e-12);
}

TEST(WaterForces, BodyOutOfTheWaterFeelsNothing) {
  const Floe floe;
  const WaterParams p;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  BodyMotion m = at_rest({0, 0.5, 0});
  m.linear_velocity = Eigen::Vector3d(0.1, -0.2, 0.1);
  m.angular_velocity = Eigen::Vector3d(1, 1, 1);
  const Wrench w = water_wrench(floe.body, m, UniformFlow({0.1, 0, 0}), p, d);
  EXPECT_EQ(w.force, Eigen::Vector3d::Zero());
  EXPECT_EQ(w.torque, Eigen::Vector3d::Zero());
}

TEST(WaterForces, DampingCoefficientsFollowFromMassAndWaterplane) {
  const Floe floe;
  WaterParams p;
  p.heave_damping_ratio = 0.5;
  p.roll_pitch_damping_ratio = 0.3;
  const DampingCoefficients d = damping_coefficients(floe.body, floe.mass, floe.inertia, p);
  const double rho_g = p.water_density * p.gravity;
  // round-off of the waterplane section
  EXPECT_NEAR(d.heave, 2 * 0.5 * std::sqrt(floe.mass * rho_g * kL * kL), 1e-12);
  EXPECT_NEAR(d.heave, 49.4, 0.05);  // 2.762 kg on 883 N/m (docs/model/validation_targets.md §1)
  EXPECT_NEAR(d.roll_pitch, 2 * 0.3 * std::sqrt(floe.inertia * rho_g * std::pow(kL, 4) / 12), 1e-12);
  EXPECT_NEAR(d.displaced_volume, floe.mass / p.water_density, 1e-18);

  // a yawed 0.3 x 0.15 outline: roll/pitch uses the smaller principal moment Lx Lz^3 / 12
  const double lx = 0.3, lz = 0.15, yaw = 0.4;
  std::vector<Eigen::Vector2d> outline;
  for (const Eigen::Vector2d& q : rectangle(lx, lz)) {
    outline.emplace_back(std::cos(yaw) * q.x() - std::sin(yaw) * q.y(),
                         std::sin(yaw) * q.x() + std::cos(yaw) * q.y());
  }
  const ConvexPolyhedron plate = make_prism(outline, kH);
  const double mass = kRhoIce * lx * lz * kH;
  const DampingCoefficients dp = damping_coefficients(plate, mass, 1e-4, p);
  EXPECT_NEAR(dp.roll_pitch, 2 * 0.3 * std::sqrt(1e-4 * rho_g * lx * std::pow(lz, 3) / 12), 1e-12);
  EXPECT_NEAR(dp.heave, 2 * 0.5 * std::sqrt(mass * rho_g * lx * lz), 1e-12);
}

}  // namespace
}  // namespace icedem
