// The sparse matrix of the second-order contact methods' linear systems (the primal Newton
// method's Hessian, the interior-point method's Newton matrix):
//
//   H = A + sum_c Jc_c^T B_c Jc_c,
//
// A the mass matrix with the soft joints folded in, B_c a 3x3 weight per contact carried onto
// the 6x6 blocks of its bodies. Lower triangle only (what the Cholesky factorisations read); the
// pattern is built once per problem and each new set of weights refills the values in place.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "dem/contact/problem.hpp"

namespace icedem {

class ContactHessian {
 public:
  /// The pattern of A's lower triangle and of every contact's body blocks; H = A.
  ContactHessian(const ContactProblem& p, const Eigen::SparseMatrix<double>& A);
  /// H = A again.
  void reset();
  /// H += Jc_c^T B Jc_c for contact c.
  void add(int c, const Eigen::Matrix3d& B);
  const Eigen::SparseMatrix<double>& matrix() const { return H_; }

 private:
  const ContactProblem& p_;
  Eigen::SparseMatrix<double> H_;
  Eigen::VectorXd base_;                 // A's values in H's pattern
  std::vector<std::vector<int>> slots_;  // per contact, where each entry of its body blocks lies (-1: above)
};

}  // namespace icedem
