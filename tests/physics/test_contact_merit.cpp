// The merits a contact solve stops on (dem/contact/merit.hpp):
//  - "siconos" is exactly the library's common measure, natural_map_residual;
//  - "impulse" gives an answer whose forces are off by a fraction e the same value
//    whatever the step and whatever gaps the island's untouching points close, where the
//    Siconos merit of the same answer shrinks as h^2 once the gaps dominate its scale;
//  - a method stopped on the impulse merit gives the load it promises.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dem/contact/merit.hpp"
#include "dem/contact/problem_file.hpp"
#include "tests/physics/contact_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

namespace {

// A box of mass m resting on the ground (contact 0, under its centre: its weight over
// the step, m g h, is the answer's normal impulse) beside a second point of the same pair
// a gap d apart (contact 1: open, it asks u_N >= -d / h of nothing).
ContactProblem resting_box(double h, double gap) {
  constexpr double m = 2.0, g = 9.81;
  ContactProblem p;
  p.dt = h;
  ProblemBody box;
  box.mass = m;
  box.inertia = Eigen::Matrix3d::Identity() * 0.01;
  box.free_velocity << 0.0, -g * h, 0.0, 0.0, 0.0, 0.0;  // gravity over the step
  p.bodies.push_back(box);
  for (int c = 0; c < 2; ++c) {
    ProblemContact k;
    k.a = 0;
    k.ja.block<3, 3>(0, 0) << 0, 1, 0,  // normal: up
        1, 0, 0,                         // tangents
        0, 0, 1;
    k.mu = 0.3;
    k.w = Eigen::Vector3d(c == 0 ? 0.0 : gap / h, 0.0, 0.0);
    p.contacts.push_back(k);
  }
  return p;
}

// the answer with the resting contact's force off by a fraction e
Eigen::VectorXd answer_off_by(const ContactProblem& p, double e) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6);
  r(0) = (1.0 + e) * p.bodies[0].mass * 9.81 * p.dt;
  return r;
}

}  // namespace

TEST(ContactMerit, SiconosIsTheLibrarysCommonMeasure) {
  // the warm start and a loose answer of the sliding row, and the guess of a jam of the paper run
  const ContactProblem row = sliding_row();
  const ProblemFile jam = read_problem_file(contact_data_file("small_floes_t124.5.hdf5"));
  for (const ContactProblem* p : {&row, &jam.problem}) {
    const LocalForm local = local_form(*p);
    const Merit merit(MeritKind::kSiconos, local.q, contact_masses(*p), local.mu, p->dt);
    for (const Eigen::VectorXd& r : {contact_guess(*p), solve_with("apgd", *p, 1e-3, 1000).r}) {
      const Eigen::VectorXd u = local.W * r + local.q;
      // the same arithmetic: equal to the last bit
      EXPECT_EQ(merit(r, u), natural_map_residual(local, r));
    }
  }
}

TEST(ContactMerit, ImpulseMeritIsTheForcesErrorAtAnyStepAndGap) {
  constexpr double e = 0.01;  // the answer's force is 1 % high
  std::vector<double> siconos_with_gap;
  for (double h : {0.02, 0.01, 0.005}) {
    for (double gap : {0.0, 0.001, 0.003}) {
      const ContactProblem p = resting_box(h, gap);
      const LocalForm local = local_form(p);
      const Eigen::VectorXd r = answer_off_by(p, e), u = local.W * r + local.q;
      const Merit impulse(MeritKind::kImpulse, local.q, contact_masses(p), local.mu, h);
      const Merit siconos(MeritKind::kSiconos, local.q, contact_masses(p), local.mu, h);
      // the resting contact's velocity error e g h times its mass m, over the larger of the
      // impulse (1 + e) m g h and the two contacts' weights over the step, sqrt(2) m g h:
      // e / sqrt(2), the same at every step and gap to round-off
      EXPECT_NEAR(impulse(r, u), e / std::sqrt(2.0), 1e-12) << "h " << h << ", gap " << gap;
      if (gap == 0.003) {
        siconos_with_gap.push_back(siconos(r, u));
        std::printf("h %.3f s, gap %.0f mm: siconos merit %.2e, impulse merit %.2e\n", h, 1e3 * gap, siconos(r, u),
                    impulse(r, u));
      }
    }
  }
  // the Siconos merit of the same answer, e g h over max(|q|, |r|, |u|): once the open
  // point's gap / h dominates the scale it falls as h^2 (measured 4.95e-3, 3.26e-3, 8.2e-4):
  // at the smallest step it passes a tolerance of 1e-3 with the force 1 % off
  EXPECT_GT(siconos_with_gap.front() / siconos_with_gap.back(), 5.0);
  EXPECT_LT(siconos_with_gap.back(), 1e-3);
}

TEST(ContactMerit, ImpulseMeritFloorIsTheContactsWeight) {
  // nothing loaded and nothing approaching (the box held up by its free velocity): the
  // scale is the contacts' weights over the step, so an impulse error of 1 % of the box's
  // weight reads about 1e-2 / sqrt(2) (two contacts of the same mass weigh in the floor)
  ContactProblem p = resting_box(0.02, 0.001);
  p.bodies[0].free_velocity.setZero();
  const LocalForm local = local_form(p);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6);
  r(0) = 0.01 * p.bodies[0].mass * 9.81 * p.dt;  // a stray 1 % of its weight
  const Merit impulse(MeritKind::kImpulse, local.q, contact_masses(p), local.mu, p.dt);
  const double floor = 9.81 * p.dt * contact_masses(p).norm();
  EXPECT_NEAR(impulse(r, local.W * r + local.q), (r - Eigen::VectorXd::Zero(6)).norm() / floor, 1e-12);
  EXPECT_NEAR(impulse(r, local.W * r + local.q), 0.01 / std::sqrt(2.0), 1e-12);
}

TEST(ContactMerit, ApgdStoppedOnTheImpulseMeritGivesThePlatesLoad) {
  // the sliding row (contact_scenes.hpp): the plate carries the friction of all 20 boxes
  const ContactProblem p = sliding_row();
  const double expected = kRowBoxes * kRowMu * kBoxMass * kGravity * kDt;
  MethodOptions o;
  o.tolerance = 1e-6;
  o.max_iterations = 20000;
  o.warm_start = false;
  o.merit = MeritKind::kImpulse;
  const SolverAnswer a = make_contact_method("apgd")->solve(p, o);
  EXPECT_FALSE(a.capped) << "merit " << a.residual << " after " << a.sweeps << " steps";
  // a merit of 1e-6 of the impulses: the plate's, the sum of the chain's 20 friction
  // impulses, within 1e-3 (measured 2.1e-4: the plate carries the errors of the whole
  // chain, each contact's about the merit times the island's impulses)
  EXPECT_NEAR(normal_impulse(p, a.r, [](const ProblemContact& c) { return c.on_structure; }), expected,
              1e-3 * expected);
  std::printf("sliding row, impulse merit: %d steps to %.1e\n", a.sweeps, a.residual);
}
