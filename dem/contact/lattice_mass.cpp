#include "dem/contact/lattice_mass.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <iterator>

namespace icedem {

struct LatticeMass::Factor {
  Eigen::LLT<Eigen::MatrixXd> dense;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> sparse;
};

// a lattice's analysed factor and the pattern it was analysed for (Mt's compressed
// columns: their starts and row indices)
struct LatticePatterns::Kept {
  LatticeMass::Factor factor;
  std::vector<int> starts, rows;
  long long used = 0;  // the solve it was last used in

  bool same_pattern(const Eigen::SparseMatrix<double>& m) const {
    return starts.size() == static_cast<std::size_t>(m.outerSize() + 1) &&
           rows.size() == static_cast<std::size_t>(m.nonZeros()) &&
           std::equal(starts.begin(), starts.end(), m.outerIndexPtr()) &&
           std::equal(rows.begin(), rows.end(), m.innerIndexPtr());
  }
  void keep_pattern(const Eigen::SparseMatrix<double>& m) {
    starts.assign(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1);
    rows.assign(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros());
  }
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

namespace {

// Mt's lower triangle in compressed columns, written straight from its blocks: column 6 j
// + c holds element j's own block from row 6 j + c down, then the blocks of the elements
// joined to j above it, in the order of their rows
template <class Below>
void compress(int n, const std::vector<Eigen::Matrix<double, 6, 6>>& own, std::vector<Below>& below,
              Eigen::SparseMatrix<double>& m) {
  std::sort(below.begin(), below.end(), [](const Below& a, const Below& b) { return a.j != b.j ? a.j < b.j : a.i < b.i; });
  m.resize(6 * n, 6 * n);
  m.resizeNonZeros(21 * n + 36 * static_cast<int>(below.size()));
  int* start = m.outerIndexPtr();
  int* row = m.innerIndexPtr();
  double* value = m.valuePtr();
  int k = 0;
  auto block = below.begin();
  for (int j = 0; j < n; ++j) {
    const auto first = block;
    while (block != below.end() && block->j == j) ++block;
    for (int c = 0; c < 6; ++c) {
      start[6 * j + c] = k;
      for (int r = c; r < 6; ++r) row[k] = 6 * j + r, value[k++] = own[j](r, c);
      for (auto b = first; b != block; ++b)
        for (int r = 0; r < 6; ++r) row[k] = 6 * b->i + r, value[k++] = b->m(r, c);
    }
  }
  start[6 * n] = k;
}

}  // namespace

bool LatticeMass::factorise(LatticePatterns* patterns, long long key) {
  if (!sparse()) {
    factor_ = std::make_unique<Factor>();
    factor_->dense.compute(dense_);
    dense_.resize(0, 0);  // the factor holds what is needed
    return factor_->dense.info() == Eigen::Success;
  }
  Eigen::SparseMatrix<double> Mt;
  compress(n_, own_, below_, Mt);
  own_ = {};
  below_ = {};
  below_index_ = {};
  if (!patterns) {
    factor_ = std::make_unique<Factor>();
    factor_->sparse.compute(Mt);
    sparse_factor_ = factor_.get();
    return factor_->sparse.info() == Eigen::Success;
  }
  std::unique_ptr<LatticePatterns::Kept>& kept = patterns->kept_[key];
  if (!kept) kept = std::make_unique<LatticePatterns::Kept>();
  kept->used = patterns->solve_;
  if (!kept->same_pattern(Mt)) {
    kept->factor.sparse.analyzePattern(Mt);
    kept->keep_pattern(Mt);
  }
  kept->factor.sparse.factorize(Mt);
  sparse_factor_ = &kept->factor;
  return kept->factor.sparse.info() == Eigen::Success;
}

void LatticeMass::solve(const Eigen::VectorXd& impulse, Eigen::VectorXd& velocity) const {
  if (!sparse())
    velocity = factor_->dense.solve(impulse);
  else
    velocity = sparse_factor_->sparse.solve(impulse);
}

Eigen::MatrixXd LatticeMass::restricted_inverse(const std::vector<int>& elements) const {
  const int k = static_cast<int>(elements.size());
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(6 * n_, 6 * k);  // E, the listed elements' unit columns
  for (int e = 0; e < k; ++e) y.block<6, 6>(6 * elements[e], 6 * e).setIdentity();
  // Mt = L L^T (dense), or P^T L L^T P with the sparse factor's fill-reducing ordering, so
  // E^T Mt^-1 E = Y^T Y with Y = L^-1 E, or L^-1 P E: one forward solve, half of a solve's
  // work, and W symmetric by construction
  if (!sparse()) {
    factor_->dense.matrixL().solveInPlace(y);
  } else {
    const auto& llt = sparse_factor_->sparse;
    if (llt.permutationP().size()) y = Eigen::MatrixXd(llt.permutationP() * y);
    llt.matrixL().solveInPlace(y);
  }
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(6 * k, 6 * k);
  w.selfadjointView<Eigen::Lower>().rankUpdate(y.transpose());
  return w.selfadjointView<Eigen::Lower>();
}

long long LatticeMass::factor_nonzeros() const {
  if (!sparse()) return 6LL * n_ * (6LL * n_ + 1) / 2;
  return sparse_factor_->sparse.matrixL().nestedExpression().nonZeros();
}

Eigen::Matrix<double, 6, 6> LatticeMass::inverse_block(int k) const { return restricted_inverse({k}); }

}  // namespace icedem
