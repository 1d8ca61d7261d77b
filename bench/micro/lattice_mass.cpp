// A lattice's folded mass matrix (dem/contact/lattice_mass.hpp), dense against sparse, at
// the sizes runs meet: what a step of the contact solve pays for it. Per island and step
// the method factorises Mt once and then applies Mt^-1 once per gradient step (tens to
// hundreds a step): through a solve over the lattice, or through W, Mt^-1's block on the
// elements contacts touch (computed once, then a small dense product a step). The lattice is a grid of square
// elements of 0.15 m joined to their four neighbours, each joint a stiff 6 x 6 block as a
// fixed joint's rows fold in (J^T C^-1 J). Its pattern is what the cost follows.
// BM_Sparse* set the sparse factorisation by blocks (dem/contact/block_cholesky.hpp) beside
// the library's, Eigen's SimplicialLLT, on the same matrices: why the project has its own.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/SparseCholesky>

#include "dem/contact/block_cholesky.hpp"
#include "dem/contact/lattice_mass.hpp"

using namespace icedem;

namespace {

// Mt of a side x side grid as blocks: element mass and inertia of a 0.15 m, 0.033 m thick
// element on the diagonal, joint blocks from a fixed joint's six rows between neighbours
// (lever arms of half an element), C^-1 = 1e5 (about a lattice's: C ~ 1e-3 of its rows'
// inverse mass); each joined pair's block below the diagonal
struct GridBlocks {
  std::vector<BlockCholesky::Block> own, below;
  std::vector<std::pair<int, int>> pairs;  // (i, j), i > j
};

GridBlocks grid_blocks(int side) {
  GridBlocks g;
  const double m = 0.15 * 0.15 * 0.033 * 900.0;
  BlockCholesky::Block M = BlockCholesky::Block::Zero();
  M.diagonal() << m, m, m, m * 0.15 * 0.15 / 12, m * 0.15 * 0.15 / 12, m * 0.15 * 0.15 / 6;
  g.own.assign(side * side, M);
  auto join = [&](int a, int b, const Eigen::Vector3d& offset) {  // b > a
    // rows: relative velocity at the joint point (3), relative angular velocity (3)
    BlockCholesky::Block ja = BlockCholesky::Block::Identity(), jb = -ja;
    Eigen::Matrix3d skew;
    skew << 0, -offset.z(), offset.y(), offset.z(), 0, -offset.x(), -offset.y(), offset.x(), 0;
    ja.topRightCorner<3, 3>() = -skew;  // v + w x r at the point, r = +offset from a
    jb.topRightCorner<3, 3>() = -skew;  // from b the point is at -offset: -(v_b + w_b x (-r))
    const double c = 1e5;
    g.own[a] += c * ja.transpose() * ja;
    g.own[b] += c * jb.transpose() * jb;
    g.pairs.emplace_back(b, a);
    g.below.push_back(c * jb.transpose() * ja);
  };
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const int k = i * side + j;
      if (j + 1 < side) join(k, k + 1, {0.075, 0, 0});
      if (i + 1 < side) join(k, k + side, {0, 0.075, 0});
    }
  return g;
}

// the same into a LatticeMass
void fill(LatticeMass& mass, int side) {
  const GridBlocks g = grid_blocks(side);
  for (int k = 0; k < side * side; ++k) mass.add(k, k, g.own[k]);
  for (std::size_t e = 0; e < g.pairs.size(); ++e) mass.add(g.pairs[e].first, g.pairs[e].second, g.below[e]);
}

