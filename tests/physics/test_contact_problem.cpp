// Contact problems captured from Bullet's rows (dem/contact/problem*.hpp), checked on
// scenes whose answer is known, solved by Siconos numerics to 1e-10 or better:
//  - a box resting on a floor: the floor carries its weight over the step, m g h;
//  - a row of boxes sliding end-on at constant speed, pushed by a kinematic plate: the
//    plate carries all their friction, n mu m g h, and a few sweeps of
//    projected Gauss-Seidel on the same problem fall well short of it (the long force
//    chain the solver issue is about, reproduced on the captured problem);
//  - two lattices of elements pushed together: the problem with its joint rows, the
//    joints folded into the Delassus form (Siconos) and solved as rows (Gauss-Seidel)
//    give the same body velocities, and Bullet's own converged answer satisfies the
//    captured joint rows;
//  - a problem file keeps the problem exactly, and its FCLIB local form is the one
//    computed from the problem;
//  - the merit is Siconos' own (fc3d_compute_error).
#include <gtest/gtest.h>

#include <optional>

#include <siconos/numerics/FrictionContactProblem.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/SolverOptions.h>
#include <siconos/numerics/fc3d_compute_error.h>

#include "dem/contact/problem_file.hpp"
#include "dem/contact/registry.hpp"
#include "dem/contact/siconos.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/world/contact_solver.hpp"
#include "tests/physics/breakable_scenes.hpp"
#include "tests/physics/contact_scenes.hpp"
#include "tests/support/box_world.hpp"

extern "C" {
#include <fclib.h>
}

using namespace icedem;
using namespace icedem::testing;

TEST(ContactProblem, RestingBoxProblemCarriesItsWeight) {
  Keep keep;
  Bench bench(tight_solver(keep));
  bench.world().getSolverInfo().m_numIterations = 5000;
  bench.world().getSolverInfo().m_minimumSolverBatchSize = 1;
  bench.box({5.0, 0.05, 1.0}, at(0, -0.05, 0), 0.0, 0.5, 2);
  bench.box({kHalf, kHalf, kHalf}, at(0, kHalf, 0), kBoxMass, 1.0, 1);
  for (int s = 0; s < 25; ++s) bench.world().stepSimulation(kDt, 0);
  keep.capture = true;
  bench.world().stepSimulation(kDt, 0);
  ASSERT_TRUE(keep.problem);
  const ContactProblem& p = *keep.problem;
  ASSERT_EQ(p.bodies.size(), 1u);  // the floor is fixed: data, not an unknown
  ASSERT_GE(p.contacts.size(), 3u);
  const SolverAnswer a = reference(p);
  EXPECT_FALSE(a.capped);
  // a body at rest: the floor's impulse over the step is its weight's, m g h, to round-off
  const double weight = kBoxMass * kGravity * kDt;
  EXPECT_NEAR(normal_impulse(p, a.r, [](const ProblemContact&) { return true; }), weight, 1e-9 * weight);
  // and what Bullet's rows ended with, swept to 1e-9, solves the captured problem: the
  // capture is the problem Bullet solved (merit to 1e-6, the rows' own tolerance being looser)
  EXPECT_LT(natural_map_residual(local_form(p), keep.answer.r), 1e-6);
}

TEST(ContactProblem, SlidingRowProblemPutsAllTheFrictionOnThePlate) {
  const ContactProblem p = sliding_row();
  ASSERT_EQ(p.bodies.size(), static_cast<std::size_t>(kRowBoxes));
  const double expected = kRowBoxes * kRowMu * kBoxMass * kGravity * kDt;  // N s over the step
  auto on_plate = [](const ProblemContact& c) { return c.on_structure; };
  // exact: Siconos reaches 1e-12; the plate's impulse within 1e-6 of n mu m g h
  const SolverAnswer exact = reference(p);
  EXPECT_FALSE(exact.capped) << "Siconos' residual " << exact.residual;
  EXPECT_NEAR(normal_impulse(p, exact.r, on_plate), expected, 1e-6 * expected);
  // ten cold sweeps of Bullet's Gauss-Seidel rows on the same problem carry about one box
  // per sweep: measured 0.15 of the load; asserted below 0.8
  MethodOptions ten;
  ten.max_iterations = 10;
  ten.tolerance = 0.0;
  ten.warm_start = false;
  const SolverAnswer pgs = make_contact_method("pgs_square")->solve(p, ten);
  const double short_of = normal_impulse(p, pgs.r, on_plate) / expected;
  EXPECT_LT(short_of, 0.8);
  std::printf("sliding row: n mu m g h = %.5f N s; Siconos %.5f N s in %d iterations; 10 cold PGS sweeps %.2f of it\n",
              expected, normal_impulse(p, exact.r, on_plate), exact.sweeps, short_of);
}

