// The mass matrix of a lattice with its soft joints folded in, Mt = M + Jj^T C^-1 Jj over
// the lattice's elements (six dofs each), and its inverse applied to impulses.
//
// The contact methods fold a lattice's joints this way so that their stiff rows are not
// iterated (dem/contact/apgd.cpp says what it saves). Mt changes every step (the joints'
// rows follow the elements), so it is factorised every step. A lattice of a few elements
// (up to kDenseElements) is factorised dense (Cholesky); a larger one sparse, by blocks
// (dem/contact/block_cholesky.hpp, AMD ordering of the elements): Mt has a 6 x 6 block for
// each element and each joined pair, so a floe of many elements costs about the square of
// its elements' neighbours per element, not the cube of its size, and its pattern's
// analysis can be kept from step to step (LatticePatterns).
//
// A contact method needs Mt^-1 only where contacts act: the impulses of an iteration fall
// on the elements contacts touch, and only those elements' velocities enter the contacts'
// rows. restricted_inverse() gives that block of Mt^-1 (6 k rows for k touched elements),
// which an iteration applies in place of a solve over the whole lattice.
#pragma once

#include <memory>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

namespace icedem {

// The symbolic analyses of the sparse lattices a contact method has factorised (the
// fill-reducing ordering and the factor's pattern), kept between its solves, one per
// lattice. Mt's pattern follows the lattice's joints alone, which hold for many steps, so a
// step pays the numeric factorisation alone (a 0.6 m floe of 0.15 m squares: about a fifth
// of the whole factorisation, bench/micro/lattice_mass.cpp). A pattern that changed (a
// joint broke, another problem under the same key) is analysed again: the factor is the
// one a fresh analysis gives, bit for bit.
class LatticePatterns {
 public:
  LatticePatterns();
  ~LatticePatterns();
  LatticePatterns(const LatticePatterns&) = delete;
  LatticePatterns& operator=(const LatticePatterns&) = delete;
  std::size_t size() const { return kept_.size(); }
  // one solve more: every kIdleSolves, the analyses no lattice used in the last kIdleSolves
  // are dropped (a lattice that broke, or a level sheet whose free part changed, leaves its
  // old one behind; one of a few hundred elements holds about a megabyte)
  void next_solve();
  static constexpr long long kIdleSolves = 2000;

 private:
  friend class LatticeMass;
  struct Kept;
  std::unordered_map<long long, std::unique_ptr<Kept>> kept_;
  long long solve_ = 0;
};

class LatticeMass {
 public:
  // the largest lattice factorised dense. With the pattern kept, a grid of 0.15 m squares
  // costs (assembly and factorisation, bench/micro/lattice_mass.cpp, 2026-11-27): 4
  // elements 2.4 us dense, 5.1 us sparse; 9 (a 0.6 m floe of 0.20 m squares) 16 and 17 us;
  // 16 (of 0.15 m squares) 71 and 36 us. Until then it was 24, the limit for a dense inverse.
  static constexpr int kDenseElements = 9;

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
  // factorise Mt; false if it is not positive definite. A sparse Mt reuses the analysis
  // kept in `patterns` under `key` (the caller's name for the lattice, say its first
  // element's id) when its pattern is the same, and keeps its own there; `patterns` must
  // outlive this object.
  bool factorise(LatticePatterns* patterns = nullptr, long long key = 0);
  // velocity = Mt^-1 impulse, stacked per element
  void solve(const Eigen::VectorXd& impulse, Eigen::VectorXd& velocity) const;
  // The same for an impulse on the listed elements alone, whose velocities alone are read
  // (sparse form, after factorise()): reach() is what such a solve needs of the factor (the
  // listed elements and their ancestors in the elimination tree, BlockCholesky::reach), once
  // per set of elements; solve_on() writes exact velocities on the listed elements (and the
  // rest of the reach) and leaves the other elements' as they were.
  std::vector<int> reach(const std::vector<int>& elements) const;
  void solve_on(const std::vector<int>& reach, const Eigen::VectorXd& impulse, Eigen::VectorXd& velocity) const;
  // the factor's nonzeros in a reach (solve_on()'s cost, as factor_nonzeros() is solve()'s)
  long long reach_nonzeros(const std::vector<int>& reach) const;
  // the block of Mt^-1 on the listed elements (rows and columns in their order, six per
  // element): W with v_k = W i_k when the impulse i falls on those elements alone. W = Y^T Y,
  // Y = L^-1 E (P E sparse): one triangular solve of 6 k columns, the sparse form's over the
  // elements' reach alone.
  Eigen::MatrixXd restricted_inverse(const std::vector<int>& elements) const;
  // the factor's nonzeros (a solve costs about four flops each: both triangles, multiply
  // and add); after factorise()
  long long factor_nonzeros() const;
  // element k's 6 x 6 block on the diagonal of Mt^-1 (what a contact on it sees of the
  // lattice's mass)
  Eigen::Matrix<double, 6, 6> inverse_block(int k) const;

 private:
  friend class LatticePatterns;
  struct Factor;
  int n_;
  bool sparse_form_;
  Eigen::MatrixXd dense_;                        // Mt (dense lattices), until factorised
  // Mt's blocks (sparse lattices): each element's own, and each joined pair's below the
  // diagonal (i > j), summed as add() comes; kept whole, zeros too, so that the pattern is
  // the lattice's joints' and holds from step to step
  struct Below {
    int i, j;
    Eigen::Matrix<double, 6, 6> m;
  };
  std::vector<Eigen::Matrix<double, 6, 6>> own_;
  std::vector<Below> below_;
  std::unordered_map<long long, int> below_index_;  // i * n + j -> its place in below_
  std::unique_ptr<Factor> factor_;
  const Factor* sparse_factor_ = nullptr;  // factor_, or the one kept in a LatticePatterns
};

}  // namespace icedem
