// The floes' loads on the analytic sheet's edge as load patches (dem/fracture/sheet_floe_load.hpp): one patch per
// floe at the outline, its axis the sheet's inward normal, its width its points' spread along the edge, its
// bending force the vertical force it puts on the sheet, a piece's corner a patch a thickness wide that breaks off
// pieces; a load farther in than a thickness left out. And the
// forces read from Bullet's contacts: a block at rest on a prism puts its weight on it.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/fracture/sheet_breaking.hpp"
#include "dem/fracture/sheet_floe_load.hpp"
#include "tests/support/box_world.hpp"

namespace icedem {
namespace {

const double kThickness = 0.033;
// the sheet x >= 0 (a straight edge along z at x = 0, the ice towards +x)
const Polygon kSheet = make_ccw({{0, -5}, {10, -5}, {10, 5}, {0, 5}});

SheetLoadPoint push(double x, double z, const Eigen::Vector3d& force, int floe) {
  return SheetLoadPoint{Eigen::Vector2d(x, z), force, floe};
}

// A floe pressing on the edge at two points 0.2 m apart: one patch centred between them on the edge, its axis into
// the sheet, half-width 0.1 m, bending force the vertical forces' sum, horizontal force its push into the sheet.
// Exact arithmetic: 1e-12
TEST(SheetFloeLoad, AFloePressingOnTheEdgeIsOnePatch) {
  const std::vector<SheetLoadPoint> points = {push(0.0, 0.1, {3.0, -2.0, 0.0}, 7),
                                              push(0.0, -0.1, {3.0, -2.0, 0.0}, 7)};
  const FloePatches out = floe_patches(kSheet, points, kThickness);
  ASSERT_EQ(out.patches.size(), 1u);
  EXPECT_EQ(out.floes[0], 7);
  const SheetContact& c = out.patches[0];
  EXPECT_NEAR(c.centre.x(), 0.0, 1e-12);
  EXPECT_NEAR(c.centre.y(), 0.0, 1e-12);
  EXPECT_NEAR(c.direction.x(), 1.0, 1e-12);
  EXPECT_NEAR(c.half_width, 0.1, 1e-12);
  EXPECT_NEAR(c.bending_force, 4.0, 1e-12);
  EXPECT_NEAR(c.horizontal_force, 6.0, 1e-12);
  EXPECT_EQ(out.interior_vertical, 0.0);
}

// Two floes are two patches, in the order of the floes; a load under the sheet within a thickness of its edge is
// at the edge, one farther in is an interior load and is left out (its vertical force summed apart)
TEST(SheetFloeLoad, EachFloeIsItsOwnPatchAndInteriorLoadsAreLeftOut) {
  const std::vector<SheetLoadPoint> points = {push(0.5 * kThickness, 1.0, {0.0, 5.0, 0.0}, 9),
                                              push(0.0, -1.0, {1.0, 0.0, 0.0}, 2),
                                              push(3 * kThickness, 2.0, {0.0, -1.5, 0.0}, 4)};
  const FloePatches out = floe_patches(kSheet, points, kThickness);
  ASSERT_EQ(out.patches.size(), 2u);
  EXPECT_EQ(out.floes[0], 2);
  EXPECT_EQ(out.floes[1], 9);
  EXPECT_NEAR(out.patches[1].centre.x(), 0.0, 1e-12);  // taken to the edge
  EXPECT_NEAR(out.patches[1].centre.y(), 1.0, 1e-12);
  EXPECT_NEAR(out.patches[1].bending_force, 5.0, 1e-12);  // up or down, the magnitude
  EXPECT_NEAR(out.patches[0].bending_force, 0.0, 1e-12);
  EXPECT_NEAR(out.interior_vertical, 1.5, 1e-12);
}

// A piece touching the straight edge at one point (its corner): the patch is a thickness wide, not a point, and the
// cut its load makes breaks off ice as a load on a plate's edge does, pieces at least a thickness across, where a
// point patch's wedge failed at the load (its crack a few millimetres out) and broke off nothing: the sheet stood
// while the piece, locked against the cone, bore it without bound. The paper's ice (Table 3); 1e-12 exact arithmetic
TEST(SheetFloeLoad, APieceTouchingAtACornerLoadsAPatchAThicknessWide) {
  const std::vector<SheetLoadPoint> points = {push(0.0, 0.4, {2.0, -30.0, 0.0}, 5)};
  const FloePatches out = floe_patches(kSheet, points, kThickness);
  ASSERT_EQ(out.patches.size(), 1u);
  const SheetContact& c = out.patches[0];
  EXPECT_NEAR(c.half_width, kLeastPatch * kThickness / 2, 1e-12);
  const SheetIce ice{kThickness, 60e6, 0.33, 36.4e3, 1000.0, 9.81};
  const SheetBreakPlan plan = plan_sheet_break(kSheet, c, ice);
  EXPECT_GT(plan.crack_distance, kThickness) << "the crack lies farther out than the ice is thick";
  const SheetCut cut = cut_sheet(kSheet, c, plan, kThickness);
  ASSERT_FALSE(cut.pieces.empty()) << "the load breaks ice off the sheet";
  for (const Polygon& piece : cut.pieces) EXPECT_GE(min_width(piece), kThickness) << "a piece, not crushed ice";
}

// At a corner of the sheet the axis is the corner's bisector, into the ice
TEST(SheetFloeLoad, AtACornerTheAxisBisectsIt) {
  const std::vector<SheetLoadPoint> points = {push(-0.01, -5.01, {1.0, 1.0, 1.0}, 1)};
  const FloePatches out = floe_patches(kSheet, points, kThickness);
  ASSERT_EQ(out.patches.size(), 1u);
  EXPECT_NEAR(out.patches[0].direction.x(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(out.patches[0].direction.y(), std::sqrt(0.5), 1e-12);
}

// A 2 kg block resting on a fixed prism (Bullet's own solver, 1 s to settle): the forces read from the contacts
// put its weight on the prism, down, at points on the prism's top face. 1e-6: a resting contact's impulse balances
// gravity to the solver's round-off
TEST(SheetFloeLoad, ABlockAtRestPutsItsWeightOnThePrism) {
  testing::Bench bench(std::make_unique<btSequentialImpulseConstraintSolver>());
  const btRigidBody* prism = bench.box({1.0, 0.05, 1.0}, testing::at(0, -0.05, 0), 0.0, 0.5, 3);
  btRigidBody* block = bench.box({0.1, 0.02, 0.1}, testing::at(0.3, 0.02, 0.2), 2.0, 0.5, 1);
  block->setUserIndex2(5);
  for (int i = 0; i < 50; ++i) bench.world().stepSimulation(testing::kDt, 1, testing::kDt);
  const std::vector<SheetLoadPoint> points =
      floe_loads_on_prisms(*bench.world().getDispatcher(), {prism}, testing::kDt);
  ASSERT_FALSE(points.empty());
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (const SheetLoadPoint& p : points) {
    total += p.force;
    EXPECT_EQ(p.floe, 5);
    EXPECT_NEAR(p.at.x(), 0.3, 0.1 + 1e-3);
    EXPECT_NEAR(p.at.y(), 0.2, 0.1 + 1e-3);
  }
  EXPECT_NEAR(total.y(), -2.0 * testing::kGravity, 1e-6 * 2.0 * testing::kGravity);
  EXPECT_NEAR(Eigen::Vector2d(total.x(), total.z()).norm(), 0.0, 1e-6);
}

}  // namespace
}  // namespace icedem
