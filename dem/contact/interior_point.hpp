// A primal-dual interior-point method for the contact problem (on velocities, as the
// primal Newton method), exact for Coulomb's law through De Saxce's shift.
//
// For a fixed shift s_c = mu |u_T,c| on each normal, Coulomb's law is the optimality
// condition of a convex second-order cone program in the bodies' velocities v:
//
//   min 1/2 v^T Mt v - ft^T v   subject to   y_c = D_c (u_c + (s_c, 0, 0)) in Q,  u = Jc v + w,
//
// with the soft joints folded into Mt, D_c = diag(1, mu, mu) taking Coulomb's dual cone
// {u_N >= mu |u_T|} to the standard second-order cone Q = {x_0 >= |x_1|}; its multipliers
// z_c in Q are the impulses scaled back, r_c = (z_N, mu z_T). The method follows
// Vandenberghe's conic QP solver (CVXOPT's coneqp): Nesterov-Todd scaling per cone,
// Mehrotra's predictor-corrector, and each iteration one sparse Cholesky factorisation of
//
//   H = Mt + Jc^T D W^-2 D Jc    (the pattern of the primal Newton method's Hessian),
//
// whose pattern is analysed once per problem. The shift is taken from the current
// velocities at every iteration (the primal residual carries its change), so the fixed
// point and the cone program's optimum are reached together; the answer is judged, as the
// primal Newton method's, by the impulses it returns and the velocities they give.
//
// Why: the gradient method's count of steps grows with the island's conditioning (the
// stiff joint rows of a lattice, the long force chains of a jam) and the primal Newton
// method's outer proximal loop converges linearly; an interior-point method's count of
// factorisations hardly depends on either (docs/model/contact_problems.md measures it).
#pragma once

#include "dem/contact/method.hpp"

namespace icedem {

class InteriorPoint : public ContactMethod {
 public:
  struct Settings {
    // how far into the cones the warm start is pushed, relative to the largest impulse
    // (and speed) of the start: the starting point must be interior, and one too near the
    // boundary stalls the first steps
    double start_margin = 1e-2;
    double step_fraction = 0.99;  // of the step to the cones' boundary
    // a step shorter than restart_step after the gap fell below restart_gap of the first
    // iteration's is a stall: the iterates are pushed back in by restart_margin (relative, as
    // start_margin). Without it, 2 of 3 islands of a level sheet stopped at 8e-6 and 1e-4 on
    // the boundary, short of 3e-6 (docs/model/contact_problems.md)
    double restart_step = 1e-2;
    double restart_gap = 1e-4;
    double restart_margin = 1e-3;
  };
  InteriorPoint() = default;
  explicit InteriorPoint(const Settings& settings) : settings_(settings) {}
  /// `sweeps` of the answer counts the iterations (each one factorisation).
  SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) override;

 private:
  Settings settings_;
};

}  // namespace icedem
