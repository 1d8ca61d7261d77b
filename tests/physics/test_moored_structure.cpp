// The moored structure (structure.motion = "moored", dem/mooring/): free decay in still water in heave,
// pitch and surge against the periods the stiffness, mass and added mass give, and the damping against
// the ratio set; the static offset under a steady pull against the mooring's stiffness (linear and
// catenary); the body's derived mass, centre of gravity and inertia against the hull's own; and a
// towed scene that the moored code leaves untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dem/core/constants.hpp"
#include "dem/mooring/floating_structure.hpp"
#include "dem/mooring/structure_motion.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/water/hull_hydrostatics.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using icedem::testing::bench_scene;

namespace {

std::vector<std::string> moored(std::vector<std::string> extra = {}) {
  std::vector<std::string> keys{"structure.motion=\"moored\"", "structure.start_x=0", "time.dt=0.01"};
  keys.insert(keys.end(), extra.begin(), extra.end());
  return keys;
}

// A free decay through the run's own step(): the structure, alone in still water, set off its rest
// by `kick` (which moves the state), stepped for `duration` s; the coordinate `read` returns, sampled
// every step
struct Decay {
  std::vector<double> t, y;
};
template <typename Kick, typename Read>
Decay free_decay(const Scene& scene, Kick kick, Read read, double duration) {
  State state = initial_state(scene, {});
  kick(state);
  Decay d;
  while (state.time < duration) {
    step(scene, state);
    d.t.push_back(state.time);
    d.y.push_back(read(state));
  }
  return d;
}

// the mean period between upward crossings of `mean`, interpolated within the step
double period(const Decay& d, double mean = 0) {
  std::vector<double> up;
  for (std::size_t i = 1; i < d.y.size(); ++i)
    if (d.y[i - 1] < mean && d.y[i] >= mean)
      up.push_back(d.t[i] - (d.t[i] - d.t[i - 1]) * (d.y[i] - mean) / (d.y[i] - d.y[i - 1]));
  if (up.size() < 3) return NAN;
  return (up.back() - up.front()) / static_cast<double>(up.size() - 1);
}

// the damping ratio from the decay of successive maxima (logarithmic decrement)
double damping_ratio(const Decay& d) {
  std::vector<double> peaks;
  for (std::size_t i = 1; i + 1 < d.y.size(); ++i)
    if (d.y[i] > d.y[i - 1] && d.y[i] >= d.y[i + 1] && d.y[i] > 0) peaks.push_back(d.y[i]);
  if (peaks.size() < 3) return NAN;
  const double delta = std::log(peaks.front() / peaks.back()) / static_cast<double>(peaks.size() - 1);
  return delta / std::sqrt(4 * kPi * kPi + delta * delta);
}

}  // namespace

TEST(FloatingStructure, TheDefaultConeFloatsAtItsWaterlineWithTheHullsOwnInertia) {
  const Scene scene = bench_scene(moored());
  const FloatingStructure b = make_floating_structure(scene);
  const HullHydrostatics h = hull_hydrostatics(scene.structure.profile);
  // mass 0: the displaced water, so it rests where it started (the mooring's springs unstretched)
  EXPECT_NEAR(b.mass, scene.water.density * h.volume, 1e-9);
  EXPECT_NEAR(b.rest_heave, 0.0, 1e-9);
  // the uniform solid of the profile, by hand (frustum sums): centroid -0.05662 m, I/m 0.10048 and 0.16446 m^2;
  // the key's default centre of gravity is that centroid, to its 5 decimals
  const HullSolid solid = hull_solid(scene.structure.profile);
  EXPECT_NEAR(solid.centroid_y, -0.056618, 1e-6);
  EXPECT_NEAR(b.gravity_centre_y, solid.centroid_y, 5e-6);
  EXPECT_NEAR(b.inertia.x() / b.mass, 0.100479, 1e-5);
  EXPECT_NEAR(b.inertia.y() / b.mass, 0.164461, 1e-5);
  // the added-mass estimate: surge the displaced water, heave (4/3) rho a^3 with a = 0.614 m
  EXPECT_NEAR(b.added_mass.x(), b.mass, 1e-6 * b.mass);
  EXPECT_NEAR(b.added_mass.y(), 4.0 / 3.0 * 1000 * std::pow(0.614, 3), 1e-6);
  EXPECT_EQ(b.added_inertia.y(), 0.0);
  // the heave stiffness at rest is the waterplane's
  EXPECT_NEAR(b.heave_stiffness, 1000 * 9.81 * kPi * 0.614 * 0.614, 1e-6);
}

