// Siconos numerics (Debian libsiconos-numerics-dev) as a contact method: its
// fc3d solvers on the Delassus form of the problem (joints folded in,
// dem/contact_problem.hpp), the joint impulses recovered from the contact
// impulses afterwards.
#pragma once

#include "dem/contact_method.hpp"

namespace icedem {

class SiconosMethod : public ContactMethod {
 public:
  /// `solver`: a SICONOS_FRICTION_3D_* id (Friction_cst.h), e.g. 500 NSGS, 504 NSN_AC, 513 NSN_FB.
  explicit SiconosMethod(int solver) : solver_(solver) {}
  SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) override;
  /// The same on a Delassus form already built (its time is then not counted).
  SolverAnswer solve_local(const LocalForm& local, const Eigen::VectorXd& guess, const MethodOptions& options);

 private:
  int solver_;
};

}  // namespace icedem
