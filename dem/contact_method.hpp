// The contact solve stage's one interface: a method takes an island's
// ContactProblem (dem/contact_problem.hpp) and returns its impulses. Every method
// lives in its own file, contact_<method>.cpp, and is measured on the problem
// library with the same merit function (natural_map_residual) by
// bench/contact/work_precision.py.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dem/contact_merit.hpp"
#include "dem/contact_problem.hpp"

namespace icedem {

struct MethodOptions {
  double tolerance = 1e-6;   // stop when the merit (dem/contact_merit.hpp) is below this
  MeritKind merit = MeritKind::kSiconos;  // the library's common measure; a run stops on kImpulse
  int max_iterations = 200;  // and at the latest after this many iterations
  bool warm_start = true;    // start from the problem's guess (else from zero)
};

class ContactMethod {
 public:
  virtual ~ContactMethod() = default;
  /// Solve `problem`. The answer's `sweeps` are the method's iterations, `residual` its
  /// own error measure at the end, `capped` whether it stopped at max_iterations above
  /// the tolerance.
  virtual SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) = 0;
};

/// The methods by name: "pgs" (Bullet's projected Gauss-Seidel rows: normal rows, then
/// each friction direction clamped on its own), "pgs_cone" (the same with Coulomb's
/// disc: both friction rows of a contact projected together), "newton" (primal
/// Newton: dem/contact_newton.hpp), "apgd" (accelerated projected gradient, as Project
/// Chrono's: dem/contact_apgd.hpp), "siconos_nsgs",
/// "siconos_nsn_ac", "siconos_nsn_fb", "siconos_prox", "siconos_admm" (Siconos numerics on
/// the Delassus form).
/// Throws std::invalid_argument for an unknown name.
std::unique_ptr<ContactMethod> make_contact_method(const std::string& name);
std::vector<std::string> contact_method_names();

}  // namespace icedem
