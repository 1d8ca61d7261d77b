#include "dem/contact/lattice_mass.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <iterator>
#include <utility>

#include "dem/contact/block_cholesky.hpp"

namespace icedem {

struct LatticeMass::Factor {
  Eigen::LLT<Eigen::MatrixXd> dense;
  BlockCholesky sparse;
};

// a lattice's analysed factor and the pattern it was analysed for (the joined pairs, in
// the order factorise() sorts them)
struct LatticePatterns::Kept {
  LatticeMass::Factor factor;
  std::vector<std::pair<int, int>> pairs;
  int elements = 0;
  long long used = 0;  // the solve it was last used in
};

LatticePatterns::LatticePatterns() = default;
LatticePatterns::~LatticePatterns() = default;

void LatticePatterns::next_solve() {
  if (++solve_ % kIdleSolves) return;
  for (auto it = kept_.begin(); it != kept_.end();)
    it = it->second->used < solve_ - kIdleSolves ? kept_.erase(it) : std::next(it);
}

LatticeMass::LatticeMass(int elements, Form form)
    : n_(elements), sparse_form_(form == Form::kSparse || (form == Form::kBySize && elements > kDenseElements)) {
  if (sparse())
    own_.assign(n_, Eigen::Matrix<double, 6, 6>::Zero());
  else
    dense_ = Eigen::MatrixXd::Zero(6 * n_, 6 * n_);
}

LatticeMass::~LatticeMass() = default;
LatticeMass::LatticeMass(LatticeMass&&) noexcept = default;
LatticeMass& LatticeMass::operator=(LatticeMass&&) noexcept = default;

void LatticeMass::add(int i, int j, const Eigen::Matrix<double, 6, 6>& m) {
  if (!sparse()) {
    dense_.block<6, 6>(6 * i, 6 * j) += m;
    return;
  }
  if (j > i) return;  // the factor reads the lower triangle; (j, i) comes as its transpose
  if (i == j) {
    own_[i] += m;
    return;
  }
  const auto [at, added] = below_index_.try_emplace(static_cast<long long>(i) * n_ + j, static_cast<int>(below_.size()));
  if (added)
    below_.push_back({i, j, m});
  else
    below_[at->second].m += m;
}

bool LatticeMass::factorise(LatticePatterns* patterns, long long key) {
  if (!sparse()) {
    factor_ = std::make_unique<Factor>();
    factor_->dense.compute(dense_);
    dense_.resize(0, 0);  // the factor holds what is needed
    return factor_->dense.info() == Eigen::Success;
  }
  // the joined pairs in one order whatever the order of add(), so that a lattice's pattern
  // is recognised from step to step
  std::sort(below_.begin(), below_.end(), [](const Below& a, const Below& b) { return a.j != b.j ? a.j < b.j : a.i < b.i; });
  std::vector<std::pair<int, int>> pairs(below_.size());
  std::vector<Eigen::Matrix<double, 6, 6>> values(below_.size());
  for (std::size_t e = 0; e < below_.size(); ++e) pairs[e] = {below_[e].i, below_[e].j}, values[e] = below_[e].m;
  below_ = {};
  below_index_ = {};
  Factor* factor = nullptr;
  if (!patterns) {
    factor_ = std::make_unique<Factor>();
    factor = factor_.get();
    factor->sparse.analyse(n_, pairs);
  } else {
    std::unique_ptr<LatticePatterns::Kept>& kept = patterns->kept_[key];
    if (!kept) kept = std::make_unique<LatticePatterns::Kept>();
    kept->used = patterns->solve_;
    if (kept->elements != n_ || kept->pairs != pairs) {
      kept->factor.sparse.analyse(n_, pairs);
      kept->elements = n_;
      kept->pairs = std::move(pairs);
    }
    factor = &kept->factor;
  }
  sparse_factor_ = factor;
  const bool positive = factor->sparse.factorise(own_, values);
  own_ = {};
  return positive;
}

void LatticeMass::solve(const Eigen::VectorXd& impulse, Eigen::VectorXd& velocity) const {
  if (!sparse()) {
    velocity = factor_->dense.solve(impulse);
  } else {
    velocity = impulse;
    sparse_factor_->sparse.solve(velocity);
  }
}

std::vector<int> LatticeMass::reach(const std::vector<int>& elements) const {
  return sparse_factor_->sparse.reach(elements);
}

void LatticeMass::solve_on(const std::vector<int>& reach, const Eigen::VectorXd& impulse,
                           Eigen::VectorXd& velocity) const {
  velocity.resize(impulse.size());
  sparse_factor_->sparse.solve_on(reach, impulse, velocity);
}

long long LatticeMass::reach_nonzeros(const std::vector<int>& reach) const {
  return sparse_factor_->sparse.nonzeros(reach);
}

Eigen::MatrixXd LatticeMass::restricted_inverse(const std::vector<int>& elements) const {
  if (sparse()) return sparse_factor_->sparse.inverse_on(elements);
  const int k = static_cast<int>(elements.size());
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(6 * n_, 6 * k);  // E, the listed elements' unit columns
  for (int e = 0; e < k; ++e) y.block<6, 6>(6 * elements[e], 6 * e).setIdentity();
  // Mt = L L^T, so E^T Mt^-1 E = Y^T Y with Y = L^-1 E: one forward solve, half of a solve's
  // work, and W symmetric by construction
  factor_->dense.matrixL().solveInPlace(y);
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(6 * k, 6 * k);
  w.selfadjointView<Eigen::Lower>().rankUpdate(y.transpose());
  return w.selfadjointView<Eigen::Lower>();
}

long long LatticeMass::factor_nonzeros() const {
  if (!sparse()) return 6LL * n_ * (6LL * n_ + 1) / 2;
  return sparse_factor_->sparse.nonzeros();
}

Eigen::Matrix<double, 6, 6> LatticeMass::inverse_block(int k) const { return restricted_inverse({k}); }

}  // namespace icedem
