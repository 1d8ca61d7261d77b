// A primal Newton method for the contact problem (on velocities, as MuJoCo's),
// exact for Coulomb's law through an outer proximal-point loop.
//
// The unknown is the bodies' velocity v: its size follows the bodies, not the
// redundant contact points, so the four points of a face resting on another
// (a rank-deficient Delassus matrix, where dual Newton methods fail) cost
// nothing special. For a proximal centre rb (contact impulses), a shift s
// (De Saxce's mu |u_T| on each normal) and a weight rho_c per contact, the inner
// problem is the minimum of the convex function
//
//   f(v) = 1/2 (v - v_free)^T M (v - v_free) + 1/2 (Jj v + b)^T C^-1 (Jj v + b)
//        + sum_c rho_c / 2 |P_K(rb_c - (u_c + s_c) / rho_c)|^2,    u = Jc v + w,
//
// (1/2 |P_K(z)|^2 is convex with gradient P_K(z), Moreau), whose gradient is the
// momentum balance G(v) = M (v - v_free) + Jj^T C^-1 (Jj v + b) - Jc^T r(v) with
// r_c(v) = P_K(rb_c - (u_c + s_c) / rho_c). Newton steps use the generalised Hessian
// H = M + Jj^T C^-1 Jj + Jc^T diag(dP_K / rho) Jc (symmetric positive definite:
// a sparse Cholesky factorisation, its pattern analysed once per problem) and an
// exact line search along the step (f is convex, so its derivative along the step is
// monotone; each trial costs O(contacts), no sparse product). The outer loop sets rb = r and s = mu |u_T|: its fixed point is
// r = P_K(r - (u + (mu |u_T|, 0, 0)) / rho), a zero of natural_map_residual.
// rho is a small fraction of each contact's effective inverse mass: the smaller, the
// longer the proximal steps, but the stiffer the inner problem, whose contacts then
// change state one by one; 1e-3 was the best of 1e-2, 1e-3 and 1e-4 on the problem
// library (docs/model/contact_problems.md has the measurements and what is still slow).
// A crushing contact's set is the cone cut at its normal cap (dem/contact/crushing.hpp):
// K is then that truncated cone, P_K project_on_contact, and dP_K its derivative (the
// normal held where the cut is reached), the rest unchanged.
#pragma once

#include "dem/contact/method.hpp"

namespace icedem {

class PrimalNewton : public ContactMethod {
 public:
  struct Settings {
    double rho_fraction = 1e-3;  // rho_c = this times the mean diagonal of J_c M^-1 J_c^T
    int inner_iterations = 20;   // Newton steps per outer iteration, at most
  };
  PrimalNewton() = default;
  explicit PrimalNewton(const Settings& settings) : settings_(settings) {}
  /// `sweeps` of the answer counts Newton steps (each one factorisation).
  SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) override;

 private:
  Settings settings_;
};

}  // namespace icedem
