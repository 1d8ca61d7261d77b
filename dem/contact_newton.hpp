// A primal Newton method for the contact problem (on velocities, as MuJoCo's),
// exact for Coulomb's law through an outer proximal-point loop. EXPERIMENTAL: a
// candidate of the solver study, not used by runs (docs/model/contact_problems.md
// has its measured convergence).
//
// The unknown is the bodies' velocity v (its size follows the bodies, not the
// redundant contact points). For a proximal centre rb (contact impulses) and a
// weight rho per contact, the contact impulses are
//   r_c(v) = P_K(rb_c - (u_c + s_c) / rho_c),  u = Jc v + w,  s_c = (mu |u_T,c|, 0, 0)
// (De Saxce's shift inside), and Newton solves the momentum balance
//   G(v) = M (v - v_free) + Jj^T C^-1 (Jj v + b) - Jc^T r(v) = 0
// with the semismooth Jacobian M + Jj^T C^-1 Jj + Jc^T B Jc (sparse LU, its pattern
// analysed once per problem) and a backtracking line search on |G|^2 in M^-1's metric.
// The outer loop sets rb = r: its fixed point is r = P_K(r - (u + s) / rho), a zero
// of natural_map_residual. rho is a fraction of each contact's effective inverse mass.
// Measured: without friction it converges in about ten outer iterations; with
// friction the line search stalls and the outer loop converges linearly (slowly).
#pragma once

#include "dem/contact_method.hpp"

namespace icedem {

class PrimalNewton : public ContactMethod {
 public:
  struct Settings {
    double rho_fraction = 0.001;  // rho_c = this times the mean diagonal of J_c M^-1 J_c^T
    int inner_iterations = 30;  // Newton steps per outer iteration, at most
  };
  PrimalNewton() = default;
  explicit PrimalNewton(const Settings& settings) : settings_(settings) {}
  /// `sweeps` of the answer counts Newton steps (each one factorisation).
  SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) override;

 private:
  Settings settings_;
};

}  // namespace icedem
