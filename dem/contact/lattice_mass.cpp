#include "dem/contact/lattice_mass.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

namespace icedem {

struct LatticeMass::Factor {
  Eigen::LLT<Eigen::MatrixXd> dense;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> sparse;
};

LatticeMass::LatticeMass(int elements, Form form)
    : n_(elements), sparse_form_(form == Form::kSparse || (form == Form::kBySize && elements > kDenseElements)) {
  if (sparse())
    entries_.reserve(static_cast<std::size_t>(36) * 5 * n_);  // own blocks and about four joined pairs
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
  for (int c = 0; c < 6; ++c)
    for (int r = 0; r < 6; ++r)
      if (6 * i + r >= 6 * j + c && m(r, c) != 0.0) entries_.emplace_back(6 * i + r, 6 * j + c, m(r, c));
}

bool LatticeMass::factorise() {
  factor_ = std::make_unique<Factor>();
  if (!sparse()) {
    factor_->dense.compute(dense_);
    dense_.resize(0, 0);  // the factor holds what is needed
    return factor_->dense.info() == Eigen::Success;
  }
  Eigen::SparseMatrix<double> Mt(6 * n_, 6 * n_);
  Mt.setFromTriplets(entries_.begin(), entries_.end());  // sums the joints' contributions
  entries_.clear();
  entries_.shrink_to_fit();
  factor_->sparse.compute(Mt);
  return factor_->sparse.info() == Eigen::Success;
}

void LatticeMass::solve(const Eigen::VectorXd& impulse, Eigen::VectorXd& velocity) const {
  if (!sparse())
    velocity = factor_->dense.solve(impulse);
  else
    velocity = factor_->sparse.solve(impulse);
}

Eigen::MatrixXd LatticeMass::restricted_inverse(const std::vector<int>& elements) const {
  const int k = static_cast<int>(elements.size());
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(6 * n_, 6 * k);
  for (int e = 0; e < k; ++e) unit.block<6, 6>(6 * elements[e], 6 * e).setIdentity();
  if (!sparse()) {
    // Mt = L L^T, so E^T Mt^-1 E = (L^-1 E)^T (L^-1 E): one forward solve, half of a
    // solve's work, and W symmetric by construction
    factor_->dense.matrixL().solveInPlace(unit);
    Eigen::MatrixXd w(6 * k, 6 * k);
    w.setZero();
    w.selfadjointView<Eigen::Lower>().rankUpdate(unit.transpose());
    return w.selfadjointView<Eigen::Lower>();
  }
  const Eigen::MatrixXd columns = factor_->sparse.solve(unit);
  Eigen::MatrixXd w(6 * k, 6 * k);
  for (int e = 0; e < k; ++e) w.middleRows<6>(6 * e) = columns.middleRows<6>(6 * elements[e]);
  return w;
}

Eigen::Matrix<double, 6, 6> LatticeMass::inverse_block(int k) const { return restricted_inverse({k}); }

}  // namespace icedem
