// Static against kinetic friction (dem/world/static_friction.hpp) on a block on a slope, whose
// answers are Coulomb's: a block at rest sticks while tan(angle) <= mu_s; once it slides it
// accelerates down the slope at g (sin a - mu_k cos a), whatever mu_s is; a block sliding on a
// slope flatter than mu_k slows at g (mu_k cos a - sin a), stops, and stays stopped.
// Each case runs with the default sweeps and with the accelerated projected gradient (the
// paper grid's method), which reads the coefficient off the rows the law set.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include <btBulletDynamicsCommon.h>

#include "dem/world/contact_solver.hpp"
#include "dem/world/static_friction.hpp"
#include "tests/support/box_world.hpp"

using icedem::ContactSolver;
using icedem::SolverSettings;
using icedem::StaticFriction;
using namespace icedem::testing;

namespace {

// a block shaped as a 0.3 m floe of the paper's 33 mm ice: half its side and thickness, m
constexpr double kHalf = 0.15, kHalfThickness = 0.0165;
constexpr double kMuK = 0.3;    // kinetic coefficient of block on slope
constexpr double kMuS = 0.45;   // static (1.5 mu_k, the ratio the managed-ice literature quotes)

struct Slide {
  double travel;       // m, down the slope, from the end of the settling on
  double speed;        // m/s, down the slope, at the end
  double last_second;  // m, travelled in the last second
};

// A 1 kg block on a slope of `angle_deg` with kinetic friction kMuK and static `mu_s` (0: none),
// solved by `method`, starting at `v0` down the slope. Measured after `settle` s (the block
// settling onto the face) for `seconds`.
Slide slide(const std::string& method, double angle_deg, double mu_s, double v0, double seconds, double settle = 0.4) {
  SolverSettings s = test_solver_settings();
  s.iterations = 200;
  s.tolerance = 1e-9;
  s.friction_warm_start = true;
  s.method = method;
  s.merit_tolerance = 1e-10;
  s.method_iterations = 2000;
  icedem::ContactLaw law;
  law.static_friction = StaticFriction{0.0, mu_s, 1e-3};
  auto solver = std::make_unique<ContactSolver>(s, law);
  ContactSolver* raw = solver.get();
  Bench bench(std::move(solver));
  const double angle = angle_deg * M_PI / 180.0;
  btTransform slope = at(0, 0, 0);
  slope.setRotation(btQuaternion(btVector3(0, 0, 1), angle));
  // slope as "the structure": its static coefficient is friction.ice_structure_static's
  // 20 m long: the fastest case slides 8.6 m
  btRigidBody* plane = bench.box({10.0, 0.05, 1.0}, slope, 0.0, kMuK, 2);
  raw->set_structure(plane);
  // up the slope, resting on its face: 0.5 mm into it, so that the contact is there in the first
  // step (a block dropped from touching would arrive with g sin(a) dt of slip, and slide)
  const btTransform pose = slope * at(9.0, 0.05 + kHalfThickness - 0.0005, 0);
  btRigidBody* block = bench.box({kHalf, kHalfThickness, kHalf}, pose, 1.0, 1.0, 1);
  // down the slope: -x of the slope's frame
  const btVector3 down = slope.getBasis() * btVector3(-1, 0, 0);
  block->setLinearVelocity(down * v0);
  auto run = [&](double t) {
    for (long k = std::lround(t / kDt); k > 0; --k) bench.world().stepSimulation(kDt, 0);
  };
  run(settle);
  const btVector3 start = block->getWorldTransform().getOrigin();
  run(seconds - 1.0);
  const btVector3 before_last = block->getWorldTransform().getOrigin();
  run(1.0);
  const btVector3 end = block->getWorldTransform().getOrigin();
  return {(end - start).dot(down), block->getLinearVelocity().dot(down), (end - before_last).dot(down)};
}

double sliding_acceleration(double angle_deg) {
  const double a = angle_deg * M_PI / 180.0;
  return kGravity * (std::sin(a) - kMuK * std::cos(a));
}

class StaticFrictionOnASlope : public ::testing::TestWithParam<std::string> {};

// tan 20 deg = 0.364: above mu_k, below mu_s
TEST_P(StaticFrictionOnASlope, BlockAtRestSticksBelowTheStaticAngle) {
  const Slide held = slide(GetParam(), 20.0, kMuS, 0.0, 5.0);
  const Slide control = slide(GetParam(), 20.0, 0.0, 0.0, 5.0);  // kinetic friction alone
  std::printf("%s, 20 deg, 5 s: with mu_s travel %.3g m; mu_k alone %.3g m at %.3f m/s (Coulomb %.3f)\n",
              GetParam().c_str(), held.travel, control.travel, control.speed, 5.4 * sliding_acceleration(20.0));
  // 0.1 mm over 5 s: a creep of 2e-5 m/s, fifty times below the stick speed
  EXPECT_LT(std::abs(held.travel), 1e-4);
  // the same block with one coefficient slides: the static coefficient is what holds it.
  // It has been sliding since the start (0.4 s before the measurement), so its speed at the
  // end is a (5.4 s) less what it gained before settling; 2 % covers the first steps' settling
  EXPECT_NEAR(control.speed, 5.4 * sliding_acceleration(20.0), 0.02 * 5.4 * sliding_acceleration(20.0));
}

// tan 30 deg = 0.577: above mu_s. It breaks away and then slides on mu_k, not mu_s
TEST_P(StaticFrictionOnASlope, BlockAboveTheStaticAngleSlidesWithTheKineticCoefficient) {
  const Slide s = slide(GetParam(), 30.0, kMuS, 0.0, 2.0);
  const double kinetic = 2.4 * sliding_acceleration(30.0);
  const double at_static = 2.4 * 9.81 * (std::sin(M_PI / 6) - kMuS * std::cos(M_PI / 6));
  std::printf("%s, 30 deg, 2.4 s from rest: %.4f m/s; Coulomb with mu_k %.4f, with mu_s %.4f\n", GetParam().c_str(),
              s.speed, kinetic, at_static);
  // 2 %: the first step from rest has the static coefficient (the block starts at rest), which
  // takes g (mu_s - mu_k) cos a dt = 0.025 m/s off of 5.1: 0.5 %
  EXPECT_NEAR(s.speed, kinetic, 0.02 * kinetic);
}

// tan 10 deg = 0.176: below mu_k. Pushed down at 0.3 m/s it slows at g (mu_k cos a - sin a)
// = 1.17 m/s^2, stops after about v0^2 / (2 decel) = 38 mm and stays put
TEST_P(StaticFrictionOnASlope, SlidingBlockStopsAndSticks) {
  const Slide s = slide(GetParam(), 10.0, kMuS, 0.3, 3.0, 0.0);
  const double a = 10.0 * M_PI / 180.0;
  const double decel = kGravity * (kMuK * std::cos(a) - std::sin(a));
  // Bullet's integration (velocity first, then position with the new velocity) over steps of
  // 0.02 s: the stop falls short of the continuous v0^2 / (2 decel) by about v0 dt / 2
  double stop = 0;
  for (double v = 0.3 - decel * kDt; v > 0; v -= decel * kDt) stop += v * kDt;
  std::printf("%s, 10 deg from 0.3 m/s: stopped after %.4f m (Coulomb with mu_k %.4f m, %.4f m continuous), "
              "last second %.3g m\n",
              GetParam().c_str(), s.travel, stop, 0.3 * 0.3 / (2 * decel), s.last_second);
  // 2 %: with mu_s in place of mu_k over the last step it would stop 0.2 mm (0.6 %) sooner,
  // with mu_s throughout 13 mm (38 %) sooner
  EXPECT_NEAR(s.travel, stop, 0.02 * stop);
  EXPECT_LT(std::abs(s.last_second), 1e-4);
  EXPECT_LT(std::abs(s.speed), 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Methods, StaticFrictionOnASlope, ::testing::Values("pgs", "apgd"));

TEST(StaticFriction, CoefficientOfAContact) {
  const StaticFriction law{0.6, 0.3, 1e-3};
  // sticking: the pair's static coefficient; slipping (at the stick speed or faster): the kinetic
  EXPECT_EQ(icedem::contact_friction(law, 0.5, false, 0.0), 0.6);
  EXPECT_EQ(icedem::contact_friction(law, 0.2, true, 0.9e-3), 0.3);
  EXPECT_EQ(icedem::contact_friction(law, 0.5, false, 1e-3), 0.5);
  // a static coefficient of 0 is none; one below a contact's kinetic does not lower it
  EXPECT_EQ(icedem::contact_friction(StaticFriction{0.0, 0.3, 1e-3}, 0.5, false, 0.0), 0.5);
  EXPECT_EQ(icedem::contact_friction(law, 0.7, false, 0.0), 0.7);
}

}  // namespace
