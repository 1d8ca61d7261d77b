// The mass matrix of a lattice with its soft joints folded in, Mt = M + Jj^T C^-1 Jj over
// the lattice's elements (six dofs each), and its inverse applied to impulses.
//
// The contact methods fold a lattice's joints this way so that their stiff rows are not
// iterated (dem/contact/apgd.cpp says what it saves). Mt changes every step (the joints'
// rows follow the elements), so it is factorised every step. A small lattice (up to
// kDenseElements) is factorised dense (Cholesky); a larger one sparse (Eigen's simplicial
// Cholesky, AMD ordering): Mt has a 6 x 6 block for each element and each joined pair, so a
// floe of many elements (a 0.6 m floe of 0.15 m hexagons, a validation plate of 324
// elements) costs about the square of its elements' neighbours per element, not the cube of
// its size.
//
// A contact method needs Mt^-1 only where contacts act: the impulses of an iteration fall
// on the elements contacts touch, and only those elements' velocities enter the contacts'
// rows. restricted_inverse() gives that block of Mt^-1 (6 k rows for k touched elements),
// which an iteration applies in place of a solve over the whole lattice.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace icedem {

class LatticeMass {
 public:
  // the largest lattice factorised dense: 144 rows (a 0.6 m floe of 0.15 m squares has 16
  // elements)
  static constexpr int kDenseElements = 24;

  // which form: by size (kDenseElements), or one of the two (the benchmark that chose
  // kDenseElements measures both at every size: bench/micro/lattice_mass.cpp)
  enum class Form { kBySize, kDense, kSparse };

  explicit LatticeMass(int elements, Form form = Form::kBySize);
  ~LatticeMass();
  LatticeMass(LatticeMass&&) noexcept;
  LatticeMass& operator=(LatticeMass&&) noexcept;

  int elements() const { return n_; }
  bool sparse() const { return sparse_form_; }

  // Mt's block of elements i and j += m (i == j: the element's own; a joint adds both
  // (i, j) and (j, i)). Before factorise().
  void add(int i, int j, const Eigen::Matrix<double, 6, 6>& m);
  // factorise Mt; false if it is not positive definite
  bool factorise();
  // velocity = Mt^-1 impulse, stacked per element
  void solve(const Eigen::VectorXd& impulse, Eigen::VectorXd& velocity) const;
  // the block of Mt^-1 on the listed elements (rows and columns in their order, six per
  // element): W with v_k = W i_k when the impulse i falls on those elements alone. Dense:
  // Y = L^-1 E (one triangular solve of 6 k columns), W = Y^T Y; sparse: 6 k solves.
  Eigen::MatrixXd restricted_inverse(const std::vector<int>& elements) const;
  // element k's 6 x 6 block on the diagonal of Mt^-1 (what a contact on it sees of the
  // lattice's mass)
  Eigen::Matrix<double, 6, 6> inverse_block(int k) const;

 private:
  struct Factor;
  int n_;
  bool sparse_form_;
  Eigen::MatrixXd dense_;                        // Mt (dense lattices), until factorised
  std::vector<Eigen::Triplet<double>> entries_;  // Mt's entries (sparse lattices)
  std::unique_ptr<Factor> factor_;
};

}  // namespace icedem
