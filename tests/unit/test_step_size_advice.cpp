// The step-size warnings: silent for the paper's settings, and naming the
// substeps that would bring an over-large Bullet step back within the limits
// the stress suite measured (dem/step_size_advice.hpp).
#include <gtest/gtest.h>

#include "dem/step_size_advice.hpp"
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
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[1].find("time.dt <= 0.012 s with time.substeps = 1000"), std::string::npos) << w[1];
}
