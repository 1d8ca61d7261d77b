// Contact problems of scenes whose answer is known, shared by the contact tests
// (test_contact_problem.cpp, test_contact_newton.cpp, test_contact_apgd.cpp): an observer that keeps a captured
// problem, a tight solver, Siconos' reference solve and the sliding row of boxes.
#pragma once

#include <algorithm>
#include <optional>
#include <string>

#include "dem/contact/registry.hpp"
#include "dem/contact/siconos.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/world/boundary_load.hpp"
#include "dem/world/contact_solver.hpp"
#include "tests/physics/breakable_scenes.hpp"
#include "tests/support/box_world.hpp"

extern "C" {
#include <fclib.h>
}

namespace icedem::testing {

// keeps the last island's problem of the steps it is asked to capture
class Keep : public ProblemObserver {
 public:
  bool capture = false;
  std::optional<ContactProblem> problem;
  SolverAnswer answer;
  bool wants_problems() const override { return capture; }
  void solved(const ContactProblem& p, const SolverAnswer& a) override {
    if (problem && problem->contacts.size() > p.contacts.size()) return;  // keep the largest island
    problem = p;
    answer = a;
  }
};

// `method`: "pgs", the sweeps to `tolerance`; another contact method: to a merit of
// `tolerance` (`structure_tolerance` on an island touching the structure, if smaller);
// either at most `cap` sweeps or iterations, then `handover` from that answer (at most 100)
inline std::unique_ptr<ContactSolver> tight_solver(Keep& keep, int cap = 5000, double tolerance = 1e-9,
                                                   const std::string& method = "pgs", double structure_tolerance = 1.0,
                                                   const std::string& handover = "none") {
  SolverSettings s = test_solver_settings();
  s.iterations = cap;
  s.tolerance = tolerance;
  s.friction_warm_start = true;
  s.method = method;
  s.merit_tolerance = tolerance;
  s.structure_merit_tolerance = structure_tolerance;
  s.method_iterations = cap;
  s.handover_method = handover;
  auto solver = std::make_unique<ContactSolver>(s);
  solver->set_observer(&keep);
  return solver;
}



// a contact method by name (dem/contact/registry.hpp) on p to `tolerance`, at most `cap`
// iterations, warm-started from the problem's guess or not
inline SolverAnswer solve_with(const std::string& method, const ContactProblem& p, double tolerance, int cap,
                               bool warm = true) {
  MethodOptions o;
  o.tolerance = tolerance;
  o.max_iterations = cap;
  o.warm_start = warm;
  return make_contact_method(method)->solve(p, o);
}

// Siconos' proximal point method (semismooth Newton inside) to `tolerance`: it solves the
// rank-deficient problems of faces touching at several points, where plain Newton fails
inline SolverAnswer reference(const ContactProblem& p, double tolerance = 1e-12) {
  register_siconos_methods();
  return solve_with("siconos_prox", p, tolerance, 200);
}

// a contact problem of the test data (tests/physics/data/contact/: islands of the paper's
// small-floe run that stopped at the sweep cap, written by `icedem run --export-problems`)
inline std::string contact_data_file(const std::string& name) {
  return std::string(ICEDEM_SOURCE_DIR) + "/tests/physics/data/contact/" + name;
}

// the reference impulses stored in a problem file (FCLIB's /solution, written by
// `contact_problems reference`); empty if it has none
inline Eigen::VectorXd stored_reference(const std::string& path, int rows) {
  fclib_solution* s = fclib_read_solution(path.c_str());
  if (!s) return {};
  Eigen::VectorXd r = Eigen::Map<Eigen::VectorXd>(s->r, rows);
  fclib_delete_solutions(s, 1);
  return r;
}

// How far an answer is from reference contact impulses r_ref in what is unique (a face's
// impulses are not): the bodies' velocities and the impulse on the structure, each
// relative to the reference's.
struct ReferenceDistance {
  double velocities = 0, load = 0;
};
inline ReferenceDistance distance_to_reference(const ContactProblem& p, const Eigen::VectorXd& r_ref,
                                               const SolverAnswer& a) {
  const GlobalForm g = global_form(p);
  const Eigen::VectorXd v_ref = velocities(g, r_ref, joint_impulses(p, r_ref)), v = velocities(g, a.r, a.l);
  const Eigen::Vector3d load_ref = structure_impulse(p, r_ref), load = structure_impulse(p, a.r);
  return {(v - v_ref).norm() / v_ref.norm(), (load - load_ref).norm() / std::max(load_ref.norm(), 1e-9)};
}

// sum of the normal impulses of the contacts that pass `which`
template <typename Which>
double normal_impulse(const ContactProblem& p, const Eigen::VectorXd& r, Which which) {
  double sum = 0.0;
  for (int c = 0; c < static_cast<int>(p.contacts.size()); ++c)
    if (which(p.contacts[c])) sum += r(3 * c);
  return sum;
}

inline constexpr int kRowBoxes = 20;
inline constexpr double kRowMu = 0.3, kBoxMass = 1.0, kHalf = 0.05, kPlateSpeed = 0.05;

// The row of boxes of test_contact_solver.cpp (20 boxes of 1 kg on a floor with mu = 0.3,
// frictionless to each other), already sliding: the boxes touch end to end and move at
// the plate's speed, the plate touching the first. Frictionless side walls keep the row
// from buckling. The problem of the first step is captured: its answer is known exactly,
// where later steps depend on how well the steps before them were solved. The step is
// solved by `method` (dem/world/contact_solver.hpp: "pgs" or a contact method) to `tolerance`,
// or to `structure_tolerance` if smaller (the row touches the plate, the structure), in at most
// `cap` sweeps or iterations.
struct RowStep {
  ContactProblem problem;
  SolverAnswer answer;           // what the solver ended the step with
  double plate_impulse = 0;      // N s, the normal impulse Bullet's contact points on the plate hold after the step
  double box_speed_min = 0, box_speed_max = 0;  // m/s, surge velocity of the boxes after the step
  double boundary_load = 0;      // N, what the fixed floor and walls take off the plate (dem/world/boundary_load.hpp)
  int handovers = 0;             // islands handed over at the cap (solver.handover_method)
};
inline RowStep sliding_row_step(const std::string& method, double tolerance = 1e-9, double structure_tolerance = 1.0,
                                int cap = 2000, const std::string& handover = "none") {
  Keep keep;
  Bench bench(tight_solver(keep, cap, tolerance, method, structure_tolerance, handover));
  auto* solver = static_cast<ContactSolver*>(bench.world().getConstraintSolver());
  bench.world().getSolverInfo().m_numIterations = cap;
  bench.world().getSolverInfo().m_warmstartingFactor = 1.0;
  bench.world().getSolverInfo().m_minimumSolverBatchSize = 1;
  bench.box({5.0, 0.05, 1.0}, at(0, -0.05, 0), 0.0, kRowMu, 2);  // floor, top at y = 0
  for (double side : {-1.0, 1.0}) bench.box({5.0, 0.1, 0.01}, at(0, 0.1, side * (kHalf + 0.011)), 0.0, 0.0, 2);
  for (int i = 0; i < kRowBoxes; ++i) {
    // overlapping by 0.5 mm: boxes that exactly touch are not all found touching
    btRigidBody* b = bench.box({kHalf, kHalf, kHalf}, at(0.2 + (2 * i + 1) * (kHalf - 0.00025), kHalf, 0), kBoxMass, 1.0, 1);
    b->setLinearVelocity(btVector3(kPlateSpeed, 0, 0));
  }
  const double plate_x0 = 0.2 - 0.01 + 0.0005;  // its face 0.5 mm into the first box
  btRigidBody* plate = bench.box({0.01, 0.04, 0.2}, at(plate_x0, 0.06, 0), 0.0, 0.0, 3, true);
  solver->set_structure(plate);
  plate->getMotionState()->setWorldTransform(at(plate_x0 + kPlateSpeed * kDt, 0.06, 0));
  keep.capture = true;
  bench.world().stepSimulation(kDt, 0);
  RowStep out{*keep.problem, keep.answer};
  out.handovers = static_cast<int>(solver->report().counts.handovers);
  btDispatcher& dispatcher = *bench.world().getDispatcher();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    if (manifold->getBody0() != plate && manifold->getBody1() != plate) continue;
    for (int k = 0; k < manifold->getNumContacts(); ++k) out.plate_impulse += manifold->getContactPoint(k).getAppliedImpulse();
  }
  BoundaryLoad boundary;
  boundary.accumulate(dispatcher, plate, 1.0);
  out.boundary_load = boundary.finish(kDt);
  out.box_speed_min = 1e300, out.box_speed_max = -1e300;
  for (int i = 0; i < bench.world().getNumCollisionObjects(); ++i) {
    const btRigidBody* b = btRigidBody::upcast(bench.world().getCollisionObjectArray()[i]);
    if (!b || b->getInvMass() == 0) continue;
    out.box_speed_min = std::min(out.box_speed_min, double(b->getLinearVelocity().x()));
    out.box_speed_max = std::max(out.box_speed_max, double(b->getLinearVelocity().x()));
  }
  return out;
}
inline ContactProblem sliding_row() { return sliding_row_step("pgs").problem; }

