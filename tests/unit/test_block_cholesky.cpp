// The block sparse Cholesky factorisation (dem/contact/block_cholesky.hpp) against a dense
// factorisation of the same matrix. The matrices are grids of 6 x 6 blocks as a lattice's
// folded mass matrix is (an element's mass on the diagonal, a stiff joint coupling each pair of
// neighbours), with diagonals across some squares: a grid's elimination fills in, so the
// factor's pattern holds blocks that are in no joint, which a wrong pattern or a missed
// update would leave out.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>

#include "dem/contact/block_cholesky.hpp"

namespace icedem {
namespace {

using Block = BlockCholesky::Block;

struct Grid {
  int n = 0;
  std::vector<Block> own;
  std::vector<std::pair<int, int>> pairs;  // (i, j), i > j
  std::vector<Block> below;
  Eigen::MatrixXd dense;
};

// side x side elements; each joint a random J's K = k J^T J, as a fixed joint's rows fold
// in (J^T C^-1 J), k a thousand to a million times the element's mass
Grid grid(int side, unsigned seed, double k = 1e6) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Grid g;
  g.n = side * side;
  g.own.assign(g.n, Block::Zero());
  for (Block& m : g.own) m.diagonal() << 0.6, 0.6, 0.6, 1.2e-3, 1.2e-3, 2.3e-3;  // kg, kg m^2
  auto join = [&](int a, int b) {
    Block J;
    for (int i = 0; i < 36; ++i) J(i) = u(random);
    const Block K = k * J.transpose() * J;
    g.own[a] += K;
    g.own[b] += K;
    g.pairs.emplace_back(std::max(a, b), std::min(a, b));
    g.below.push_back(-K);
  };
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const int e = i * side + j;
      if (j + 1 < side) join(e, e + 1);
      if (i + 1 < side) join(e, e + side);
      if (i + 1 < side && j + 1 < side && (i + j) % 3 == 0) join(e + side + 1, e);  // given as (i, j), i > j
    }
  g.dense = Eigen::MatrixXd::Zero(6 * g.n, 6 * g.n);
  for (int e = 0; e < g.n; ++e) g.dense.block<6, 6>(6 * e, 6 * e) = g.own[e];
  for (std::size_t e = 0; e < g.pairs.size(); ++e) {
    const auto [i, j] = g.pairs[e];
    g.dense.block<6, 6>(6 * i, 6 * j) += g.below[e];
    g.dense.block<6, 6>(6 * j, 6 * i) += g.below[e].transpose();
  }
  return g;
}

// A solve and the inverse's block on a few elements agree with a dense LDLT to 1e-8 of their
// size. With joints of k = 1e3 the grid's condition number is about 1e7 (k |J|^2 ~ 1e4 over
// the inertia's 1e-3), so round-off alone allows about 1e-16 x 1e7 in either factorisation; a
// wrong or missing block is an error of order 1.
TEST(BlockCholesky, SolvesAsADenseFactorisationDoes) {
  for (int side : {1, 2, 5, 9}) {
    const Grid g = grid(side, 11u + side, 1e3);
    BlockCholesky llt;
    llt.analyse(g.n, g.pairs);
    ASSERT_TRUE(llt.factorise(g.own, g.below)) << side;
    std::mt19937 random(3);
    std::normal_distribution<double> normal;
    Eigen::VectorXd x(6 * g.n);
    for (int i = 0; i < x.size(); ++i) x(i) = normal(random);
    const Eigen::VectorXd expected = g.dense.ldlt().solve(x);
    llt.solve(x);
    EXPECT_LT((x - expected).norm(), 1e-8 * expected.norm()) << side << " x " << side;
    // A^-1's block on two elements, from a forward pass over their reach
    const std::vector<int> touched{g.n - 1, g.n / 2};
    const Eigen::MatrixXd w = llt.inverse_on(touched);
    const Eigen::MatrixXd inverse = g.dense.ldlt().solve(Eigen::MatrixXd::Identity(6 * g.n, 6 * g.n));
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const Eigen::MatrixXd block = inverse.block(6 * touched[a], 6 * touched[b], 6, 6);
        const double size = inverse.block(6 * touched[a], 6 * touched[a], 6, 6).norm();
        EXPECT_LT((w.block(6 * a, 6 * b, 6, 6) - block).norm(), 1e-8 * size)
            << side << " x " << side << ", blocks " << a << ", " << b;
      }
  }
}