TEST(FloatingStructure, AHeavierStructureRestsDeeperWhereItsBuoyancyHoldsIt) {
  const Scene scene = bench_scene(moored({"structure.mass=260", "mooring.stiffness=[935, 0, 935]"}));
  const FloatingStructure b = make_floating_structure(scene);
  EXPECT_LT(b.rest_heave, 0.0);
  EXPECT_NEAR(hull_buoyancy(scene, b.rest_heave), 260 * scene.water.gravity, 1e-6);
}

TEST(FloatingStructure, AnUnstableCentreOfGravityIsRefused) {
  // G above the metacentre (KB + BM: 0.325 m above the waterline)
  EXPECT_THROW(make_floating_structure(bench_scene(moored({"structure.gravity_centre_y=0.4"}))), std::invalid_argument);
}

TEST(MooredStructure, HeaveDecaysAtThePeriodOfItsMassAddedMassAndWaterplane) {
  // undamped: T = 2 pi sqrt((m + a33) / (rho g A_wp)); the exact buoyancy of the 45-degree hull
  // stiffens by 2 dr / r = 0.3 % at the 1 mm offset's crest and softens as much at its trough, and
  // the semi-implicit step's period error is (w h)^2 / 24 = 0.01 %: 0.5 %
  const Scene scene = bench_scene(moored({"structure.damping_ratio=[0, 0, 0]", "structure.angular_damping_ratio=[0, 0, 0]"}));
  const FloatingStructure b = make_floating_structure(scene);
  const double expected = 2 * kPi * std::sqrt((b.mass + b.added_mass.y()) / b.heave_stiffness);
  const Decay d = free_decay(scene, [](State& s) { s.structure_position.y() -= 0.001; },
                             [](const State& s) { return s.structure_position.y(); }, 8.0);
  EXPECT_NEAR(period(d), expected, 0.005 * expected);
}

TEST(MooredStructure, HeaveDampsAtTheRatioSet) {
  // the implicit damping of the step shifts the ratio by about w h / 2 of itself (2 %): 5 %
  const Scene scene = bench_scene(moored({"structure.damping_ratio=[0.05, 0.05, 0.05]"}));
  const Decay d = free_decay(scene, [](State& s) { s.structure_position.y() -= 0.001; },
                             [](const State& s) { return s.structure_position.y(); }, 6.0);
  EXPECT_NEAR(damping_ratio(d), 0.05, 0.05 * 0.05);
}

TEST(MooredStructure, PitchDecaysAtThePeriodOfItsInertiaAndMetacentricHeight) {
  // T = 2 pi sqrt((I + I_a) / (rho g V GM)), no mooring: the linear restoring is exact by
  // construction, the step's error (w h)^2 / 24 = 0.01 %, the gyroscopic terms left out zero in a
  // plane motion: 0.5 %
  const Scene scene = bench_scene(moored({"structure.angular_damping_ratio=[0, 0, 0]", "structure.damping_ratio=[0, 0, 0]",
                                          "mooring.stiffness=[0, 0, 0]", "mooring.angular_stiffness=[0, 0, 0]"}));
  const FloatingStructure b = make_floating_structure(scene);
  const double expected = 2 * kPi * std::sqrt((b.inertia.z() + b.added_inertia.z()) / b.tilt_stiffness);
  const Decay d = free_decay(scene, [](State& s) { s.structure_motion.rotation.z() = 0.01; },
                             [](const State& s) { return s.structure_motion.rotation.z(); }, 8.0);
  EXPECT_NEAR(period(d), expected, 0.005 * expected);
}

