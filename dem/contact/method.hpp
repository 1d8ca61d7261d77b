// The contact solve stage's one interface: a method takes an island's
// ContactProblem (dem/contact/problem.hpp) and returns its impulses. Every method
// lives in its own file of dem/contact/, has one row in the registry
// (dem/contact/registry.cpp), and is measured on the problem library with the same
// merit function (natural_map_residual) by bench/contact/work_precision.py.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "dem/contact/merit.hpp"
#include "dem/contact/problem.hpp"

namespace icedem {

struct MethodOptions {
  double tolerance = 1e-6;   // stop when the merit (dem/contact/merit.hpp) is below this
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

/// Throws std::invalid_argument if `problem` has crushing contacts (dem/contact/crushing.hpp) and
/// `method`, which does not take them, was asked to solve it.
inline void refuse_crushing(const ContactProblem& problem, const std::string& method) {
  if (has_crushing(problem))
    throw std::invalid_argument("the contact method \"" + method +
                                "\" does not take crushing contacts (contact.model = \"crushing\"): \"apgd\", "
                                "\"newton\" and \"pgs_cone\" do");
}

}  // namespace icedem
