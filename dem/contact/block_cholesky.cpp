#include "dem/contact/block_cholesky.hpp"

#include <algorithm>
#include <numeric>

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

namespace icedem {

void BlockCholesky::analyse(int n, const std::vector<std::pair<int, int>>& below) {
  n_ = n;
  // a fill-reducing order of the blocks: AMD on the graph of the blocks
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(n + 2 * below.size());
  for (int k = 0; k < n; ++k) pattern.emplace_back(k, k, 1.0);
  for (const auto& [i, j] : below) pattern.emplace_back(i, j, 1.0), pattern.emplace_back(j, i, 1.0);
  Eigen::SparseMatrix<double> graph(n, n);
  graph.setFromTriplets(pattern.begin(), pattern.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
  Eigen::AMDOrdering<int>()(graph, inverse);
  position_.assign(n, 0);
  if (inverse.size() == n) {
    const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order = inverse.inverse();
    for (int k = 0; k < n; ++k) position_[k] = order.indices()[k];
  } else {
    for (int k = 0; k < n; ++k) position_[k] = k;
  }
  order_.assign(n, 0);
  for (int k = 0; k < n; ++k) order_[position_[k]] = k;
  columns_.resize(n);
  std::iota(columns_.begin(), columns_.end(), 0);

  // A's blocks below the diagonal in the new order, by columns
  std::vector<std::vector<int>> rows_of_a(n);
  for (const auto& [i, j] : below) {
    const int a = position_[i], b = position_[j];
    rows_of_a[std::min(a, b)].push_back(std::max(a, b));
  }
  // L's pattern, column by column: A's rows in the column and the rows of its children in the
  // elimination tree (the columns whose first row below the diagonal it is), less itself
  std::vector<std::vector<int>> children(n);
  std::vector<int> mark(n, -1), rows;
  start_.assign(n + 1, 0);
  row_.clear();
  for (int j = 0; j < n; ++j) {
    rows.clear();
    mark[j] = j;
    auto take = [&](int r) {
      if (mark[r] != j) mark[r] = j, rows.push_back(r);
    };
    for (int r : rows_of_a[j]) take(r);
    for (int c : children[j])
      for (int s = start_[c]; s < start_[c + 1]; ++s) take(row_[s]);
    std::sort(rows.begin(), rows.end());
    row_.insert(row_.end(), rows.begin(), rows.end());
    start_[j + 1] = static_cast<int>(row_.size());
    if (!rows.empty()) children[rows.front()].push_back(j);
  }
  l_.assign(row_.size(), Block::Zero());
  diagonal_.assign(n, Block::Zero());

  // where each of A's blocks below the diagonal lands in L
  slot_.resize(below.size());
  transpose_.resize(below.size());
  for (std::size_t e = 0; e < below.size(); ++e) {
    const int a = position_[below[e].first], b = position_[below[e].second];
    const int column = std::min(a, b), row = std::max(a, b);
    slot_[e] = static_cast<int>(std::lower_bound(row_.begin() + start_[column], row_.begin() + start_[column + 1], row) -
                                row_.begin());
    transpose_[e] = a < b;
  }
}

bool BlockCholesky::factorise(const std::vector<Block>& own, const std::vector<Block>& below) {
  for (int k = 0; k < n_; ++k) diagonal_[position_[k]] = own[k];
  std::fill(l_.begin(), l_.end(), Block::Zero());
  for (std::size_t e = 0; e < below.size(); ++e) {
    if (transpose_[e])
      l_[slot_[e]] += below[e].transpose();
    else
      l_[slot_[e]] += below[e];
  }
  // Left-looking, column by column: column j takes the updates of every finished column c
  // with a block in row j (L_jc), found through linked lists of the columns waiting for each
  // row (each column waits on its next row below the one just used)
  std::vector<int> head(n_, -1), link(n_, -1), next(n_, 0), where(n_, -1);
  for (int j = 0; j < n_; ++j) {
    for (int s = start_[j]; s < start_[j + 1]; ++s) where[row_[s]] = s;
    Block d = diagonal_[j];
    for (int c = head[j]; c != -1;) {
      const int after = link[c], k = next[c];
      const Block ljc = l_[k];
      d.noalias() -= ljc * ljc.transpose();
      // column c's rows below j are in column j's pattern (L's pattern is closed up its tree)
      for (int s = k + 1; s < start_[c + 1]; ++s) l_[where[row_[s]]].noalias() -= l_[s] * ljc.transpose();
      if (k + 1 < start_[c + 1]) {
        next[c] = k + 1;
        link[c] = head[row_[k + 1]];
        head[row_[k + 1]] = c;
      }
      c = after;
    }
    const Eigen::LLT<Block> llt(d);
    if (llt.info() != Eigen::Success) return false;
    diagonal_[j] = llt.matrixL();
    const auto ljj = diagonal_[j].triangularView<Eigen::Lower>();
    for (int s = start_[j]; s < start_[j + 1]; ++s) {
      // L_ij = C_ij L_jj^-T
      Block t = l_[s].transpose();
      ljj.solveInPlace(t);
      l_[s] = t.transpose();
    }
    if (start_[j] < start_[j + 1]) {
      next[j] = start_[j];
      link[j] = head[row_[start_[j]]];
      head[row_[start_[j]]] = j;
    }
  }
  return true;
}

void BlockCholesky::solve(Eigen::VectorXd& x) const {
  // every column is the reach of a right-hand side on every block (solve_on reads b whole
  // before it writes x, so the two may be one vector)
  solve_on(columns_, x, x);
}


std::vector<int> BlockCholesky::reach(const std::vector<int>& blocks) const {
  std::vector<char> in(n_, 0);
  std::vector<int> columns;
  for (int b : blocks)
    // up the elimination tree (a column's parent is its first row below the diagonal) until a
    // column already taken
    for (int j = position_[b]; j >= 0 && !in[j]; j = start_[j] < start_[j + 1] ? row_[start_[j]] : -1) {
      in[j] = 1;
      columns.push_back(j);
    }
  std::sort(columns.begin(), columns.end());
  return columns;
}

void BlockCholesky::solve_on(const std::vector<int>& reach, const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  // scratch that only grows: an iteration's solves, over lattices of any size, allocate nothing
  thread_local Eigen::VectorXd y;
  if (y.size() < 6 * n_) y.resize(6 * n_);
  for (int j : reach) y.segment<6>(6 * j) = b.segment<6>(6 * order_[j]);
  for (int j : reach) {
    auto yj = y.segment<6>(6 * j);
    diagonal_[j].triangularView<Eigen::Lower>().solveInPlace(yj);
    const Eigen::Matrix<double, 6, 1> v = yj;
    for (int s = start_[j]; s < start_[j + 1]; ++s) y.segment<6>(6 * row_[s]).noalias() -= l_[s] * v;
  }
  for (auto it = reach.rbegin(); it != reach.rend(); ++it) {
    const int j = *it;
    Eigen::Matrix<double, 6, 1> v = y.segment<6>(6 * j);
    for (int s = start_[j]; s < start_[j + 1]; ++s) v.noalias() -= l_[s].transpose() * y.segment<6>(6 * row_[s]);
    diagonal_[j].transpose().triangularView<Eigen::Upper>().solveInPlace(v);
    y.segment<6>(6 * j) = v;
  }
  for (int j : reach) x.segment<6>(6 * order_[j]) = y.segment<6>(6 * j);
}

Eigen::MatrixXd BlockCholesky::inverse_on(const std::vector<int>& blocks) const {
  const std::vector<int> columns = reach(blocks);
  std::vector<int> at(n_, -1);  // a reach column's place in Y
  for (std::size_t i = 0; i < columns.size(); ++i) at[columns[i]] = static_cast<int>(i);
  const int k = static_cast<int>(blocks.size());
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(columns.size()), 6 * k);
  for (int e = 0; e < k; ++e) y.block<6, 6>(6 * at[position_[blocks[e]]], 6 * e).setIdentity();
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const int j = columns[i];
    auto yj = y.middleRows<6>(6 * i);
    diagonal_[j].triangularView<Eigen::Lower>().solveInPlace(yj);
    for (int s = start_[j]; s < start_[j + 1]; ++s) y.middleRows<6>(6 * at[row_[s]]).noalias() -= l_[s] * yj;
  }
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(6 * k, 6 * k);
  w.selfadjointView<Eigen::Lower>().rankUpdate(y.transpose());
  return w.selfadjointView<Eigen::Lower>();
}

long long BlockCholesky::nonzeros(const std::vector<int>& reach) const {
  long long blocks = 0;
  for (int j : reach) blocks += start_[j + 1] - start_[j];
  return 21LL * static_cast<long long>(reach.size()) + 36LL * blocks;
}

}  // namespace icedem