TEST(ContactProblem, FileKeepsTheProblemAndItsFclibForms) {
  const ContactProblem p = sliding_row();
  SolverAnswer answer;
  answer.r = Eigen::VectorXd::LinSpaced(p.contact_rows(), 0.0, 1.0);
  answer.l = Eigen::VectorXd();
  answer.sweeps = 7;
  answer.residual = 0.25;
  answer.capped = true;
  const std::string path = std::string(ICEDEM_TEST_TMP) + "/row_problem.hdf5";
  write_problem_file(path, p, answer);
  const ProblemFile back = read_problem_file(path);
  const ContactProblem& q = back.problem;
  ASSERT_EQ(q.bodies.size(), p.bodies.size());
  ASSERT_EQ(q.contacts.size(), p.contacts.size());
  for (std::size_t i = 0; i < p.bodies.size(); ++i) {
    EXPECT_EQ(q.bodies[i].mass, p.bodies[i].mass);
    EXPECT_TRUE(q.bodies[i].inertia.isApprox(p.bodies[i].inertia, 1e-14));
    // stored as M v_free: v_free comes back through a 6x6 solve
    EXPECT_LT((q.bodies[i].free_velocity - p.bodies[i].free_velocity).norm(), 1e-14);
  }
  for (std::size_t c = 0; c < p.contacts.size(); ++c) {
    EXPECT_EQ(q.contacts[c].ja, p.contacts[c].ja);
    EXPECT_EQ(q.contacts[c].jb, p.contacts[c].jb);
    EXPECT_EQ(q.contacts[c].w, p.contacts[c].w);
    EXPECT_EQ(q.contacts[c].mu, p.contacts[c].mu);
    EXPECT_EQ(q.contacts[c].guess, p.contacts[c].guess);
    EXPECT_EQ(q.contacts[c].on_structure, p.contacts[c].on_structure);
  }
  ASSERT_TRUE(back.answer);
  EXPECT_EQ(back.answer->r, answer.r);
  EXPECT_EQ(back.answer->sweeps, 7);
  EXPECT_TRUE(back.answer->capped);
  // the file's FCLIB local form, read by libfclib, is the Delassus form of the problem
  fclib_local* local = fclib_read_local(path.c_str());
  ASSERT_NE(local, nullptr);
  const LocalForm expected = local_form(p);
  ASSERT_EQ(local->W->n, expected.W.cols());
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(local->W->m, local->W->n);
  for (int col = 0; col < local->W->n; ++col)
    for (int k = local->W->p[col]; k < local->W->p[col + 1]; ++k) W(local->W->i[k], col) = local->W->x[k];
  EXPECT_LT((W - Eigen::MatrixXd(expected.W)).norm(), 1e-15 * W.norm());
  EXPECT_EQ(Eigen::Map<Eigen::VectorXd>(local->q, local->W->n), expected.q);
  fclib_delete_local(local);
}

