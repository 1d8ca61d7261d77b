// The contact solver's second, tighter solve of an island whose answer puts a joint near
// its capacity (solver.breaking_ratio, solver.breaking_merit_tolerance;
// dem/world/contact_solver.cpp): the measure it takes is the fracture stage's, and the
// answer it keeps meets the tighter merit.
//
// The scene: two lattices of 0.15 m elements (a 0.6 x 0.3 m strip, a 0.3 x 0.3 m square), the
// square pushed into the strip at 0.2 m/s, frictionless, the default solve (the gradient
// method, elastic joints), joints that never break.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dem/fracture/fracture.hpp"
#include "tests/physics/contact_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

namespace {

struct Pushed {
  Scene scene;
  State state;
};

// the two lattices stepped until they have touched for a step (at first touch the answer is
// trivial: the contacts open; a few steps later the elastic lattices may have parted again,
// as they do at the default merit since 2026-11-27, when the round-off of the lattices'
// solve changed); `keep` then holds that step's largest island's problem (its run's warm
// start) and the answer the run kept
Pushed push(Keep& keep, std::vector<std::string> set) {
  set.push_back("friction.ice_ice=0");
  Pushed p{bench(set), State{}};
  p.state = initial_state(p.scene, {strip(0.6, 0.3), square_floe(10.0 + 0.45 + 0.002, 0.0, 0.3)});
  for (FloeBody& f : p.state.world->floes())
    if (f.floe_id == 1) f.body->setLinearVelocity(btVector3(-0.2, 0, 0));
  p.state.world->set_problem_observer(&keep);
  for (int s = 0; s < 10 && !keep.problem; ++s) {
    keep.capture = true;
    step(p.scene, p.state);
  }
  if (keep.problem) {
    keep.problem.reset();
    step(p.scene, p.state);
  }
  p.state.world->set_problem_observer(nullptr);
  return p;
}

}  // namespace

// joint_ratios, taken on the problem and the answer, are the ratios the fracture stage finds
// from Bullet's joint feedback after the step: the same rows' impulses, the same decomposition
// at the midpoint (round-off apart; the step's poses are used by both here)
TEST(BreakingSolve, JointRatioIsTheFractureStagesRatio) {
  Keep keep;
  Pushed p = push(keep, {});
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  ASSERT_FALSE(keep.problem->joints.empty());
  const World& world = *p.state.world;
  const JointRatios from_answer = joint_ratios(p.scene, world, *keep.problem, keep.answer.l);
  double largest = 0, nearest = 0;
  for (const IceJoint& joint : world.joints()) {
    double ratio = 0;
    failure_mode(joint_loads(world, joint), joint_capacity(p.scene, joint), ratio);
    largest = std::max(largest, ratio);
    if (std::abs(ratio - 1) < std::abs(nearest - 1)) nearest = ratio;
  }
  ASSERT_GT(largest, 0.0);
  EXPECT_NEAR(from_answer.largest, largest, 1e-9 * largest);
  EXPECT_NEAR(from_answer.nearest, nearest, 1e-9 * nearest);
}

// With the ratio at 0 every island with joints is solved again: the step counts it in
// /diagnostics/breaking_solves, and the answer it keeps is at the tighter merit, started
// from the first answer; with the ratio above any joint's, none is
TEST(BreakingSolve, AnIslandNearBreakingIsSolvedToTheTighterMerit) {
  Keep keep;
  // (the check's band wider than any ratio's distance from 1: never decided at the check)
  Pushed p = push(keep, {"solver.breaking_ratio=0", "solver.breaking_merit_tolerance=1e-8",
                         "solver.breaking_check_band=10"});
  ASSERT_TRUE(keep.problem);
  ASSERT_GT(keep.answer.r.norm(), 0.0) << "the lattices do not press: a trivial problem";
  EXPECT_GE(p.state.diagnostics.breaking_solves, 1.0);
  EXPECT_LE(keep.answer.residual, 1e-8);
  EXPECT_FALSE(keep.answer.capped);
  // the default: the same step solved to the joints' merit alone
  Keep loose;
  Pushed q = push(loose, {"solver.breaking_ratio=10"});
  ASSERT_TRUE(loose.problem);
  ASSERT_GT(loose.answer.r.norm(), 0.0) << "the lattices do not press: a trivial problem";
  EXPECT_EQ(q.state.diagnostics.breaking_solves, 0.0);
  EXPECT_GT(loose.answer.residual, 1e-8);
  std::printf("pushed lattices: merit %.2e solved again, %.2e at the joints' tolerance\n", keep.answer.residual,
              loose.answer.residual);
}

// What the gradient method leaves above the tighter merit at its cap, the Newton method
// finishes: with a cap of one gradient step, the answer still meets the merit
TEST(BreakingSolve, TheNewtonMethodFinishesWhatTheCapLeft) {
  Keep keep;
  Pushed p = push(keep, {"solver.breaking_ratio=0", "solver.breaking_merit_tolerance=1e-8",
                         "solver.breaking_iterations=1", "solver.breaking_check_band=10"});
  ASSERT_TRUE(keep.problem);
  ASSERT_GT(keep.answer.r.norm(), 0.0) << "the lattices do not press: a trivial problem";
  EXPECT_GE(p.state.diagnostics.breaking_solves, 1.0);
  EXPECT_EQ(p.state.diagnostics.breaking_capped, 0.0);
  EXPECT_LE(keep.answer.residual, 1e-8);
}

// A break decided at the check's merit stops there: these joints never come near their
// capacity (every ratio farther than the band from 1), so an island solved again for them (the
// ratio at 0 sends every one) stops at solver.breaking_check_tolerance, not at the tight merit
TEST(BreakingSolve, AnIslandWhoseBreaksAreDecidedStopsAtTheCheck) {
  Keep keep;
  Pushed p = push(keep, {"solver.breaking_ratio=0", "solver.breaking_merit_tolerance=1e-10"});
  ASSERT_TRUE(keep.problem);
  const JointRatios r = joint_ratios(p.scene, *p.state.world, *keep.problem, keep.answer.l);
  ASSERT_GT(std::abs(r.nearest - 1), 0.04) << "the scene's joints should be far from breaking";
  EXPECT_GE(p.state.diagnostics.breaking_solves, 1.0);
  EXPECT_EQ(p.state.diagnostics.breaking_decided, p.state.diagnostics.breaking_solves);
  EXPECT_LE(keep.answer.residual, 1e-5);
  EXPECT_GT(keep.answer.residual, 1e-10);
  EXPECT_EQ(p.state.diagnostics.breaking_capped, 0.0);
}
