// Projected Gauss-Seidel on a ContactProblem (dem/contact/pgs.cpp says how).
#pragma once

#include "dem/contact/method.hpp"

namespace icedem {

class ProjectedGaussSeidel : public ContactMethod {
 public:
  /// `cone`: friction projected onto Coulomb's disc; else Bullet's square.
  explicit ProjectedGaussSeidel(bool cone) : cone_(cone) {}
  SolverAnswer solve(const ContactProblem& problem, const MethodOptions& options) override;

 private:
  bool cone_;
};

}  // namespace icedem
