#include "dem/contact/contact_hessian.hpp"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace icedem {

ContactHessian::ContactHessian(const ContactProblem& p, const Eigen::SparseMatrix<double>& A) : p_(p) {
  const int n = static_cast<int>(p.bodies.size());
  std::vector<std::pair<int, int>> pairs;
  std::unordered_map<long long, int> index;  // i * n + j -> its pair
  const auto pair = [&](int i, int j) {
    const auto [at, added] = index.try_emplace(static_cast<long long>(i) * n + j, static_cast<int>(pairs.size()));
    if (added) pairs.emplace_back(i, j), base_below_.push_back(Block::Zero());
    return at->second;
  };
  // A's lower triangle, by blocks (a block on the diagonal keeps its lower triangle: what the
  // factorisation reads)
  base_own_.assign(n, Block::Zero());
  for (int col = 0; col < A.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, col); it; ++it) {
      const int row = static_cast<int>(it.row());
      if (row < col) continue;
      const int i = row / 6, j = col / 6;
      if (i == j)
        base_own_[i](row % 6, col % 6) = it.value();
      else
        base_below_[pair(i, j)](row % 6, col % 6) = it.value();
    }
  pair_of_contact_.assign(p.contacts.size(), -1);
  for (std::size_t c = 0; c < p.contacts.size(); ++c) {
    const ProblemContact& k = p.contacts[c];
    if (k.a >= 0 && k.b >= 0 && k.a != k.b) pair_of_contact_[c] = pair(std::max(k.a, k.b), std::min(k.a, k.b));
  }
  llt_.analyse(n, pairs);
  reset();
}

void ContactHessian::reset() {
  own_ = base_own_;
  below_ = base_below_;
}

void ContactHessian::add(int c, const Eigen::Matrix3d& B) {
  const ProblemContact& k = p_.contacts[c];
  if (k.a >= 0 && k.a == k.b) {  // both sides on one body
    const ContactJacobian j = k.ja + k.jb;
    own_[k.a].noalias() += j.transpose() * B * j;
    return;
  }
  if (k.a >= 0) own_[k.a].noalias() += k.ja.transpose() * B * k.ja;
  if (k.b >= 0) own_[k.b].noalias() += k.jb.transpose() * B * k.jb;
  if (pair_of_contact_[c] >= 0) {
    // block (i, j), i > j: J_i^T B J_j
    if (k.a > k.b)
      below_[pair_of_contact_[c]].noalias() += k.ja.transpose() * B * k.jb;
    else
      below_[pair_of_contact_[c]].noalias() += k.jb.transpose() * B * k.ja;
  }
}

bool ContactHessian::factorise() { return llt_.factorise(own_, below_); }

void ContactHessian::solve(Eigen::VectorXd& x) const { llt_.solve(x); }

}  // namespace icedem
