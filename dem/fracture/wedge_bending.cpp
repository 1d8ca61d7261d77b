#include "dem/fracture/wedge_bending.hpp"

#include "dem/fracture/floating_plate.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <Eigen/Sparse>
#include <fmt/format.h>

namespace icedem {

namespace {

constexpr double kLength = 12.0;  // the beam's length in characteristic lengths: e^-8 of the deflection left

// Gauss-Legendre, 4 points on [0, 1]: exact for the width (linear) times two cubics' products (degree 7)
constexpr std::array<double, 4> kGaussS{0.0694318442029737, 0.3300094782075719, 0.6699905217924281,
                                        0.9305681557970263};
constexpr std::array<double, 4> kGaussW{0.1739274225687269, 0.3260725774312731, 0.3260725774312731,
                                        0.1739274225687269};

// cubic Hermite shape functions on an element of length L at s in [0, 1], and their second derivatives in x
std::array<double, 4> shape(double s, double L) {
  return {1 - 3 * s * s + 2 * s * s * s, L * (s - 2 * s * s + s * s * s), 3 * s * s - 2 * s * s * s,
          L * (-s * s + s * s * s)};
}
std::array<double, 4> curvature(double s, double L) {
  return {(-6 + 12 * s) / (L * L), (-4 + 6 * s) / L, (6 - 12 * s) / (L * L), (-2 + 6 * s) / L};
}

// (b u'')'' + b u = f on [0, kLength] in units of the characteristic length (D = rho_w g = 1), the end at
// 0 free, the far end clamped, on the nodes `x`; `point` a unit load at x = 0 besides f. The largest
// |u''| (each node's the mean of its two elements') and where it is.
WedgeBending solve(const std::vector<double>& x, const std::function<double(double)>& width,
                   const std::function<double(double)>& load, bool point) {
  const int nodes = static_cast<int>(x.size()), dofs = 2 * nodes;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs);
  for (int e = 0; e + 1 < nodes; ++e) {
    const double L = x[e + 1] - x[e];
    for (int g = 0; g < 4; ++g) {
      const double s = kGaussS[g], xi = x[e] + L * s, w = kGaussW[g] * L, b = width(xi);
      const auto n = shape(s, L), c = curvature(s, L);
      for (int i = 0; i < 4; ++i) {
        f[2 * e + i] += w * load(xi) * n[i];
        for (int j = 0; j < 4; ++j) entries.emplace_back(2 * e + i, 2 * e + j, w * b * (c[i] * c[j] + n[i] * n[j]));
      }
    }
  }
  if (point) f[0] += 1.0;
  // the far end clamped: its two unknowns are zero, so the problem is that of the others
  const int free = dofs - 2;
  std::vector<Eigen::Triplet<double>> kept;
  for (const auto& t : entries)
    if (t.row() < free && t.col() < free) kept.push_back(t);
  Eigen::SparseMatrix<double> k(free, free);
  k.setFromTriplets(kept.begin(), kept.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(k);
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("wedge_bending: the beam's stiffness is singular");
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs);
  u.head(free) = ldlt.solve(f.head(free));
  // u'' at each node: the mean of the ends of its elements (each linear along the element)
  std::vector<double> m(nodes, 0.0), count(nodes, 0.0);
  for (int e = 0; e + 1 < nodes; ++e) {
    const double L = x[e + 1] - x[e];
    for (int end = 0; end < 2; ++end) {
      const auto c = curvature(end, L);
      double v = 0;
      for (int i = 0; i < 4; ++i) v += c[i] * u[2 * e + i];
      m[e + end] += v;
      count[e + end] += 1;
    }
  }
  int at = 0;
  for (int i = 0; i < nodes; ++i) {
    m[i] = std::abs(m[i] / count[i]);
    if (m[i] > m[at]) at = i;
  }
  double where = x[at];
  if (at > 0 && at + 1 < nodes) {  // the parabola through the largest and its neighbours: its vertex
    const double a = m[at - 1], b = m[at], c = m[at + 1], h0 = x[at] - x[at - 1], h1 = x[at + 1] - x[at];
    const double d1 = (c - b) / h1, d0 = (b - a) / h0, curv = (d1 - d0) / ((h0 + h1) / 2);
    if (curv < 0) where = x[at] - ((d0 * h1 + d1 * h0) / (h0 + h1)) / curv;
  }
  return WedgeBending{m[at], where};
}

// nodes from 0 to kLength, `per` elements a unit length, one of them at `mark` (0: none)
std::vector<double> mesh(double mark, int per) {
  std::vector<double> x{0.0};
  auto fill = [&](double to) {
    const int n = std::max(1, static_cast<int>(std::ceil((to - x.back()) * per)));
    const double from = x.back();
    for (int i = 1; i <= n; ++i) x.push_back(from + (to - from) * i / n);
  };
  if (mark > 0) fill(mark);
  fill(kLength);
  return x;
}

}  // namespace

WedgeBending wedge_bending(double patch, int elements) {
  if (!(patch > 0) || patch > 6)
    throw std::invalid_argument(fmt::format("a wedge's load patch must be in (0, 6] characteristic lengths, not {}", patch));
  // Written for w = P u / (rho_w g tan(theta/2) l^2) and x in units of l, the wedge's equation is
  // (x u'')'' + x u = x / a^2 over the patch (the load P in uniform pressure over its area a^2 tan(theta/2)),
  // the width's factor 2 tan(theta/2) divided out; the stress 6 D w'' / h^2 is then 6 P u'' / (h^2 tan(theta/2)),
  // so S = 2 |u''|
  const WedgeBending r = solve(mesh(patch, elements), [](double x) { return x; },
                               [patch](double x) { return x < patch ? x / (patch * patch) : 0.0; }, false);
  return WedgeBending{2 * r.stress_factor, r.crack_distance};
}

WedgeBending constant_width_bending(int elements) {
  const WedgeBending r = solve(mesh(0, elements), [](double) { return 1.0; }, [](double) { return 0.0; }, true);
  // beta = 1 / (sqrt(2) l): M beta / P = |u''| / sqrt(2), the distance times beta likewise
  return WedgeBending{r.stress_factor / std::sqrt(2.0), r.crack_distance / std::sqrt(2.0)};
}

double wedge_load(double opening_angle, const WedgeBending& w, double thickness, double bending_strength) {
  return bending_strength * thickness * thickness * std::tan(opening_angle / 2) / (3 * w.stress_factor);
}

WedgeBreak wedge_breaking_load(double opening_angle, double patch_length, double thickness, double elastic_modulus,
                               double poisson_ratio, double bending_strength, double water_density, double gravity) {
  if (!(opening_angle > 0) || !(opening_angle < M_PI))
    throw std::invalid_argument(fmt::format("a wedge's opening angle must be in (0, pi), not {}", opening_angle));
  const double l = characteristic_length(thickness, elastic_modulus, poisson_ratio, water_density, gravity);
  const WedgeBending w = wedge_bending(patch_length / l);
  return WedgeBreak{wedge_load(opening_angle, w, thickness, bending_strength), w.crack_distance * l};
}

}  // namespace icedem
