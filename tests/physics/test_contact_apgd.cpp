// The accelerated projected gradient contact method (dem/contact/apgd.hpp) on problems
// whose answer is known (the same as the Newton method's tests):
//  - the sliding row of 20 boxes (contact_scenes.hpp): the plate carries all their
//    friction, n mu m g h;
//  - two lattices pushed together: the method folds the joints into the lattices' mass
//    matrices, the answer is Siconos' on the same folded form, and the joint rows hold;
//  - two islands of the paper's small-floe run that stopped at today's sweep cap, with
//    their stored reference solutions (Siconos to about 1e-11), and one of them written in
//    other coordinates, so that its contacts' sides are not opposite.
// APGD is a first-order method: it is run to the merits a run uses (1e-6 and looser),
// and the tolerances below follow from the merit reached, as stated at each.
#include <gtest/gtest.h>

#include <algorithm>

#include "dem/contact/problem_file.hpp"
#include "tests/physics/contact_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

// cold, from zero impulses: the whole chain's load has to travel 20 boxes
TEST(ContactApgd, SlidingRowPutsAllTheFrictionOnThePlate) { expect_all_friction_on_the_plate("apgd", 1e-8, 5000); }

// solver.method = "apgd" in a run: the island's answer goes back into Bullet's rows, so
// the plate's contact points hold n mu m g h after the step and the boxes move with it
// (to a merit of 1e-8: a first-order method needs about 2500 steps for 1e-9 here)
TEST(ContactApgd, InTheRunTheRowsHoldTheAnswer) { expect_the_row_holds(sliding_row_step("apgd", 1e-8)); }

// solver.structure_merit_tolerance: an island touching the structure (the row touches the
// plate) is solved to that merit when it is below solver.merit_tolerance
TEST(ContactApgd, TheIslandOnTheStructureIsSolvedToItsOwnTolerance) {
  const double expected = kRowBoxes * kRowMu * kBoxMass * kGravity * kDt;
  // a loose merit alone stops early: the plate's impulse is off by more than 1e-6 of it
  const RowStep loose = sliding_row_step("apgd", 1e-2);
  EXPECT_GT(loose.answer.residual, 1e-8);
  EXPECT_GT(std::abs(loose.plate_impulse - expected), 1e-6 * expected);
  // the same loose merit with 1e-8 on the structure's island: the run's answer as at 1e-8
  // everywhere (ContactApgd.InTheRunTheRowsHoldTheAnswer)
  const RowStep tight = sliding_row_step("apgd", 1e-2, 1e-8);
  EXPECT_FALSE(tight.answer.capped) << "merit " << tight.answer.residual;
  EXPECT_LE(tight.answer.residual, 1e-8);
  EXPECT_NEAR(tight.plate_impulse, expected, 1e-6 * expected);
  std::printf("sliding row: plate impulse off by %.2e of it at a merit of 1e-2, %.2e with 1e-8 on the structure\n",
              std::abs(loose.plate_impulse - expected) / expected, std::abs(tight.plate_impulse - expected) / expected);
}

TEST(ContactApgd, LatticeJointRowsGiveTheFoldedAnswer) {
  Keep keep;
  pushed_lattices(keep);
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  expect_the_folded_answer(*keep.problem, "apgd", 20000);
}

// A lattice of more than LatticeMass::kDenseElements elements (a 1.2 x 0.9 m strip of 48)
// is folded too, through a sparse factorisation (dem/contact/lattice_mass.hpp); before it
// was, such an island kept its joint rows as unknowns and its solves stopped at the cap:
// the same answer, and in about as few steps as the small lattices take.
TEST(ContactApgd, LargeLatticeIsFoldedThroughASparseFactor) {
  Keep keep;
  pushed_lattices(keep, 1.2, 0.9);
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  ASSERT_EQ(keep.problem->bodies.size(), 48u + 4u);
  // measured: 247 gradient steps to 1e-8 folded, 1067 with the joint rows iterated (as
  // before the sparse factor), which also leaves the joint rows' equations off by 6e-9
  EXPECT_LT(expect_the_folded_answer(*keep.problem, "apgd", 20000), 600);
}

