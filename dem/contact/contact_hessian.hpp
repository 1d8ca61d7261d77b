// The matrix of the second-order contact methods' linear systems (the primal Newton method's
// Hessian, the interior-point method's Newton matrix), and its factorisation:
//
//   H = A + sum_c Jc_c^T B_c Jc_c,
//
// A the mass matrix with the soft joints folded in, B_c a 3x3 weight per contact carried onto
// the 6x6 blocks of its bodies. H is held as 6x6 blocks, one per body and one per pair of bodies
// a joint or a contact couples, and factorised by blocks (dem/contact/block_cholesky.hpp: on a
// level sheet's islands Eigen's scalar simplicial factorisation of it was 38 % of a run's CPU).
// The pattern is analysed once per problem; each new set of weights refills the values.
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "dem/contact/block_cholesky.hpp"
#include "dem/contact/problem.hpp"

namespace icedem {

class ContactHessian {
 public:
  /// The pattern of A and of every contact's body blocks, analysed; H = A.
  ContactHessian(const ContactProblem& p, const Eigen::SparseMatrix<double>& A);
  /// H = A again.
  void reset();
  /// H += Jc_c^T B Jc_c for contact c.
  void add(int c, const Eigen::Matrix3d& B);
  /// Factorise H; false if it is not positive definite.
  bool factorise();
  /// x = H^-1 x, after factorise().
  void solve(Eigen::VectorXd& x) const;

 private:
  using Block = BlockCholesky::Block;
  const ContactProblem& p_;
  std::vector<Block> own_, below_;            // H's blocks: per body, per coupled pair (i > j)
  std::vector<Block> base_own_, base_below_;  // A's
  std::vector<int> pair_of_contact_;          // the contact's pair block in below_ (-1: one body)
  BlockCholesky llt_;
};

}  // namespace icedem
