// The primal Newton contact method (dem/contact/newton.hpp) on problems whose answer
// is known:
//  - the sliding row of 20 boxes (contact_scenes.hpp): the plate carries all their
//    friction, n mu m g h, a chain that ten Gauss-Seidel sweeps solve to 0.15 of it;
//  - two lattices pushed together: with the joints in the Hessian (not folded, not
//    swept) the bodies' velocities and joint impulses are Siconos' on the folded form;
//  - two islands of the paper's small-floe run that stopped at today's sweep cap
//    (tests/physics/data/contact/, written by `icedem run --export-problems`), with the
//    reference solution that `contact_problems reference` stored in them (Siconos to
//    about 1e-11, cross-checked by a second Siconos method).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem/contact/island_solve.hpp"
#include "dem/contact/problem_file.hpp"
#include "dem/contact/registry.hpp"
#include "tests/physics/contact_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

// cold: the chain's whole load from zero impulses; 1e-10 is round-off for this problem
TEST(ContactNewton, SlidingRowPutsAllTheFrictionOnThePlate) { expect_all_friction_on_the_plate("newton", 1e-10, 200); }

// The method in a run (solver.method = "newton", dem/world/contact_solver.cpp): the island is
// solved by Newton and its impulses written back to Bullet's rows, so the contact points
// on the plate hold n mu m g h after the step and every box keeps the plate's speed
// (a row pushed at constant speed: friction balances the push exactly).
TEST(ContactNewton, InTheRunTheRowsHoldNewtonsAnswer) { expect_the_row_holds(sliding_row_step("newton")); }

TEST(ContactNewton, LatticeJointsInTheHessianGiveTheFoldedAnswer) {
  Keep keep;
  pushed_lattices(keep);
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  const ContactProblem& p = *keep.problem;
  const GlobalForm g = global_form(p);
  const SolverAnswer folded = reference(p, 1e-11);
  const SolverAnswer a = solve_with("newton", p, 1e-11, 200);
  EXPECT_FALSE(a.capped) << "merit " << a.residual;
  const Eigen::VectorXd v_folded = velocities(g, folded.r, folded.l), v = velocities(g, a.r, a.l);
  // both at 1e-11: velocities to 1e-8, joint impulses to 1e-6 (the folded joint impulses
  // go through C^-1, a factor ~1e3 on round-off)
  EXPECT_LT((v - v_folded).norm(), 1e-8 * v_folded.norm());
  EXPECT_LT((a.l - folded.l).norm(), 1e-6 * folded.l.norm());
  // and Newton's joint impulses solve the joint rows J v + b + C l = 0 to round-off
  // (relative to the rows' largest term: here b is nearly zero, the joints start unstrained)
  const Eigen::VectorXd Cl = g.compliance.cwiseProduct(a.l), Jv = g.Jj * v;
  EXPECT_LT((Jv + g.b + Cl).norm(), 1e-9 * std::max({g.b.norm(), Cl.norm(), Jv.norm()}));
}

// Islands of the paper run's jams: the solution Newton reaches agrees with the stored
// reference in what is unique (bodies' velocities, the load on the structure; a face's
// impulses are not unique). Tolerances: Siconos' own two methods differ by 2e-7 in the
// velocities on the first problem, so 1e-5 at a merit of 1e-7 is what the solutions allow.
class ContactNewtonRun : public ::testing::TestWithParam<const char*> {};

TEST_P(ContactNewtonRun, ReachesTheReferenceOnAJamOfThePaperRun) {
  const std::string path = contact_data_file(GetParam());
  const ProblemFile file = read_problem_file(path);
  const ContactProblem& p = file.problem;
  const Eigen::VectorXd r_ref = stored_reference(path, p.contact_rows());
  ASSERT_EQ(r_ref.size(), p.contact_rows()) << "no reference solution in " << path;
  // the run's own solver stopped at the sweep cap on these islands
  ASSERT_TRUE(file.answer && file.answer->capped);
  const SolverAnswer a = solve_with("newton", p, 1e-7, 400);
  const double merit = natural_map_residual(local_form(p), a.r);
  EXPECT_LT(merit, 1e-7) << a.sweeps << " Newton steps";
  const ReferenceDistance d = distance_to_reference(p, r_ref, a);
  EXPECT_LT(d.velocities, 1e-5);
  EXPECT_LT(d.load, 1e-5);
  // what the run's capped sweeps left: the merit of its answer, for the record
  std::printf("%s: %zu contacts; the run's answer %.1e, Newton %.1e in %d steps\n", GetParam(), p.contacts.size(),
              natural_map_residual(local_form(p), file.answer->r), merit, a.sweeps);
}

