// Siconos numerics (Debian libsiconos-numerics-dev) as a contact method: its
// fc3d solvers on the Delassus form of the problem (joints folded in,
// dem/contact/problem.hpp), the joint impulses recovered from the contact
// impulses afterwards. Not in the program: its own library (icedem_contact_siconos), which the
// benchmark and the tests link and register (register_siconos_methods).
#pragma once

#include "dem/contact/method.hpp"

namespace icedem {

class SiconosMethod : public ContactMethod {
 public:
  /// Siconos numerics' SICONOS_FRICTION_3D_* solver ids (siconos/numerics/Friction_cst.h)
  static constexpr int kNsgs = 500, kProx = 502, kNsnAc = 504, kNsnFb = 513, kAdmm = 523;
  /// `solver`: one of the ids above.
  explicit SiconosMethod(int solver) : solver_(solver) {}
  SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) override;
  /// The same on a Delassus form already built (its time is then not counted).
  SolverAnswer solve_local(const LocalForm& local, const Eigen::VectorXd& guess, const MethodOptions& options);

 private:
  int solver_;
};

/// Adds "siconos_nsgs", "siconos_nsn_ac", "siconos_nsn_fb", "siconos_prox" and "siconos_admm" to
/// the contact methods (dem/contact/registry.hpp), once however often it is called.
void register_siconos_methods();

}  // namespace icedem