TEST(MooredStructure, SurgeDecaysAtThePeriodOfItsMooringAndDampsAtTheRatioSet) {
  // the centre of gravity at the attachment's height, so surge does not pitch: T = 2 pi sqrt((m + a11) / k)
  const Scene undamped = bench_scene(moored({"structure.gravity_centre_y=0", "structure.damping_ratio=[0, 0, 0]"}));
  const FloatingStructure b = make_floating_structure(undamped);
  const double expected = 2 * kPi * std::sqrt((b.mass + b.added_mass.x()) / undamped.mooring.stiffness.x());
  const auto kick = [](State& s) { s.structure_position.x() += 0.01; };
  const auto surge = [x0 = b.start.x()](const State& s) { return s.structure_position.x() - x0; };
  EXPECT_NEAR(period(free_decay(undamped, kick, surge, 20.0)), expected, 0.005 * expected);
  const Scene damped = bench_scene(moored({"structure.gravity_centre_y=0", "structure.damping_ratio=[0.05, 0.05, 0.05]"}));
  EXPECT_NEAR(damping_ratio(free_decay(damped, kick, surge, 20.0)), 0.05, 0.05 * 0.05);
}

TEST(MooredStructure, ASteadyPullOffsetsItByTheForceOverTheMooringsStiffness) {
  // F / k to the step's convergence (1e-6 of the offset) with the linear mooring
  const Scene scene = bench_scene(moored({"structure.gravity_centre_y=0"}));
  const FloatingStructure b = make_floating_structure(scene);
  Eigen::Vector3d reference = b.start;
  StructureMotionState m;
  const Eigen::Vector3d pull(10.0, 0, 0);
  for (int i = 0; i < 20000; ++i) advance_structure(scene, b, 0.01, 0.0, reference, m, pull);
  EXPECT_NEAR(reference.x() - b.start.x(), 10.0 / 935.0, 1e-6 * 10.0 / 935.0);
  EXPECT_NEAR(mooring_load_at(scene, b, reference, m, 0.0).force.x(), -10.0, 1e-5);
}

TEST(MooredStructure, ASteadyPullOnCatenaryLinesIsHeldByTheirTension) {
  // the lines' horizontal pull balances the steady force where it comes to rest, and a small pull's
  // offset is the force over the spread's stiffness (the lines' Jacobian at rest, by central
  // differences): within 2 %, the change of that stiffness over the offset
  const Scene scene = bench_scene(moored({"mooring.model=\"catenary\"", "structure.gravity_centre_y=0"}));
  const FloatingStructure b = make_floating_structure(scene);
  const DiagonalStiffness k = mooring_stiffness(*b.mooring, b.start);
  ASSERT_GT(k.linear.x(), 0);
  Eigen::Vector3d reference = b.start;
  StructureMotionState m;
  const Eigen::Vector3d pull(10.0, 0, 0);
  for (int i = 0; i < 20000; ++i) advance_structure(scene, b, 0.01, 0.0, reference, m, pull);
  EXPECT_NEAR(mooring_load_at(scene, b, reference, m, 0.0).force.x(), -10.0, 1e-4);
  EXPECT_NEAR(reference.x() - b.start.x(), 10.0 / k.linear.x(), 0.02 * 10.0 / k.linear.x());
}

TEST(MooredStructure, TheCarriageDrawsTheMooredStructureAlongAtItsSpeed) {
  // with no ice the structure, started at the carriage's speed, follows its attachment where it is: the
  // damping acts on the motion about the carriage's, and the hull's steady resistance is not modelled
  // (1e-9 m: round-off over 6,000 steps)
  const Scene scene = bench_scene(moored({"structure.speed=0.07"}));
  const FloatingStructure b = make_floating_structure(scene);
  State state = initial_state(scene, {});
  while (state.time < 60.0) step(scene, state);
  const double carriage = b.start.x() + 0.07 * state.time;
  EXPECT_NEAR(state.structure_velocity.x(), 0.07, 1e-9);
  EXPECT_NEAR(state.structure_position.x() - carriage, 0.0, 1e-9);
}
