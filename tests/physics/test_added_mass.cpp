// The water's added mass (water.added_mass, dem/water/added_mass.hpp) in the real Bullet world:
// a floe's free heave oscillation has the period of its mass plus the added mass, its equilibrium
// does not move, and the contact solve sees the same larger mass Bullet's own sweeps do.
// References: ../docs/model/validation_targets.md §1: the heave period without added mass is
// 2 pi sqrt(rho_i h / (rho_w g)) = 0.351 s for any size; with a33 it is 2 pi sqrt((m + a33) / C33).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dem/core/constants.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/water/added_mass.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using icedem::testing::bench_scene;
using icedem::testing::square_floe;

namespace {

// The period of a floe's free heave, released 1 mm below its equilibrium without damping (within its
// 2.3 mm freeboard: beyond it the top goes under and the restoring force stops growing): the mean
// spacing of the upward crossings of its equilibrium height over the first oscillations
double heave_period(const Scene& scene, double side) {
  State state = initial_state(scene, {square_floe(10, 0, side)});
  btRigidBody& body = *state.world->floes()[0].body;
  const double rest = body.getCenterOfMassPosition().y();
  btTransform t = body.getWorldTransform();
  t.getOrigin() -= btVector3(0, 0.001, 0);
  body.setWorldTransform(t);
  std::vector<double> up;  // s, times of upward crossings (interpolated within the step)
  double last = -0.001;
  while (state.time < 6.0 && up.size() < 6) {
    step(scene, state);
    const double y = body.getCenterOfMassPosition().y() - rest;
    if (last < 0 && y >= 0) up.push_back(state.time - scene.time.dt * y / (y - last));
    last = y;
  }
  if (up.size() < 3) return NAN;
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

const std::vector<std::string> kUndamped{"water.heave_damping_ratio=0", "water.roll_pitch_damping_ratio=0",
                                         "water.drag_coefficient=0", "water.skin_friction_coefficient=0"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST(AddedMass, TheCoefficientsAreThoseOfADiscOfEqualArea) {
  // a 0.6 m floe: a = 0.3385 m, m_a = 51.7 kg (DNV's square plate, C_A 0.579: 49.1 kg, 5 % less)
  const AddedMass a = plate_added_mass(0.36, 1000.0);
  EXPECT_NEAR(a.heave, 4.0 / 3.0 * 1000.0 * std::pow(0.6 / std::sqrt(kPi), 3), 1e-9);
  EXPECT_NEAR(a.heave, 0.5 * 1000 * 0.579 * kPi / 4 * 0.216, 0.06 * a.heave);
  // four elements share a 2 x 2 lattice's heave added mass by area
  const AddedMass e = element_added_mass(a, 0.36, 0.09);
  EXPECT_NEAR(4 * e.heave, a.heave, 1e-12);
}

TEST(AddedMass, WithoutItTheHeavePeriodIsTheFloesOwn) {
  // 0.351 s whatever the size; 3 %: the semi-implicit step (17 steps a period) shortens it a little
  const double expected = 2 * kPi * std::sqrt(930.0 * 0.033 / (1000.0 * 9.81));
  EXPECT_NEAR(heave_period(bench_scene(kUndamped), 0.6), expected, 0.03 * expected);
}

TEST(AddedMass, WithItTheHeavePeriodIsOfTheMassPlusTheAddedMass) {
  const Scene scene = bench_scene(with(kUndamped, {"water.added_mass=true"}));
  for (const double side : {0.3, 0.6}) {
    const double area = side * side, m = area * 0.033 * 930.0;
    const double a33 = plate_added_mass(area, 1000.0).heave;
    const double expected = 2 * kPi * std::sqrt((m + a33) / (1000.0 * 9.81 * area));  // 0.64 s and 0.84 s
    // 2 %: 30-40 steps a period
    EXPECT_NEAR(heave_period(scene, side), expected, 0.02 * expected) << side << " m floe";
  }
}

TEST(AddedMass, TheEquilibriumDoesNotMove) {
  // gravity and buoyancy are scaled alike: a floe released 10 mm high settles at Archimedes' draft
  const Scene scene = bench_scene({"water.added_mass=true"});
  State state = initial_state(scene, {square_floe(10, 0, 0.6)});
  btRigidBody& body = *state.world->floes()[0].body;
  btTransform t = body.getWorldTransform();
  t.getOrigin() += btVector3(0, 0.010, 0);
  body.setWorldTransform(t);
  while (state.time < 20.0) step(scene, state);
  EXPECT_NEAR(scene.ice.thickness / 2 - body.getCenterOfMassPosition().y(), 0.033 * 930.0 / 1000.0, 1e-5);
}

// A floe dropped on another, both with added mass: the contact solve that works on the problem
// (the accelerated projected gradient, to 1e-8) and Bullet's own sweeps (PGS, 1000 a step) see the
// same masses, so they give the same motion. Without the added mass in the problem, the stacked floe
// would rebound off a lower floe five times lighter than Bullet moves it
TEST(AddedMass, TheContactSolveSeesTheMassBulletsSweepsSee) {
  std::vector<double> heights[2];
  const std::vector<std::string> methods[2] = {
      {"solver.method=apgd", "solver.merit_tolerance=1e-8", "solver.method_iterations=100000"},
      {"solver.method=pgs", "solver.tolerance=0", "solver.iterations=1000"}};
  for (int k = 0; k < 2; ++k) {
    const Scene scene = bench_scene(with(methods[k], {"water.added_mass=true"}));
    Floe upper = square_floe(10, 0, 0.6);
    upper.layer = 1;
    State state = initial_state(scene, {square_floe(10.1, 0, 0.6), upper});
    btRigidBody& top = *state.world->floes()[1].body;
    btTransform t = top.getWorldTransform();
    t.getOrigin() += btVector3(0, 0.02, 0);  // dropped from 2 cm
    top.setWorldTransform(t);
    for (int i = 0; i < 100; ++i) {
      step(scene, state);
      heights[k].push_back(top.getCenterOfMassPosition().y());
    }
  }
  double largest = 0;
  for (std::size_t i = 0; i < heights[0].size(); ++i) largest = std::max(largest, std::abs(heights[0][i] - heights[1][i]));
  // 0.1 mm over 2 s: the two methods' answers at their tolerances, not a factor of five in mass
  EXPECT_LT(largest, 1e-4);
}
