// A lattice's folded mass matrix (dem/contact/lattice_mass.hpp), dense against sparse, at
// the sizes runs meet: what a step of the contact solve pays for it. Per island and step
// the method factorises Mt once and then applies Mt^-1 once per gradient step (tens to
// hundreds a step): through a solve over the lattice, or through W, Mt^-1's block on the
// elements contacts touch (computed once, then a small dense product a step). The lattice is a grid of square
// elements of 0.15 m joined to their four neighbours, each joint a stiff 6 x 6 block as a
// fixed joint's rows fold in (J^T C^-1 J). Its pattern is what the cost follows.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "dem/contact/lattice_mass.hpp"

using namespace icedem;

namespace {

// Mt of a side x side grid: element mass and inertia of a 0.15 m, 0.033 m thick element,
// joint blocks from a fixed joint's six rows between neighbours (lever arms of half an
// element), C^-1 = 1e5 (about a lattice's: C ~ 1e-3 of its rows' inverse mass)
void fill(LatticeMass& mass, int side) {
  const double m = 0.15 * 0.15 * 0.033 * 900.0;
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  M.diagonal() << m, m, m, m * 0.15 * 0.15 / 12, m * 0.15 * 0.15 / 12, m * 0.15 * 0.15 / 6;
  for (int k = 0; k < side * side; ++k) mass.add(k, k, M);
  auto join = [&](int a, int b, const Eigen::Vector3d& offset) {
    // rows: relative velocity at the joint point (3), relative angular velocity (3)
    Eigen::Matrix<double, 6, 6> ja = Eigen::Matrix<double, 6, 6>::Identity(), jb = -ja;
    Eigen::Matrix3d skew;
    skew << 0, -offset.z(), offset.y(), offset.z(), 0, -offset.x(), -offset.y(), offset.x(), 0;
    ja.topRightCorner<3, 3>() = -skew;  // v + w x r at the point, r = +offset from a
    jb.topRightCorner<3, 3>() = -skew;  // from b the point is at -offset: -(v_b + w_b x (-r))
    const double c = 1e5;
    mass.add(a, a, c * ja.transpose() * ja);
    mass.add(b, b, c * jb.transpose() * jb);
    mass.add(a, b, c * ja.transpose() * jb);
    mass.add(b, a, c * jb.transpose() * ja);
  };
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const int k = i * side + j;
      if (j + 1 < side) join(k, k + 1, {0.075, 0, 0});
      if (i + 1 < side) join(k, k + side, {0, 0.075, 0});
    }
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

BENCHMARK(BM_LatticeMassFactorise)->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassFactoriseKept)->DenseRange(1, 7)->Arg(10)->Arg(18)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassSolve)->Apply(sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassRestrictedSetup)->Apply(touched_sizes)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LatticeMassRestrictedApply)->Apply(touched_sizes)->Unit(benchmark::kMicrosecond);
