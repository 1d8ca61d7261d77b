#include "dem/contact/lattice_mass.hpp"

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>

namespace icedem {

struct LatticeMass::Sparse {
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>> cholesky;
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
  if (!sparse()) {
    const Eigen::LLT<Eigen::MatrixXd> llt(dense_);
    if (llt.info() != Eigen::Success) return false;
    dense_ = llt.solve(Eigen::MatrixXd::Identity(6 * n_, 6 * n_));
    return true;
  }
  Eigen::SparseMatrix<double> Mt(6 * n_, 6 * n_);
  Mt.setFromTriplets(entries_.begin(), entries_.end());  // sums the joints' contributions
  entries_.clear();
  entries_.shrink_to_fit();
  sparse_ = std::make_unique<Sparse>();
  sparse_->cholesky.compute(Mt);
  return sparse_->cholesky.info() == Eigen::Success;
}

void LatticeMass::solve(const Eigen::VectorXd& impulse, Eigen::VectorXd& velocity) const {
  if (!sparse())
    velocity.noalias() = dense_ * impulse;
  else
    velocity = sparse_->cholesky.solve(impulse);
}

Eigen::Matrix<double, 6, 6> LatticeMass::inverse_block(int k) const {
  if (!sparse()) return dense_.block<6, 6>(6 * k, 6 * k);
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(6 * n_, 6);
  unit.block<6, 6>(6 * k, 0).setIdentity();
  const Eigen::MatrixXd columns = sparse_->cholesky.solve(unit);
  return columns.block<6, 6>(6 * k, 0);
}

}  // namespace icedem