TEST(ContactProblem, MeritIsSiconosNaturalMapResidual) {
  const ContactProblem p = sliding_row();
  const LocalForm local = local_form(p);
  const int m = p.contact_rows();
  // any impulses will do: a ramp that is neither zero nor a solution
  const Eigen::VectorXd r = Eigen::VectorXd::LinSpaced(m, 0.0, 0.01);
  NumericsMatrix* W = NM_create(NM_SPARSE, m, m);
  NM_triplet_alloc(W, local.W.nonZeros());
  for (int col = 0; col < local.W.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(local.W, col); it; ++it)
      NM_entry(W, static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
  auto* q = static_cast<double*>(std::malloc(sizeof(double) * m));
  auto* mu = static_cast<double*>(std::malloc(sizeof(double) * m / 3));
  for (int i = 0; i < m; ++i) q[i] = local.q(i);
  for (int i = 0; i < m / 3; ++i) mu[i] = local.mu(i);
  FrictionContactProblem* problem = frictionContactProblem_new_with_data(3, m / 3, W, q, mu);
  SolverOptions* so = solver_options_create(500);
  Eigen::VectorXd rr = r, u(m);
  double siconos = 0.0;
  fc3d_compute_error(problem, rr.data(), u.data(), 1e-10, so, local.q.norm(), &siconos);
  solver_options_delete(so);
  frictionContactProblem_free(problem);
  EXPECT_NEAR(natural_map_residual(local, r), siconos, 1e-12 * siconos);
}

TEST(ContactProblem, LatticeJointsFoldIntoTheDelassusForm) {
  // two lattices pushed together (contact_scenes.hpp), frictionless, joints soft
  Keep keep;
  pushed_lattices(keep);
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  const ContactProblem& p = *keep.problem;
  ASSERT_EQ(p.joint_rows(), 6 * (10 + 4));  // six rows per joint: 10 in the strip, 4 in the square
  for (const ProblemJointRow& j : p.joints) ASSERT_GT(j.compliance, 0.0);

  // Bullet's own answer, joints and contacts swept to 1e-9, satisfies the captured joint rows
  const GlobalForm g = global_form(p);
  const Eigen::VectorXd v_run = velocities(g, keep.answer.r, keep.answer.l);
  const Eigen::VectorXd joint_error = g.Jj * v_run + g.b + g.compliance.cwiseProduct(keep.answer.l);
  EXPECT_LT(joint_error.norm(), 1e-6 * g.b.norm() + 1e-12) << "|J v + b + C l| of the run's answer";

  // joints folded (Siconos on the Delassus form) and joints as rows (Gauss-Seidel) agree
  const SolverAnswer folded = reference(p, 1e-11);
  MethodOptions rows;
  rows.tolerance = 1e-11;
  rows.max_iterations = 200000;
  const SolverAnswer swept = make_contact_method("pgs_cone")->solve(p, rows);
  const Eigen::VectorXd v_folded = velocities(g, folded.r, folded.l), v_swept = velocities(g, swept.r, swept.l);
  EXPECT_LT((v_folded - v_swept).norm(), 1e-6 * v_folded.norm());
  EXPECT_LT((folded.l - swept.l).norm(), 1e-4 * folded.l.norm());
}

// The two Gauss-Seidel code paths, one answer: the run's sweeps over Bullet's rows
// (solver.method = "pgs", dem/world/contact_solver.hpp) and pgs_square on the problem captured
// from those rows (dem/contact/pgs.hpp), each swept until it no longer moves, give the same body
// velocities and the same impulse on the structure (what is unique: a face's points share their
// impulses in many ways). Both clamp friction per direction, so neither reaches a small merit on
// Coulomb's disc (3e-2 here): pgs_square runs its whole cap. The sliding row is a chain of 20
// boxes, which Gauss-Seidel converges slowly: the run's sweeps stop at their own residual of 1e-9
// after about 3,500 sweeps. Tolerance 1e-6 of each, against a difference of 1e-5 when the run's
// sweeps stop at 2,000 (residual 5e-6).
TEST(ContactProblem, InRunSweepsAndProblemSweepsAgree) {
  const RowStep row = sliding_row_step(kBulletSweeps, 1e-9, 1.0, 50000);
  EXPECT_FALSE(row.answer.capped) << "the run's sweeps ended at residual " << row.answer.residual;
  MethodOptions tight;
  tight.tolerance = 1e-12;
  tight.max_iterations = 50000;
  const SolverAnswer problem_sweeps = make_contact_method("pgs_square")->solve(row.problem, tight);
  const ReferenceDistance d = distance_to_reference(row.problem, row.answer.r, problem_sweeps);
  std::printf("sliding row: the run's sweeps %d (residual %.1e), pgs_square %d; velocities %.1e, load %.1e apart\n",
              row.answer.sweeps, row.answer.residual, problem_sweeps.sweeps, d.velocities, d.load);
  EXPECT_LT(d.velocities, 1e-6) << "body velocities, relative";
  EXPECT_LT(d.load, 1e-6) << "impulse on the plate, relative";

  // with joints: the lattices' step, Bullet's CFM joint rows swept by the run to 1e-9, frictionless
  // (so a small merit is reachable), as rows on the problem
  Keep keep;
  pushed_lattices(keep);
  ASSERT_TRUE(keep.problem) << "the lattices never touched";
  const SolverAnswer lattice_sweeps = make_contact_method("pgs_square")->solve(*keep.problem, tight);
  EXPECT_FALSE(lattice_sweeps.capped);
  const GlobalForm g = global_form(*keep.problem);
  const Eigen::VectorXd v_run = velocities(g, keep.answer.r, keep.answer.l);
  const Eigen::VectorXd v_problem = velocities(g, lattice_sweeps.r, lattice_sweeps.l);
  EXPECT_LT((v_run - v_problem).norm(), 1e-6 * v_run.norm()) << "lattice body velocities";
}
