#include "dem/contact/contact_hessian.hpp"

#include <algorithm>

namespace icedem {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// position of (row, col) in the compressed values of H
int slot(const SparseMatrix& H, int row, int col) {
  const int* begin = H.innerIndexPtr() + H.outerIndexPtr()[col];
  const int* end = H.innerIndexPtr() + H.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - H.innerIndexPtr());
}

// the lower-triangle body blocks (i, j) a contact fills: i >= j, both with unknown velocity
template <class Visit>
void each_block(const ProblemContact& k, Visit&& visit) {
  for (int i : {k.a, k.b})
    for (int j : {k.a, k.b})
      if (i >= 0 && j >= 0 && i >= j) visit(i, j);
}

}  // namespace

ContactHessian::ContactHessian(const ContactProblem& p, const SparseMatrix& A) : p_(p) {
  std::vector<Eigen::Triplet<double>> t;
  for (int col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      if (it.row() >= it.col()) t.emplace_back(it.row(), it.col(), it.value());
  for (const ProblemContact& k : p.contacts)
    each_block(k, [&](int i, int j) {
      for (int r = 0; r < 6; ++r)
        for (int s = 0; s < 6; ++s)
          if (6 * i + r >= 6 * j + s) t.emplace_back(6 * i + r, 6 * j + s, 0.0);
    });
  H_.resize(p.dofs(), p.dofs());
  H_.setFromTriplets(t.begin(), t.end());
  H_.makeCompressed();
  base_ = Eigen::Map<const Eigen::VectorXd>(H_.valuePtr(), H_.nonZeros());
  slots_.resize(p.contacts.size());
  for (std::size_t c = 0; c < p.contacts.size(); ++c)
    each_block(p.contacts[c], [&](int i, int j) {
      for (int r = 0; r < 6; ++r)
        for (int s = 0; s < 6; ++s) slots_[c].push_back(6 * i + r >= 6 * j + s ? slot(H_, 6 * i + r, 6 * j + s) : -1);
    });
}

void ContactHessian::reset() { Eigen::Map<Eigen::VectorXd>(H_.valuePtr(), H_.nonZeros()) = base_; }

void ContactHessian::add(int c, const Eigen::Matrix3d& B) {
  const ProblemContact& k = p_.contacts[c];
  int at = 0;
  each_block(k, [&](int i, int j) {
    const ContactJacobian& Ji = i == k.a ? k.ja : k.jb;
    const ContactJacobian& Jk = j == k.a ? k.ja : k.jb;
    const Eigen::Matrix<double, 6, 6> block = Ji.transpose() * B * Jk;
    for (int rr = 0; rr < 6; ++rr)
      for (int ss = 0; ss < 6; ++ss, ++at)
        if (slots_[c][at] >= 0) H_.valuePtr()[slots_[c][at]] += block(rr, ss);
  });
}

}  // namespace icedem