// Islands of the paper run's jams, where the run's sweeps stopped at 1e-2: APGD reaches
// 1e-6, and what is unique in the answer (the bodies' velocities, the structure's load)
// is within 1e-3 of the reference (measured: the velocities are 15 and 160 times the
// merit from the reference on these two islands; Newton's test, at 1e-7, asks 1e-5).
class ContactApgdRun : public ::testing::TestWithParam<const char*> {};

TEST_P(ContactApgdRun, ReachesTheReferenceOnAJamOfThePaperRun) {
  const std::string path = contact_data_file(GetParam());
  const ProblemFile file = read_problem_file(path);
  const ContactProblem& p = file.problem;
  const Eigen::VectorXd r_ref = stored_reference(path, p.contact_rows());
  ASSERT_EQ(r_ref.size(), p.contact_rows()) << "no reference solution in " << path;
  ASSERT_TRUE(file.answer && file.answer->capped);
  const SolverAnswer a = solve_with("apgd", p, 1e-6, 5000);
  const double merit = natural_map_residual(local_form(p), a.r);
  EXPECT_LT(merit, 1e-6) << a.sweeps << " steps";
  const ReferenceDistance d = distance_to_reference(p, r_ref, a);
  EXPECT_LT(d.velocities, 1e-3);
  EXPECT_LT(d.load, 1e-3);
  std::printf("%s: %zu contacts; APGD %.1e in %d steps; velocities %.1e, load %.1e from the reference\n", GetParam(),
              p.contacts.size(), merit, a.sweeps, d.velocities, d.load);
}

INSTANTIATE_TEST_SUITE_P(Jams, ContactApgdRun,
                         ::testing::Values("small_floes_t052.9.hdf5", "small_floes_t124.5.hdf5"));

// The method keeps a contact's rows as one linear part, opposite on its two bodies, as
// Bullet writes them; a contact whose sides are not opposite keeps one side apart. Here a
// jam of the paper run is written in other coordinates: every second body's linear
// velocity in units of half of it (its mass times 4, its rows' linear parts times 2), so
// that most contacts' sides are not opposite, though the problem is the same (J M^-1 J^T
// and the impulses do not change). The answer meets the same reference as above.
TEST(ContactApgd, ContactsWhoseSidesAreNotOppositeAreTheSameProblem) {
  const std::string path = contact_data_file("small_floes_t124.5.hdf5");
  ContactProblem p = read_problem_file(path).problem;
  const Eigen::VectorXd r_ref = stored_reference(path, p.contact_rows());
  auto rescaled = [](int body) { return body >= 0 && body % 2 == 0; };
  for (int i = 0; i < static_cast<int>(p.bodies.size()); ++i)
    if (rescaled(i)) p.bodies[i].mass *= 4.0, p.bodies[i].free_velocity.head<3>() /= 2.0;
  int apart = 0;
  for (ProblemContact& c : p.contacts) {
    if (rescaled(c.a)) c.ja.leftCols<3>() *= 2.0;
    if (rescaled(c.b)) c.jb.leftCols<3>() *= 2.0;
    if (c.a >= 0 && c.b >= 0 && c.ja.leftCols<3>() != -c.jb.leftCols<3>()) ++apart;
  }
  ASSERT_GT(apart, static_cast<int>(p.contacts.size()) / 4);
  const SolverAnswer a = solve_with("apgd", p, 1e-6, 5000);
  EXPECT_LT(natural_map_residual(local_form(p), a.r), 1e-6) << a.sweeps << " steps";
  // the velocities and the load within 1e-3 of the reference, as on the problem as written
  const ReferenceDistance d = distance_to_reference(p, r_ref, a);
  EXPECT_LT(d.velocities, 1e-3);
  EXPECT_LT(d.load, 1e-3);
}
