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

#include "dem/fracture/fracture.hpp"
#include "tests/physics/contact_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

namespace {

struct Pushed {
  Scene scene;
  State state;
};

// the two lattices stepped until they have touched for a few steps (at first touch the
// answer is trivial: the contacts open); `keep` then holds that step's largest island's
// problem (its run's warm start) and the answer the run kept
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
  for (int s = 0; s < 3 && keep.problem; ++s) {
    keep.problem.reset();
    step(p.scene, p.state);
  }
  p.state.world->set_problem_observer(nullptr);
  return p;
}

}  // namespace

// largest_joint_ratio, taken on the problem and the answer, is the ratio the fracture stage
// finds from Bullet's joint feedback after the step: the same rows' impulses, the same
// decomposition at the midpoint (round-off apart; the step's poses are used by both here)
TEST(BreakingSolve, JointRatioIsTheFractureStagesRatio) {
  Keep keep;
  Pushed p = push(keep, {});
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  ASSERT_FALSE(keep.problem->joints.empty());
  const World& world = *p.state.world;
  const double from_answer = largest_joint_ratio(p.scene, world, *keep.problem, keep.answer.l);
  double from_feedback = 0;
  for (const IceJoint& joint : world.joints()) {
    double ratio = 0;
    failure_mode(joint_loads(world, joint), joint_capacity(p.scene, joint), ratio);
    from_feedback = std::max(from_feedback, ratio);
  }
  ASSERT_GT(from_feedback, 0.0);
  EXPECT_NEAR(from_answer, from_feedback, 1e-9 * from_feedback);
}

// With the ratio at 0 every island with joints is solved again: the step counts it in
// /diagnostics/breaking_solves, and the answer it keeps is at the tighter merit, started
// from the first answer; with the ratio above any joint's, none is
TEST(BreakingSolve, AnIslandNearBreakingIsSolvedToTheTighterMerit) {
  Keep keep;
  Pushed p = push(keep, {"solver.breaking_ratio=0", "solver.breaking_merit_tolerance=1e-8"});
  ASSERT_TRUE(keep.problem);
  EXPECT_GE(p.state.diagnostics.breaking_solves, 1.0);
  EXPECT_LE(keep.answer.residual, 1e-8);
  EXPECT_FALSE(keep.answer.capped);
  // the default: the same step solved to the joints' merit alone
  Keep loose;
  Pushed q = push(loose, {"solver.breaking_ratio=10"});
  ASSERT_TRUE(loose.problem);
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
                         "solver.breaking_iterations=1"});
  ASSERT_TRUE(keep.problem);
  EXPECT_GE(p.state.diagnostics.breaking_solves, 1.0);
  EXPECT_EQ(p.state.diagnostics.breaking_capped, 0.0);
  EXPECT_LE(keep.answer.residual, 1e-8);
}