INSTANTIATE_TEST_SUITE_P(Jams, ContactNewtonRun,
                         ::testing::Values("small_floes_t052.9.hdf5", "small_floes_t124.5.hdf5"));

// Crushing contacts (contact.model = "crushing", docs/model/crushing.md): each contact's normal
// impulse is bounded by its cap, the set the Newton method projects onto is the cone cut there
// (dem/contact/projection_jacobian.hpp). On an island of the 0.6 m floes' run with crushing
// and the water's added mass (25 contacts at t = 110.02 s, written by `icedem run
// --export-problems`; no Siconos method takes the bound, so there is no stored reference),
// Newton and the accelerated projected gradient (a second-order and a first-order method,
// which share only the projection) reach the natural map's merit on the cut cones and agree
// in what is unique: the bodies' velocities and the impulse on the structure. Tolerances: at
// a merit of 1e-8 the answers' velocities differ by that relative amount times the problem's
// conditioning; 1e-4 is what Newton and Siconos' methods agree to on the rigid islands above
// at 1e-7. The bound binds, or the case would not test it: some contacts crush, their normal
// at the cap while they close (u_N < 0). A contact not yet overlapping at the step's start has
// a cap of 0 (docs/model/crushing.md): it closes without load.
TEST(ContactNewton, CrushingContactsAreSolvedOnTheirCutCones) {
  const std::string path = contact_data_file("crushing_large_floes_t110.02.hdf5");
  const ContactProblem p = read_problem_file(path).problem;
  ASSERT_TRUE(has_crushing(p));
  const Eigen::VectorXd caps = normal_caps(p);
  const SolverAnswer newton = solve_with("newton", p, 1e-8, 400);
  EXPECT_FALSE(newton.capped) << "merit " << newton.residual << " after " << newton.sweeps << " steps";
  const LocalForm local = local_form(p);
  const Eigen::VectorXd u = local.W * newton.r + local.q;
  int crushing = 0, loaded = 0;
  for (int c = 0; c < static_cast<int>(p.contacts.size()); ++c) {
    EXPECT_LE(newton.r(3 * c), caps(c) * (1 + 1e-12));
    const bool at_cap = newton.r(3 * c) >= caps(c) * (1 - 1e-6) && u(3 * c) < -1e-6;
    crushing += at_cap;
    loaded += at_cap && caps(c) > 0;
  }
  EXPECT_GT(crushing, 0) << "no contact crushes: the bound is not tested";
  const SolverAnswer apgd = solve_with("apgd", p, 1e-8, 20000);
  EXPECT_FALSE(apgd.capped) << "merit " << apgd.residual;
  const ReferenceDistance d = distance_to_reference(p, newton.r, apgd);
  EXPECT_LT(d.velocities, 1e-4);
  EXPECT_LT(d.load, 1e-4);
  std::printf("%zu contacts, %d crushing (%d of them loaded); Newton %.1e in %d steps, APGD %.1e in %d; they differ by %.1e (velocities), "
              "%.1e (load)\n",
              p.contacts.size(), crushing, loaded, newton.residual, newton.sweeps, apgd.residual, apgd.sweeps, d.velocities,
              d.load);
}

// The run's island solve (dem/contact/island_solve.hpp) on the same island: left at the gradient method's cap far
// from its merit, it goes on with Newton from there when the hand-over method is the interior-point method, which
// does not take crushing contacts (the default hand-over): the step ends at its merit, one hand-over counted.
// Without a hand-over it ends capped. The analytic level tow with crushing at the cone left 3.5 % of its window's
// steps at the cap before its crushing islands went on with Newton.
TEST(ContactNewton, ACrushingIslandLeftAtTheCapGoesOnWithNewton) {
  const ContactProblem p = read_problem_file(contact_data_file("crushing_large_floes_t110.02.hdf5")).problem;
  ASSERT_FALSE(takes_crushing("ipm"));
  SolverSettings s = test_solver_settings();
  s.method = "apgd";
  s.method_iterations = 5;
  s.handover_iterations = 400;
  SolverReport alone, handed;
  s.handover_method = "none";
  const SolverAnswer capped = IslandSolve(s).solve(p, alone);
  s.handover_method = "ipm";
  const SolverAnswer finished = IslandSolve(s).solve(p, handed);
  EXPECT_TRUE(capped.capped) << "merit " << capped.residual;
  EXPECT_EQ(alone.counts.handovers, 0);
  EXPECT_FALSE(finished.capped) << "merit " << finished.residual << " after " << finished.sweeps << " iterations";
  EXPECT_LE(finished.residual, s.merit_tolerance);
  EXPECT_EQ(handed.counts.handovers, 1);
  std::printf("5 gradient steps: merit %.1e; handed to Newton: %.1e after %d iterations in all\n", capped.residual,
              finished.residual, finished.sweeps);
}
