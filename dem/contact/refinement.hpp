// Whether a method's answer, started from another's, is a better answer to take in its place
// (the hand-over at the cap, the breaking solves' stages: dem/contact/island_solve.cpp).
//
// A lower merit alone does not say so. The impulse merit (dem/contact/merit.hpp) is relative
// to the answer's own impulses, and where the problem's solutions are not bounded an answer
// can lower it by growing them: a free element wedged between held (fixed) pieces has
// contacts whose normals oppose, any equal push on both is a solution, and the interior-point
// method runs off along that direction towards its analytic centre. On a level tow (2.0 m,
// 0.02 s) the finisher of a breaking solve, started from the gradient method's answer at
// 3e-6, put 395 N s on one such element's contact where the gradient method had 0.02 (the
// island's impulses 7.9 -> 562 N s, its merit 2.8e-6 -> 5.7e-7). The run took such answers:
// at t = 127.54 s the element's warm start for the next step held 1.4e7 N s on two opposing
// contacts, and their imbalance then launched it at 503 m/s (the run stopped on the blow-up;
// with this rule it went on). A method that refines an answer moves its impulses by about its
// merit times their size (10 % at a merit of 0.1): an answer whose impulses grew by more than
// kRefinementGrowth is not a refinement of the one it started from, whatever its merit.
#pragma once

#include <algorithm>
#include <cmath>

#include "dem/contact/problem.hpp"
#include "dem/core/constants.hpp"

namespace icedem {

/// How much larger an answer's impulses may be than those it started from, and still count
/// as a refinement of them.
constexpr double kRefinementGrowth = 10.0;

/// The size of an answer's impulses, N s: |(r, l)|.
inline double impulse_norm(const SolverAnswer& a) { return std::sqrt(a.r.squaredNorm() + a.l.squaredNorm()); }

/// The island's weight over the step, N s: the impulses a resting island carries, the least size
/// a later answer is judged against (refines' floor).
inline double weight_impulse(const ContactProblem& p) {
  double mass = 0;
  for (const ProblemBody& b : p.bodies) mass += b.mass;
  return std::max(kMeritGravity * p.dt * mass, 1e-12);
}

/// Whether `next`, solved from `from`'s answer, lowered the merit by running off: a merit no
/// higher, with impulses more than kRefinementGrowth times `from`'s. `floor` (N s, > 0) stands in
/// for `from`'s size when that is smaller, so that an answer started from rest may load up.
inline bool runs_off(const SolverAnswer& from, const SolverAnswer& next, double floor) {
  return next.residual <= from.residual &&
         impulse_norm(next) > kRefinementGrowth * std::max(impulse_norm(from), floor);
}

/// Whether `next`, solved from `from`'s answer, is the better answer: a merit no higher, without
/// running off (runs_off).
inline bool refines(const SolverAnswer& from, const SolverAnswer& next, double floor) {
  return next.residual <= from.residual && !runs_off(from, next, floor);
}

}  // namespace icedem
