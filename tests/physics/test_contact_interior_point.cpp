// The interior-point contact method (dem/contact/interior_point.hpp) and the cone algebra
// it works in (dem/contact/second_order_cone.hpp), on problems whose answer is known:
//  - the Nesterov-Todd scaling's defining identities, and the step to the cone's boundary;
//  - the sliding row of 20 boxes (contact_scenes.hpp): the plate carries all their
//    friction, n mu m g h, the sliding contacts being where De Saxce's shift matters;
//  - two lattices pushed together: with the joints folded into H the bodies' velocities
//    and the joint impulses are the folded reference's;
//  - two islands of the paper's small-floe run (tests/physics/data/contact/) with their
//    stored Siconos references.
#include <gtest/gtest.h>

#include "dem/contact/problem_file.hpp"
#include "dem/contact/second_order_cone.hpp"
#include "tests/physics/contact_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

// W z = W^-1 s = lambda and W W^-1 = I at any interior pair: the scaling's definition
// (round-off: the entries are of order one, 1e-12)
TEST(SecondOrderCone, NesterovToddScalingTakesBothPointsToTheSameLambda) {
  const Eigen::Vector3d pairs[][2] = {{{2.0, 0.5, -0.3}, {1.0, 0.2, 0.6}},
                                      {{1e-3, 0.0, 9e-4}, {50.0, -49.0, 0.0}},
                                      {{1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}}};
  for (const auto& pair : pairs) {
    const soc::Scaling sc = soc::nesterov_todd(pair[0], pair[1]);
    const Eigen::Vector3d from_s = sc.W_inv * pair[0];
    EXPECT_LT((sc.W * sc.W_inv - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_LT((sc.lambda - from_s).norm(), 1e-12 * from_s.norm()) << pair[0].transpose() << " / " << pair[1].transpose();
    // lambda is interior: the scaled point the iterates' centrality is measured on
    EXPECT_GT(soc::cone_det(sc.lambda), 0.0);
    // lambda o lambda has the gap s . z as its first entry
    EXPECT_NEAR(soc::jordan(sc.lambda, sc.lambda)(0), pair[0].dot(pair[1]), 1e-12 * pair[0].dot(pair[1]));
  }
}

// The step to the boundary lands on it (det 0) and stays in Q before it; a direction into
// the cone has no boundary (infinity); jordan_solve inverts the Jordan product
TEST(SecondOrderCone, TheStepToTheBoundaryEndsOnIt) {
  const Eigen::Vector3d x(1.0, 0.3, -0.2);
  for (const Eigen::Vector3d& d : {Eigen::Vector3d(-1.0, 0.0, 0.0), Eigen::Vector3d(0.0, 2.0, 1.0),
                                   Eigen::Vector3d(-0.5, -0.5, 0.5), Eigen::Vector3d(0.1, 1.0, 0.0)}) {
    const double a = soc::step_to_boundary(x, d);
    ASSERT_TRUE(std::isfinite(a)) << d.transpose();
    const Eigen::Vector3d end = x + a * d, before = x + 0.999 * a * d;
    EXPECT_NEAR(end(0), tangential_norm(end(1), end(2)), 1e-12) << d.transpose();
    EXPECT_GT(before(0), tangential_norm(before(1), before(2))) << d.transpose();
  }
  EXPECT_TRUE(std::isinf(soc::step_to_boundary(x, Eigen::Vector3d(1.0, 0.1, 0.0))));
  // along the axis (a frictionless contact's cone is its axis): to the apex, not past it
  EXPECT_NEAR(soc::step_to_boundary(Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d(-0.7, 0, 0)), 0.3 / 0.7, 1e-15);
  const Eigen::Vector3d l(2.0, 0.5, -0.7), b(0.3, -1.0, 2.0);
  EXPECT_LT((soc::jordan(l, soc::jordan_solve(l, b)) - b).norm(), 1e-12);
}

// cold: the chain's whole load from zero impulses, every contact sliding (De Saxce's shift)
TEST(ContactInteriorPoint, SlidingRowPutsAllTheFrictionOnThePlate) {
  expect_all_friction_on_the_plate("ipm", 1e-9, 200);
}

// The method in a run (solver.method = "ipm"): its impulses go back to Bullet's rows
TEST(ContactInteriorPoint, InTheRunTheRowsHoldTheAnswer) { expect_the_row_holds(sliding_row_step("ipm")); }

// The hand-over in a run (solver.handover_method): the gradient method stopped after 5 steps,
// far from the answer, and the island goes on with the interior-point method from there: the
// step ends converged, with the plate's exact impulse, and the report counts one hand-over;
// without it the step ends capped
TEST(ContactInteriorPoint, AnIslandCappedByTheGradientMethodIsHandedOver) {
  const RowStep capped = sliding_row_step("apgd", 1e-9, 1.0, 5, "none");
  EXPECT_TRUE(capped.answer.capped) << "merit " << capped.answer.residual;
  EXPECT_EQ(capped.handovers, 0);
  const RowStep s = sliding_row_step("apgd", 1e-9, 1.0, 5, "ipm");
  EXPECT_EQ(s.handovers, 1);
  expect_the_row_holds(s);
  std::printf("sliding row, 5 gradient steps: merit %.1e; handed over: %.1e after %d iterations in all\n",
              capped.answer.residual, s.answer.residual, s.answer.sweeps);
}

// Lattices: the answer's joint impulses are the ones the contacts' impulses give with the
// joints folded (the method judges itself on that form), so the joint rows hold to round-off
// and the velocities are the folded reference's to what the merit allows
TEST(ContactInteriorPoint, LatticeJointsGiveTheFoldedAnswer) {
  Keep keep;
  pushed_lattices(keep);
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  expect_the_folded_answer(*keep.problem, "ipm", 200);
}

// Islands of the paper run's jams: to 1e-6, the unique parts of the answer (velocities, the
// structure's load) within 1e-4 of the stored reference (Newton's test asks 1e-5 at 1e-7,
// the gradient method's 1e-3 at 1e-6). Not 1e-7: on the first island De Saxce's shift,
// taken from the iterate at each step, leaves the method cycling near 3e-7 (400 iterations)
class ContactInteriorPointRun : public ::testing::TestWithParam<const char*> {};

TEST_P(ContactInteriorPointRun, ReachesTheReferenceOnAJamOfThePaperRun) {
  const std::string path = contact_data_file(GetParam());
  const ProblemFile file = read_problem_file(path);
  const ContactProblem& p = file.problem;
  const Eigen::VectorXd r_ref = stored_reference(path, p.contact_rows());
  ASSERT_EQ(r_ref.size(), p.contact_rows()) << "no reference solution in " << path;
  const SolverAnswer a = solve_with("ipm", p, 1e-6, 400);
  const double merit = natural_map_residual(local_form(p), a.r);
  EXPECT_LT(merit, 1e-6) << a.sweeps << " iterations";
  const ReferenceDistance d = distance_to_reference(p, r_ref, a);
  EXPECT_LT(d.velocities, 1e-4);
  EXPECT_LT(d.load, 1e-4);
  std::printf("%s: %zu contacts; interior point %.1e in %d iterations; velocities %.1e, load %.1e from the reference\n",
              GetParam(), p.contacts.size(), merit, a.sweeps, d.velocities, d.load);
}

INSTANTIATE_TEST_SUITE_P(Jams, ContactInteriorPointRun,
                         ::testing::Values("small_floes_t052.9.hdf5", "small_floes_t124.5.hdf5"));

// The interior-point method does not take a crushing contact's bound (docs/model/crushing.md):
// asked to solve a problem with one, it refuses by name rather than solve a rigid problem in
// its place, and the message names the methods that take it
TEST(ContactInteriorPoint, RefusesCrushingContactsByName) {
  const ContactProblem p = read_problem_file(contact_data_file("crushing_large_floes_t110.02.hdf5")).problem;
  ASSERT_TRUE(has_crushing(p));
  try {
    solve_with("ipm", p, 1e-6, 100);
    ADD_FAILURE() << "the interior-point method solved a crushing problem";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"ipm\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("newton"), std::string::npos) << e.what();
  }
}