// With a lattice's stiffness (k = 1e6, condition number about 1e10) the two factorisations'
// answers differ by 1e-5 of their size, as round-off allows; what a stable factorisation
// guarantees is the backward error: A x reproduces the impulse to round-off of A's size
// times x's, 1e-16 with a margin of a hundred.
TEST(BlockCholesky, StiffLatticesAreSolvedToRoundOff) {
  const Grid g = grid(9, 4u, 1e6);
  BlockCholesky llt;
  llt.analyse(g.n, g.pairs);
  ASSERT_TRUE(llt.factorise(g.own, g.below));
  std::mt19937 random(8);
  std::normal_distribution<double> normal;
  Eigen::VectorXd b(6 * g.n);
  for (int i = 0; i < b.size(); ++i) b(i) = normal(random);
  Eigen::VectorXd x = b;
  llt.solve(x);
  const double scale = g.dense.norm() * x.norm();
  EXPECT_LT((g.dense * x - b).norm(), 1e-14 * scale);
}

// A solve over a reach (the touched blocks and their ancestors in the elimination tree) gives
// the full solve's answer on the touched blocks, to round-off, for a right-hand side on them
// alone, and leaves the answer elsewhere as it was; and for blocks along one edge of the grid
// (contacts at a sheet's edge) the reach is a part of the factor, not all of it.
TEST(BlockCholesky, ASolveOverTheReachIsTheSolveWhereItIsRead) {
  const Grid g = grid(9, 6u);
  BlockCholesky llt;
  llt.analyse(g.n, g.pairs);
  ASSERT_TRUE(llt.factorise(g.own, g.below));
  const std::vector<int> touched{0, 1, 2, 9, 18};  // a corner of the grid
  const std::vector<int> reach = llt.reach(touched);
  EXPECT_LT(reach.size(), static_cast<std::size_t>(g.n) * 3 / 4) << reach.size() << " of " << g.n << " columns";
  EXPECT_LT(llt.nonzeros(reach), llt.nonzeros());
  Eigen::VectorXd b = Eigen::VectorXd::Zero(6 * g.n);
  std::mt19937 random(2);
  std::normal_distribution<double> normal;
  for (int t : touched)
    for (int i = 0; i < 6; ++i) b(6 * t + i) = normal(random);
  Eigen::VectorXd full = b;
  llt.solve(full);
  Eigen::VectorXd x = Eigen::VectorXd::Constant(6 * g.n, 7.0);
  llt.solve_on(reach, b, x);
  for (int t : touched)
    EXPECT_LT((x.segment<6>(6 * t) - full.segment<6>(6 * t)).norm(), 1e-12 * full.norm()) << "block " << t;
  int untouched = 0;
  for (int k = 0; k < g.n; ++k) untouched += x.segment<6>(6 * k) == Eigen::Matrix<double, 6, 1>::Constant(7.0);
  EXPECT_EQ(untouched, g.n - static_cast<int>(reach.size()));
}

// One analysis serves any values on its pattern: the second factorisation is the one a fresh
// analysis gives, bit for bit (a run that keeps its analyses must repeat one that does not).
TEST(BlockCholesky, OneAnalysisServesNewValues) {
  const Grid first = grid(6, 1u), second = grid(6, 2u, 1e3);
  BlockCholesky kept, fresh;
  kept.analyse(first.n, first.pairs);
  ASSERT_TRUE(kept.factorise(first.own, first.below));
  ASSERT_TRUE(kept.factorise(second.own, second.below));
  fresh.analyse(second.n, second.pairs);
  ASSERT_TRUE(fresh.factorise(second.own, second.below));
  Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(6 * second.n, -1.0, 1.0), b = a;
  kept.solve(a);
  fresh.solve(b);
  EXPECT_EQ(a, b);
}

// A matrix that is not positive definite (an element without mass or joint) is refused.
TEST(BlockCholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
  Grid g = grid(4, 5u);
  g.own[7].setZero();
  g.own[7].diagonal() << 1, 1, 1, 1, 1, -1;
  BlockCholesky llt;
  llt.analyse(g.n, g.pairs);
  EXPECT_FALSE(llt.factorise(g.own, g.below));
}

}  // namespace
}  // namespace icedem
