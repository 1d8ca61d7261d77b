// Whether a later method's answer replaces the one it started from (dem/contact/refinement.hpp):
// a lower merit bought by impulses grown by orders of magnitude is not a refinement.
//  - the rule itself, on answers made up for it;
//  - a free element wedged between held pieces of a level tow (tests/physics/data/contact/
//    level_wedge_t127.54.hdf5: the element and its four contacts with fixed bodies, cut out of
//    its island at the step before the one that launched it at 503 m/s, `contact_problems
//    extract`): where the solutions are unbounded the interior-point method, started from the
//    gradient method's answer at the breaking merit, lowers the merit by growing the impulses
//    hundreds of times, and the rule keeps the gradient method's.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "dem/contact/merit.hpp"
#include "dem/contact/problem_file.hpp"
#include "dem/contact/refinement.hpp"
#include "dem/contact/registry.hpp"

using namespace icedem;

namespace {

SolverAnswer answer(double impulse, double residual) {
  SolverAnswer a;
  a.r = Eigen::VectorXd::Constant(3, impulse);
  a.l = Eigen::VectorXd::Zero(2);
  a.residual = residual;
  return a;
}

}  // namespace

TEST(Refinement, ALowerMeritWithImpulsesOfTheSameSizeIsBetter) {
  const SolverAnswer from = answer(1.0, 1e-3);
  EXPECT_TRUE(refines(from, answer(1.05, 1e-6), 0.1));
  EXPECT_FALSE(refines(from, answer(1.0, 2e-3), 0.1)) << "a higher merit";
  // impulses a million times larger: no refinement, however low the merit
  EXPECT_FALSE(refines(from, answer(1e6, 1e-9), 0.1));
  EXPECT_TRUE(runs_off(from, answer(1e6, 1e-9), 0.1)) << "what /diagnostics/runaways counts";
  EXPECT_FALSE(runs_off(from, answer(1e6, 2e-3), 0.1)) << "a higher merit is refused as such, not counted as run off";
  // up to kRefinementGrowth times: still one (a capped answer far from the solution)
  EXPECT_TRUE(refines(from, answer(0.99 * kRefinementGrowth, 1e-6), 0.1));
  // an answer started from rest may load up to the floor's scale
  EXPECT_TRUE(refines(answer(0.0, 1.0), answer(0.5, 1e-6), 0.1));
  EXPECT_FALSE(refines(answer(0.0, 1.0), answer(5.0, 1e-6), 0.1));
}

TEST(Refinement, AnElementWedgedBetweenHeldPiecesKeepsTheGradientMethodsImpulses) {
  const ContactProblem p =
      read_problem_file(std::string(ICEDEM_SOURCE_DIR) + "/tests/physics/data/contact/level_wedge_t127.54.hdf5").problem;
  ASSERT_EQ(p.bodies.size(), 1u);
  ASSERT_EQ(p.contacts.size(), 4u);
  // as a run solves an island with a joint near its capacity: the gradient method to the
  // joints' merit, then to the breaking merit, then the hand-over method from its answer
  MethodOptions o;
  o.merit = MeritKind::kImpulse;
  o.tolerance = 1e-4;
  o.max_iterations = 1000;
  const SolverAnswer first = make_contact_method("apgd")->solve(p, o);
  o.tolerance = 3e-6;
  o.max_iterations = 3000;
  const SolverAnswer gradient = make_contact_method("apgd")->solve(started_from(p, first), o);
  ASSERT_FALSE(gradient.capped) << gradient.residual;
  o.max_iterations = 100;
  const SolverAnswer ipm = make_contact_method("ipm")->solve(started_from(p, gradient), o);
  const double weight = weight_impulse(p);  // the element's weight over the step
  std::printf("wedge: apgd |r| %.3g N s (merit %.2g), ipm from it |r| %.3g N s (merit %.2g); weight over the step %.3g N s\n",
              impulse_norm(gradient), gradient.residual, impulse_norm(ipm), ipm.residual, weight);
  // what the rule is for: a merit no higher (the run's own test would take it) with impulses
  // a hundred times the gradient method's and ten times the element's weight over the step
  // (2026-11-28: 0.0067 -> 2.1 N s at 2.6e-6 -> 1.9e-6; in the island, 7.9 -> 562 N s)
  EXPECT_LE(ipm.residual, gradient.residual);
  EXPECT_GT(impulse_norm(ipm), 100 * impulse_norm(gradient));
  EXPECT_GT(impulse_norm(ipm), kRefinementGrowth * weight);
  EXPECT_FALSE(refines(gradient, ipm, weight)) << "the interior-point answer replaced the gradient method's";
  EXPECT_TRUE(runs_off(gradient, ipm, weight)) << "the refusal is counted as a runaway";
}
