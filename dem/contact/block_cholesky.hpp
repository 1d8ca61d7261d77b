// A sparse Cholesky factorisation A = P^T L L^T P of a symmetric positive definite matrix made
// of 6 x 6 blocks, one block row and column per body: a lattice's folded mass matrix Mt
// (dem/contact/lattice_mass.hpp), whose elements each carry six dofs and whose joints couple
// two elements' six with six.
//
// Why not Eigen's SimplicialLLT, which the lattices used until 2026-11-28: it orders, factorises
// and solves scalar by scalar, each nonzero reached through an index, so a block's 36 values
// cost 36 indirect loads. Here the ordering (AMD, Eigen's, on the graph of the blocks) and the
// pattern of L are of blocks, and every operation is a fixed-size 6 x 6 product that the
// compiler unrolls. bench/micro/lattice_mass.cpp measures both on the lattices runs meet.
//
// analyse() takes the pattern (the blocks below the diagonal), factorise() the values, any
// number of times for one pattern: a lattice's pattern holds while its joints do.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace icedem {

class BlockCholesky {
 public:
  using Block = Eigen::Matrix<double, 6, 6>;

  /// The pattern: n block rows and columns, and the blocks (i, j), i > j, of the lower triangle
  /// that may be nonzero (each once). factorise() takes their values in this order.
  void analyse(int n, const std::vector<std::pair<int, int>>& below);
  /// L from A's values: its n diagonal blocks and the blocks below, in analyse()'s order (block
  /// (i, j) is A's rows 6 i.., columns 6 j..). False if A is not positive definite.
  bool factorise(const std::vector<Block>& own, const std::vector<Block>& below);
  /// x = A^-1 x (6 n values, block by block)
  void solve(Eigen::VectorXd& x) const;

  /// The columns of L a solve needs when its right-hand side is nonzero on `blocks` alone and
  /// only the answer there is read: those blocks' columns and their ancestors in the
  /// elimination tree (L^-1 b is nonzero there alone, and the backward pass reaches a column
  /// from its ancestors alone), in the factor's order. A lattice touched by contacts near one
  /// edge needs the path from there to the tree's root, not the whole lattice.
  std::vector<int> reach(const std::vector<int>& blocks) const;
  /// x = A^-1 b on the blocks of a reach: b is read on them (zero elsewhere, as reach()
  /// assumes) and the answer is written there, exact; x (6 n values) elsewhere is left as it was.
  void solve_on(const std::vector<int>& reach, const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// L's scalar nonzeros in a reach's columns (what solve_on()'s cost follows)
  long long nonzeros(const std::vector<int>& reach) const;
  /// A^-1's block on the listed blocks (rows and columns in their order, six each): E^T A^-1 E
  /// = Y^T Y with Y = L^-1 P E, one forward pass over the blocks' reach (Y is zero elsewhere),
  /// symmetric by construction.
  Eigen::MatrixXd inverse_on(const std::vector<int>& blocks) const;

  /// L's scalar nonzeros: 21 per diagonal block, 36 per block below (what a solve's cost follows)
  long long nonzeros() const { return 21LL * n_ + 36LL * static_cast<long long>(row_.size()); }

 private:
  int n_ = 0;
  std::vector<int> position_;  // old block index -> its place in the factor's order
  std::vector<int> order_;     // the factor's order -> old block index
  std::vector<int> columns_;   // every column, in order: a full solve's reach
  // L's blocks below the diagonal by columns: column j's are start_[j] .. start_[j + 1], rows
  // ascending
  std::vector<int> start_, row_;
  std::vector<Block> l_;
  std::vector<Block> diagonal_;  // L's diagonal blocks (lower triangular)
  // where A's blocks go: the diagonal's to diagonal_[position_[k]], block e below to
  // l_[slot_[e]] (transposed when transpose_[e]: the permutation put it above the diagonal)
  std::vector<int> slot_;
  std::vector<char> transpose_;
};

}  // namespace icedem