// its lower triangle as an Eigen sparse matrix, for Eigen's simplicial Cholesky
Eigen::SparseMatrix<double> lower_triangle(const GridBlocks& g) {
  std::vector<Eigen::Triplet<double>> t;
  const int n = static_cast<int>(g.own.size());
  for (int e = 0; e < n; ++e)
    for (int c = 0; c < 6; ++c)
      for (int r = c; r < 6; ++r) t.emplace_back(6 * e + r, 6 * e + c, g.own[e](r, c));
  for (std::size_t e = 0; e < g.pairs.size(); ++e)
    for (int c = 0; c < 6; ++c)
      for (int r = 0; r < 6; ++r) t.emplace_back(6 * g.pairs[e].first + r, 6 * g.pairs[e].second + c, g.below[e](r, c));
  Eigen::SparseMatrix<double> m(6 * n, 6 * n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

using Simplicial = Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int>>;

// The sparse factorisation, the library's against the blocks' (dem/contact/block_cholesky.hpp),
// on one grid, the analysis done once (as a run keeps it): range(1) 0 Eigen's SimplicialLLT,
// 1 BlockCholesky
void BM_SparseFactorise(benchmark::State& s) {
  const int side = static_cast<int>(s.range(0));
  const GridBlocks g = grid_blocks(side);
  if (s.range(1) == 0) {
    const Eigen::SparseMatrix<double> m = lower_triangle(g);
    Simplicial llt;
    llt.analyzePattern(m);
    for (auto _ : s) {
      llt.factorize(m);
      benchmark::DoNotOptimize(llt.info());
    }
  } else {
    BlockCholesky llt;
    llt.analyse(side * side, g.pairs);
    for (auto _ : s) benchmark::DoNotOptimize(llt.factorise(g.own, g.below));
  }
  s.SetLabel(std::to_string(side * side) + (s.range(1) ? " elements, BlockCholesky" : " elements, Eigen SimplicialLLT"));
}

// one solve with each factor (a gradient step's Mt^-1 J^T x on a lattice iterated through a
// solve)
void BM_SparseSolve(benchmark::State& s) {
  const int side = static_cast<int>(s.range(0));
  const GridBlocks g = grid_blocks(side);
  std::mt19937 random(1);
  std::normal_distribution<double> normal;
  Eigen::VectorXd impulse(6 * side * side), velocity(6 * side * side);
  for (int i = 0; i < impulse.size(); ++i) impulse(i) = normal(random);
  if (s.range(1) == 0) {
    Simplicial llt(lower_triangle(g));
    for (auto _ : s) {
      velocity = llt.solve(impulse);
      benchmark::DoNotOptimize(velocity.data());
    }
  } else {
    BlockCholesky llt;
    llt.analyse(side * side, g.pairs);
    llt.factorise(g.own, g.below);
    for (auto _ : s) {
      velocity = impulse;
      llt.solve(velocity);
      benchmark::DoNotOptimize(velocity.data());
    }
  }
  s.SetLabel(std::to_string(side * side) + (s.range(1) ? " elements, BlockCholesky" : " elements, Eigen SimplicialLLT"));
}

// a 0.6 m floe of 0.15 m squares (16), a hexagon floe's 25-49, the 2.7 m plate's 324, a level
// sheet's free part (about 600: side 24)
void sparse_sizes(benchmark::internal::Benchmark* b) {
  for (int side : {4, 5, 7, 10, 18, 24})
    for (int form : {0, 1}) b->Args({side, form});
}

LatticeMass::Form form_of(int64_t f) { return f ? LatticeMass::Form::kSparse : LatticeMass::Form::kDense; }

// the set-up of a step: Mt assembled and factorised
void BM_LatticeMassFactorise(benchmark::State& s) {
  const int side = static_cast<int>(s.range(0));
  for (auto _ : s) {
    LatticeMass mass(side * side, form_of(s.range(1)));
    fill(mass, side);
    benchmark::DoNotOptimize(mass.factorise());
  }
  s.SetLabel(std::to_string(side * side) + (s.range(1) ? " elements, sparse" : " elements, dense"));
}

// the same, sparse, with the pattern's analysis kept from the step before (a run's
// lattices: their pattern holds while their joints do)
void BM_LatticeMassFactoriseKept(benchmark::State& s) {
  const int side = static_cast<int>(s.range(0));
  LatticePatterns patterns;
  {
    LatticeMass first(side * side, LatticeMass::Form::kSparse);
    fill(first, side);
    first.factorise(&patterns, 0);
  }
  long long nonzeros = 0;
  for (auto _ : s) {
    LatticeMass mass(side * side, LatticeMass::Form::kSparse);
    fill(mass, side);
    benchmark::DoNotOptimize(mass.factorise(&patterns, 0));
    nonzeros = mass.factor_nonzeros();
  }
  s.SetLabel(std::to_string(side * side) + " elements, sparse, pattern kept, " + std::to_string(nonzeros) +
             " nonzeros in L");
}

// one gradient step's Mt^-1 J^T x
void BM_LatticeMassSolve(benchmark::State& s) {
  const int side = static_cast<int>(s.range(0));
  LatticeMass mass(side * side, form_of(s.range(1)));
  fill(mass, side);
  mass.factorise();
  std::mt19937 random(1);
  std::normal_distribution<double> g;
  Eigen::VectorXd impulse(6 * side * side), velocity(6 * side * side);
  for (int i = 0; i < impulse.size(); ++i) impulse(i) = g(random);
  for (auto _ : s) {
    mass.solve(impulse, velocity);
    benchmark::DoNotOptimize(velocity.data());
  }
  s.SetLabel(std::to_string(side * side) + (s.range(1) ? " elements, sparse" : " elements, dense"));
}

// the touched elements of a lattice: k spread over it (every n/k-th)
std::vector<int> touched(int n, int k) {
  std::vector<int> t;
  for (int e = 0; e < k; ++e) t.push_back(e * n / k);
  return t;
}

// W of k touched elements, once per island and step (after the factorisation)
void BM_LatticeMassRestrictedSetup(benchmark::State& s) {
  const int side = static_cast<int>(s.range(0)), k = static_cast<int>(s.range(2));
  LatticeMass mass(side * side, form_of(s.range(1)));
  fill(mass, side);
  mass.factorise();
  const std::vector<int> t = touched(side * side, k);
  for (auto _ : s) benchmark::DoNotOptimize(mass.restricted_inverse(t).data());
  s.SetLabel(std::to_string(side * side) + (s.range(1) ? " elements, sparse, " : " elements, dense, ") +
             std::to_string(k) + " touched");
}

// one gradient step's W J^T x on the touched elements
void BM_LatticeMassRestrictedApply(benchmark::State& s) {
  const int side = static_cast<int>(s.range(0)), k = static_cast<int>(s.range(2));
  LatticeMass mass(side * side, form_of(s.range(1)));
  fill(mass, side);
  mass.factorise();
  const Eigen::MatrixXd w = mass.restricted_inverse(touched(side * side, k));
  std::mt19937 random(1);
  std::normal_distribution<double> g;
  Eigen::VectorXd impulse(6 * k), velocity(6 * k);
  for (int i = 0; i < impulse.size(); ++i) impulse(i) = g(random);
  for (auto _ : s) {
    velocity.noalias() = w * impulse;
    benchmark::DoNotOptimize(velocity.data());
  }
  s.SetLabel(std::to_string(side * side) + " elements, " + std::to_string(k) + " touched");
}

// the 0.15 m squares' floe (16 elements, dense) and a hexagon floe or plate (sparse), with
// 1 to 16 elements touched
void touched_sizes(benchmark::internal::Benchmark* b) {
  for (int side : {4, 6, 18})
    for (int k : {1, 2, 4, 8, 16})
      if (k <= side * side) b->Args({side, side > 4 ? 1 : 0, k});
}

// sides 3, 4 (the 0.15 m squares' 16), 5 (25, just above the dense limit), 6, 7, 10, 18 (the
// 2.7 m validation plate's 324; dense only up to 10: its inverse alone is 0.9 GB a second)
void sizes(benchmark::internal::Benchmark* b) {
  for (int side : {1, 2, 3, 4, 5, 6, 7, 10, 18})
    for (int sparse : {0, 1})
      if (sparse || side <= 10) b->Args({side, sparse});
}

}  // namespace

BENCHMARK(BM_SparseFactorise)->Apply(sparse_sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SparseSolve)->Apply(sparse_sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassFactorise)->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassFactoriseKept)->DenseRange(1, 7)->Arg(10)->Arg(18)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassSolve)->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassRestrictedSetup)->Apply(touched_sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassRestrictedApply)->Apply(touched_sizes)->Unit(benchmark::kMicrosecond);
