// The folded mass matrix of a lattice (dem/contact/lattice_mass.hpp): its dense and sparse
// forms are the same operator. The matrix is a chain of elements joined by stiff springs,
// as a lattice's Mt = M + Jj^T C^-1 Jj is: a 0.15 m element's mass and inertia on the
// diagonal, joint blocks a million times stiffer, harsher than a lattice's (its rows' C is
// about 1e-3 of their inverse mass), so the tolerances below are the round-off this
// condition number allows.
#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>

#include "dem/contact/lattice_mass.hpp"

namespace icedem {
namespace {

// Mt of `n` elements in a row, each joined to the next: blocks of k (rows of a random
// 6 x 6 J and its negative on the neighbour, as a fixed joint's are)
Eigen::MatrixXd chain(int n, LatticeMass& mass, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  for (int k = 0; k < n; ++k) {
    Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
    M.diagonal() << 0.6, 0.6, 0.6, 1.2e-3, 1.2e-3, 2.3e-3;  // kg, kg m^2
    mass.add(k, k, M);
    dense.block<6, 6>(6 * k, 6 * k) += M;
  }
  for (int k = 0; k + 1 < n; ++k) {
    Eigen::Matrix<double, 6, 6> J;
    for (int i = 0; i < 36; ++i) J(i) = u(random);
    const Eigen::Matrix<double, 6, 6> K = 1e6 * J.transpose() * J;  // J^T C^-1 J
    const int ends[2] = {k, k + 1};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const Eigen::Matrix<double, 6, 6> block = a == b ? K : Eigen::Matrix<double, 6, 6>(-K);
        mass.add(ends[a], ends[b], block);
        dense.block<6, 6>(6 * ends[a], 6 * ends[b]) += block;
      }
  }
  return dense;
}

// both forms against a dense inverse computed here (LDLT, another factorisation): solves
// and diagonal blocks to 1e-5 of their size. The chain's condition number is about 1e10, so
// round-off alone allows 1e-16 x 1e10 = 1e-6 (measured: 1e-7); a wrong or missing block
// is an error of order 1.
void expect_the_inverse(int n) {
  LatticeMass mass(n);
  const Eigen::MatrixXd Mt = chain(n, mass, 7u + n);
  ASSERT_TRUE(mass.factorise());
  const Eigen::MatrixXd inverse = Mt.ldlt().solve(Eigen::MatrixXd::Identity(6 * n, 6 * n));
  std::mt19937 random(3);
  std::normal_distribution<double> g;
  Eigen::VectorXd impulse(6 * n), velocity(6 * n);
  for (int i = 0; i < 6 * n; ++i) impulse(i) = g(random);
  mass.solve(impulse, velocity);
  const Eigen::VectorXd expected = inverse * impulse;
  EXPECT_LT((velocity - expected).norm(), 1e-5 * expected.norm());
  for (int k : {0, n / 2, n - 1}) {
    const Eigen::Matrix<double, 6, 6> block = inverse.block<6, 6>(6 * k, 6 * k);
    EXPECT_LT((mass.inverse_block(k) - block).norm(), 1e-5 * block.norm()) << "element " << k;
  }
  // the block on a few elements, in the order asked (not the elements'), off-diagonal
  // blocks included: what an iteration applies in place of a solve over the lattice
  const std::vector<int> touched{n - 1, 0, n / 2};
  const Eigen::MatrixXd w = mass.restricted_inverse(touched);
  ASSERT_EQ(w.rows(), 18);
  ASSERT_EQ(w.cols(), 18);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Eigen::Matrix<double, 6, 6> block = inverse.block<6, 6>(6 * touched[i], 6 * touched[j]);
      const double size = inverse.block<6, 6>(6 * touched[i], 6 * touched[i]).norm();
      EXPECT_LT((w.block<6, 6>(6 * i, 6 * j) - block).norm(), 1e-5 * size) << "elements " << touched[i] << ", " << touched[j];
    }
}

TEST(LatticeMass, SmallLatticesAreDense) {
  EXPECT_FALSE(LatticeMass(LatticeMass::kDenseElements).sparse());
  EXPECT_TRUE(LatticeMass(LatticeMass::kDenseElements + 1).sparse());
}

TEST(LatticeMass, DenseFormIsTheInverse) { expect_the_inverse(LatticeMass::kDenseElements); }

TEST(LatticeMass, SparseFormIsTheInverse) { expect_the_inverse(3 * LatticeMass::kDenseElements); }

// The analysis kept between steps (LatticePatterns) gives the factor a fresh analysis
// gives, bit for bit (a run resumed from a checkpoint starts without it and must repeat the
// run), for a lattice whose values changed and for one whose pattern changed (a chain of
// another length under the same key: a joint broke, another problem came), which must be
// analysed again, not factorised on the old pattern.
TEST(LatticeMass, AKeptPatternGivesTheFreshFactor) {
  const int n = 3 * LatticeMass::kDenseElements;
  LatticePatterns patterns;
  std::mt19937 random(5);
  std::normal_distribution<double> g;
  Eigen::VectorXd impulse(6 * n);
  for (int i = 0; i < 6 * n; ++i) impulse(i) = g(random);
  for (auto [elements, seed] : {std::pair{n, 1u}, std::pair{n, 2u}, std::pair{n - 1, 3u}, std::pair{n, 4u}}) {
    LatticeMass kept(elements), fresh(elements);
    chain(elements, kept, seed);
    chain(elements, fresh, seed);
    ASSERT_TRUE(kept.factorise(&patterns, 7));
    ASSERT_TRUE(fresh.factorise());
    const Eigen::VectorXd in = impulse.head(6 * elements);
    Eigen::VectorXd a(6 * elements), b(6 * elements);
    kept.solve(in, a);
    fresh.solve(in, b);
    EXPECT_EQ(a, b) << elements << " elements, seed " << seed;
    EXPECT_EQ(kept.restricted_inverse({0, elements - 1}), fresh.restricted_inverse({0, elements - 1}));
  }
  EXPECT_EQ(patterns.size(), 1u);
  // an analysis no lattice uses is dropped after kIdleSolves to 2 kIdleSolves solves, one in use
  // is not
  for (long long s = 0; s < 2 * LatticePatterns::kIdleSolves; ++s) {
    patterns.next_solve();
    if (s % 100 == 0) {
      LatticeMass again(4 * LatticeMass::kDenseElements);
      chain(4 * LatticeMass::kDenseElements, again, 9u);
      ASSERT_TRUE(again.factorise(&patterns, 8));
    }
  }
  EXPECT_EQ(patterns.size(), 1u) << "the idle analysis (key 7) is dropped, the used one (key 8) kept";
}

// a lattice whose matrix is not positive definite (an element without mass or joint, as a
// corrupt problem would give) is refused, and the method keeps its joint rows as unknowns
TEST(LatticeMass, RefusesAMatrixThatIsNotPositiveDefinite) {
  for (int n : {4, 40}) {
    LatticeMass mass(n);
    for (int k = 0; k + 1 < n; ++k) mass.add(k, k, Eigen::Matrix<double, 6, 6>::Identity());
    EXPECT_FALSE(mass.factorise()) << n << " elements";
  }
}

}  // namespace
}  // namespace icedem
