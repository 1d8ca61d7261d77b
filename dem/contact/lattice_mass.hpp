// The mass matrix of a lattice with its soft joints folded in, Mt = M + Jj^T C^-1 Jj over
// the lattice's elements (six dofs each), and its inverse applied to impulses.
//
// The contact methods fold a lattice's joints this way so that their stiff rows are not
// iterated (dem/contact/apgd.cpp says what it saves). Mt changes every step (the joints'
// rows follow the elements), so it is factorised every step. A small lattice (up to
// kDenseElements) keeps a dense inverse: one product a step of the method, as fast as a
// factor's two triangular solves at that size and bit for bit what the runs have computed
// since folding came in. A larger one is factorised sparse (Eigen's simplicial Cholesky,
// AMD ordering): Mt has a 6 x 6 block for each element and each joined pair, so a floe of
// many elements (a 0.6 m floe of 0.15 m hexagons, a validation plate of 324 elements)
// costs about the square of its elements' neighbours per element, not the cube of its size.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace icedem {

class LatticeMass {
 public:
  // the largest lattice kept dense: 144 rows (a 0.6 m floe of 0.15 m squares has 16
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
  // element k's 6 x 6 block on the diagonal of Mt^-1 (what a contact on it sees of the
  // lattice's mass); a sparse factor solves for its six columns
  Eigen::Matrix<double, 6, 6> inverse_block(int k) const;

 private:
  struct Sparse;
  int n_;
  bool sparse_form_;
  Eigen::MatrixXd dense_;  // Mt, then Mt^-1 (dense lattices)
  std::vector<Eigen::Triplet<double>> entries_;  // Mt's entries (sparse lattices)
  std::unique_ptr<Sparse> sparse_;
};

}  // namespace icedem
