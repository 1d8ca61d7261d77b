// The step-size warnings: silent for the paper's settings, and naming the
// substeps that would bring an over-large Bullet step back within the limits
// the stress suite measured (dem/input/step_size_advice.hpp).
#include <gtest/gtest.h>

#include <string>

#include "dem/input/scene_builder.hpp"
#include "dem/input/step_size_advice.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using icedem::testing::scene_from;

TEST(StepSizeAdvice, PaperSettingsNeedNoWarning) {
  // dt 0.02 s, 33 mm ice, 0.07 m/s: omega h = 0.36, 4 % of the thickness per step
  EXPECT_TRUE(step_size_warnings(scene_from("")).empty());
}

TEST(StepSizeAdvice, LargeStepWarnsThatFloatingFloesLoseAccuracyAndNamesTheSubsteps) {
  const auto w = step_size_warnings(scene_from("", {"time.dt=0.05"}));  // omega h = 0.89
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("time.substeps >= 2"), std::string::npos) << w[0];
  EXPECT_TRUE(step_size_warnings(scene_from("", {"time.dt=0.05", "time.substeps=2"})).empty());
}

TEST(StepSizeAdvice, FastTowWarnsThatIceIsPushedIntoTheHull) {
  const auto w = step_size_warnings(scene_from("", {"structure.speed=0.7"}));  // 42 % per step
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("42 %"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("time.substeps >= 4"), std::string::npos) << w[0];
  EXPECT_TRUE(step_size_warnings(scene_from("", {"structure.speed=0.7", "time.substeps=4"})).empty());
}

TEST(StepSizeAdvice, BeyondTheLargestSubstepCountItNamesTheTimeStep) {
  // 10 m/s with 1 mm ice: a Bullet step of 1.2e-5 s, 42,000 substeps at dt 0.5 s, more than
  // time.substeps allows (1000): the advice is a shorter time.dt instead
  const auto w = step_size_warnings(scene_from("", {"structure.speed=10", "ice.thickness=0.001", "time.dt=0.5"}));
  ASSERT_EQ(w.size(), 3u);  // accuracy, the damping's stability (omega h = 49) and the travel
  EXPECT_NE(w[2].find("time.dt <= 0.012 s with time.substeps = 1000"), std::string::npos) << w[2];
}

TEST(StepSizeAdvice, WaterDampingTheStepCannotIntegrateIsABlowUpWarned) {
  // damping ratio 10 at the paper's step: omega h = 0.36, (omega h)^2 + 4 zeta omega h = 14.4,
  // beyond semi-implicit Euler's bound of 4; at 4 substeps 3.6, within it
  const auto w = step_size_warnings(scene_from("", {"water.roll_pitch_damping_ratio=10"}));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("blow-up"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("time.substeps >= 4"), std::string::npos) << w[0];
  EXPECT_TRUE(step_size_warnings(scene_from("", {"water.roll_pitch_damping_ratio=10", "time.substeps=4"})).empty());
  // the bound itself: damping ratio 0.5 warns of accuracy (0.6) long before omega h = 1.24
  EXPECT_EQ(step_size_warnings(scene_from("", {"water.heave_damping_ratio=5"})).size(), 1u);  // 0.13 + 7.2
}

// Lattices of elements below 0.20 m at a Bullet step above 0.01 s break with the step (the
// 0.15 m squares' step study): warned, with the substeps; the 0.20 m squares, rigid floes and
// the 0.15 m paper and level-ice scenarios (two substeps each) are not
TEST(StepSizeAdvice, SmallElementsAtTheFullStepWarnThatBreaksMoveWithTheStep) {
  const auto w = step_size_warnings(scene_from("", {"fracture.mode=\"on\"", "fracture.element_size=0.15"}));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("break with the step"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("use time.substeps >= 2"), std::string::npos) << w[0];
  EXPECT_TRUE(step_size_warnings(
                  scene_from("", {"fracture.mode=\"on\"", "fracture.element_size=0.15", "time.substeps=2"}))
                  .empty());
  EXPECT_TRUE(step_size_warnings(scene_from("", {"fracture.mode=\"on\"", "ice.floe_size=0.6", "fracture.element_size=0.2"})).empty());
  EXPECT_TRUE(step_size_warnings(scene_from("", {"fracture.element_size=0.15"})).empty()) << "rigid floes";
  EXPECT_TRUE(step_size_warnings(load_scene(std::string(ICEDEM_SOURCE_DIR) +
                                            "/scenarios/paper/large_floes_breakable_015.toml"))
                  .empty());
  const std::string level = std::string(ICEDEM_SOURCE_DIR) + "/scenarios/level_ice/level_ice_015.toml";
  EXPECT_TRUE(step_size_warnings(load_scene(level)).empty()) << "the level sheet of 0.15 m elements runs two substeps";
  EXPECT_EQ(step_size_warnings(load_scene(level, {"time.substeps=1"})).size(), 1u)
      << "the level sheet at one step of 0.02 s";
}