// The sliding row's known answer: the plate carries all the boxes' friction, n mu m g h over
// the step. A method's answer on the captured problem, cold (the whole chain's load from zero
// impulses), to `merit`: not capped, the merit reached, and the plate's impulse within 1e-6 of
// n mu m g h (a merit of 1e-8 or below is relative to the row's largest impulse or velocity,
// which bounds the plate's error to about 1e-6 of it). Returns the answer.
inline SolverAnswer expect_all_friction_on_the_plate(const std::string& method, double merit, int cap) {
  const ContactProblem p = sliding_row();
  const double expected = kRowBoxes * kRowMu * kBoxMass * kGravity * kDt;  // N s over the step
  const SolverAnswer a = solve_with(method, p, merit, cap, false);
  EXPECT_FALSE(a.capped) << method << ": merit " << a.residual << " after " << a.sweeps << " iterations";
  EXPECT_LT(natural_map_residual(local_form(p), a.r), merit);
  EXPECT_NEAR(normal_impulse(p, a.r, [](const ProblemContact& c) { return c.on_structure; }), expected,
              1e-6 * expected);
  std::printf("sliding row: %s, %d iterations to a merit of %.1e\n", method.c_str(), a.sweeps, a.residual);
  return a;
}

// The same after a step of a run: the answer went back into Bullet's rows, so the plate's
// contact points hold n mu m g h and every box keeps the plate's speed, both to 1e-6
inline void expect_the_row_holds(const RowStep& s) {
  const double expected = kRowBoxes * kRowMu * kBoxMass * kGravity * kDt;
  EXPECT_FALSE(s.answer.capped) << "merit " << s.answer.residual;
  EXPECT_NEAR(s.plate_impulse, expected, 1e-6 * expected);
  EXPECT_NEAR(s.box_speed_min, kPlateSpeed, 1e-6 * kPlateSpeed);
  EXPECT_NEAR(s.box_speed_max, kPlateSpeed, 1e-6 * kPlateSpeed);
}

