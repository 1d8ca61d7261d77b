// Accelerated projected gradient descent (APGD) on the dual of the contact problem,
// as Project Chrono solves contact (Mazhar, Heyn, Negrut, Tasora 2015: Nesterov's
// method with an adaptive step and restart).
//
// The unknown is the impulses x = (r of the contacts, l of the joint rows); the
// velocities they give are v(x) = v_free + M^-1 J^T x. Each iteration takes a projected
// gradient step from an extrapolated point y,
//
//   x+ = P(y - t D g(y)),   g(x) = J v(x) + (w, b) + (shift, C l),
//
// where P projects each contact's impulse onto its friction cone (a joint row is free),
// D scales each contact and joint row by its effective mass, split among the rows on its
// bodies (a scalar per contact, so P is unchanged by it) and t = 1/L comes from a
// backtracking test on
// f(x) = 1/2 x^T (J M^-1 J^T + C) x + x^T (J v_free + (w, b) + shift). The shift is
// De Saxce's mu |u_T| on each normal, taken at y: without it the method solves the
// convex relaxation of Coulomb's law (Chrono's cone complementarity problem), where a
// sliding contact opens at mu |u_T|; with it the fixed point is Coulomb's law. The
// extrapolation restarts when the step goes uphill (O'Donoghue and Candes). The merit
// (natural_map_residual, with the joint rows' equation) is taken every 4th step, and the
// answer is the iterate with the lowest merit seen.
#pragma once

#include "dem/contact/lattice_mass.hpp"
#include "dem/contact/method.hpp"

namespace icedem {

class AcceleratedProjectedGradient : public ContactMethod {
 public:
  /// `sweeps` of the answer counts gradient steps (each one product with J M^-1 J^T,
  /// plus one per backtracking trial).
  SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) override;

 private:
  // the lattices' analysed patterns, kept from one solve to the next (a cache: the
  // answers are those of a fresh analysis, so a run resumed from a checkpoint, which
  // starts without it, repeats the run bit for bit)
  LatticePatterns lattice_patterns_;
};

}  // namespace icedem
