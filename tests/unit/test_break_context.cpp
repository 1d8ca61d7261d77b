// The classification of breaks into mechanisms and the distance from the
// structure (dem/fracture/break_context.hpp), on hand-made contexts.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "dem/fracture/break_context.hpp"
#include "dem/world/cone_geometry.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;

namespace {
constexpr double kH = 0.033;  // m, the paper's ice thickness

BreakContext context(bool touching, double depth, double press_down, double press_toward) {
  BreakContext c;
  c.touching_structure = touching;
  c.depth = depth;
  c.press_down = press_down;
  c.press_toward = press_toward;
  return c;
}
}  // namespace

TEST(BreakMechanism, TouchingTheStructureIsOnTheSlopeUnlessSubmergedAndPressed) {
  // afloat, the midpoint of a 33 mm floe is 0.43 h = 14 mm deep: on the slope even when pressed
  EXPECT_EQ(classify_break(context(true, 0.014, 50, 50), kH), BreakMechanism::kOnSlope);
  // deep (riding down the slope) but nothing presses it: on the slope
  EXPECT_EQ(classify_break(context(true, 0.2, 0, 0), kH), BreakMechanism::kOnSlope);
  EXPECT_EQ(classify_break(context(true, 0.2, 0.5 * kPressingForce, 0.4 * kPressingForce), kH),
            BreakMechanism::kOnSlope);
  // deep and pressed from above, or from behind: pressed under
  EXPECT_EQ(classify_break(context(true, 0.2, 2 * kPressingForce, 0), kH), BreakMechanism::kPressedUnder);
  EXPECT_EQ(classify_break(context(true, kH, 0, 2 * kPressingForce), kH), BreakMechanism::kPressedUnder);
}

TEST(BreakMechanism, AwayFromTheStructureIsInOrUnderThePack) {
  EXPECT_EQ(classify_break(context(false, 0.014, 50, 50), kH), BreakMechanism::kInPack);
  EXPECT_EQ(classify_break(context(false, 0.1, 0, 0), kH), BreakMechanism::kInRubble);
}

TEST(BreakMechanism, EveryMechanismHasItsOwnName) {
  std::set<std::string> names;
  for (int m = 0; m < kBreakMechanisms; ++m) names.insert(break_mechanism_name(static_cast<BreakMechanism>(m)));
  EXPECT_EQ(names.size(), static_cast<std::size_t>(kBreakMechanisms));
  EXPECT_EQ(names.count("unknown"), 0u);
}

TEST(DistanceFromStructure, IsMeasuredToTheSectionAtThePointsHeight) {
  // the default structure: the paper's 45-degree cone, its radius shrinking with depth
  const Scene scene = icedem::testing::scene_from("");
  const Eigen::Vector3d axis(2.0, 0.0, 0.0);
  const double r0 = profile_radius(scene.structure.profile, 0.0);
  // on the waterline, 0.5 m outside the section
  EXPECT_NEAR(distance_from_structure(scene, axis, axis + Eigen::Vector3d(0, 0, r0 + 0.5)), 0.5, 1e-12);
  // 0.1 m deep, at the waterline radius: the 45-degree section is 0.1 m narrower there
  EXPECT_NEAR(distance_from_structure(scene, axis, axis + Eigen::Vector3d(r0, -0.1, 0)), 0.1, 1e-9);
  // inside: 0
  EXPECT_EQ(distance_from_structure(scene, axis, axis + Eigen::Vector3d(0.5 * r0, 0, 0)), 0.0);
}