// the pushed lattices' problem solved to 1e-8 against Siconos' reference on the folded
// form, by `method` in at most `cap` iterations; returns the iterations taken
inline int expect_the_folded_answer(const ContactProblem& p, const std::string& method, int cap) {
  const GlobalForm g = global_form(p);
  const SolverAnswer folded = reference(p, 1e-11);
  const SolverAnswer a = solve_with(method, p, 1e-8, cap);
  EXPECT_FALSE(a.capped) << method << ": merit " << a.residual << " after " << a.sweeps << " iterations";
  // judged on the folded form too (the joint rows exact): the same answer
  EXPECT_LT(natural_map_residual(local_form(p), a.r), 1e-7);
  const Eigen::VectorXd v_folded = velocities(g, folded.r, folded.l), v = velocities(g, a.r, a.l);
  // at a merit of 1e-8, the bodies' velocities within 1e-5 of the reference (the joint
  // rows are stiff: C ~ 1e-3 of the rows' inverse mass, so a velocity error carries a
  // thousandfold into the joint impulses, which are left to the merit)
  EXPECT_LT((v - v_folded).norm(), 1e-5 * v_folded.norm());
  // the joints are folded into the lattices' mass matrices and their impulses follow from the
  // velocities: the joint rows J v + b + C l = 0 hold to round-off, whatever the merit
  const Eigen::VectorXd Jv = g.Jj * v, Cl = g.compliance.cwiseProduct(a.l);
  EXPECT_LT((Jv + g.b + Cl).norm(), 1e-9 * std::max({g.b.norm(), Jv.norm(), Cl.norm()}));
  std::printf("pushed lattices: %zu bodies, %zu contacts, %d joint rows; %s, %d iterations to %.1e\n",
              p.bodies.size(), p.contacts.size(), p.joint_rows(), method.c_str(), a.sweeps, a.residual);
  return a.sweeps;
}

// Two lattices of 0.15 m elements (a strip, 0.6 x 0.3 m unless given, and a 0.3 x 0.3 m
// square), frictionless, the square pushed into the strip's end at 0.2 m/s; joints soft
// (the 0.15 m paper CFM) and unbreakable; solved to 1e-9 by Bullet's rows. `keep` gets the
// problem of the first step in which they touch (none if they never do).
inline void pushed_lattices(Keep& keep, double strip_length = 0.6, double strip_width = 0.3) {
  // Bullet's CFM joints swept by its rows: the rows' own answer is the one under test
  const Scene scene = bench({"solver.method=pgs", "fracture.joint_stiffness=cfm", "fracture.cfm=0.00743",
                             "friction.ice_ice=0", "solver.tolerance=1e-9", "solver.iterations=20000",
                             "fracture.joint_iterations=20000"});
  Floe square = square_floe(10.0 + strip_length / 2 + 0.15 + 0.002, 0.0, 0.3);
  State state = initial_state(scene, {strip(strip_length, strip_width), square});
  for (FloeBody& f : state.world->floes())
    if (f.floe_id == 1) f.body->setLinearVelocity(btVector3(-0.2, 0, 0));
  state.world->set_problem_observer(&keep);
  for (int s = 0; s < 10 && !keep.problem; ++s) {
    keep.capture = true;
    step(scene, state);
  }
  state.world->set_problem_observer(nullptr);
}

}  // namespace icedem::testing
