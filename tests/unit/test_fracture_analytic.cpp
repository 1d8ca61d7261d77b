// The edge load that breaks a floating floe (dem/fracture/fracture_analytic.hpp): its two limits in
// closed form, and the paper's 0.6 m floe against an independent solver.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dem/fracture/fracture_analytic.hpp"

using namespace icedem;

namespace {
constexpr double kRhoG = 1000.0 * 9.81;  // N/m^3

double largest(const std::vector<double>& m) { return *std::max_element(m.begin(), m.end()); }
int where(const std::vector<double>& m) { return static_cast<int>(std::max_element(m.begin(), m.end()) - m.begin()); }
}  // namespace

TEST(FloatingBeam, AShortStiffFloeTiltsAsARigidBody) {
  // L = 0.6 m with EI a million times the paper ice's: L / l_c = 0.05. The rigid floe's
  // moment is s (1 - s/L)^2 per unit load, largest 4 L / 27 at L / 3 (0.2 %: its bending).
  const double L = 0.6, n = 600;
  const std::vector<double> m = floating_beam_moment_per_load(L, 1.2e8, kRhoG * 0.6, 600);
  EXPECT_NEAR(largest(m), 4 * L / 27, 0.002 * 4 * L / 27);
  EXPECT_NEAR(where(m) * L / n, L / 3, 0.002);
  EXPECT_NEAR(m[150], 0.15 * std::pow(1 - 0.25, 2), 0.002 * 0.15 * 0.5625);
}

TEST(FloatingBeam, ALongFloeBendsAsASemiInfiniteBeam) {
  // The paper's ice (EI per metre 202 N m, l_c 0.38 m) over 8 m, 21 characteristic lengths:
  // M = e^(-beta s) sin(beta s) / beta per unit load, largest e^(-pi/4) sin(pi/4) / beta =
  // 0.3224 / beta at pi / (4 beta) (0.1 %: the far end's influence is e^(-beta L) ~ 1e-7).
  const double ei = 202.0, k = kRhoG, L = 8.0;
  const double beta = std::pow(k / (4 * ei), 0.25);
  const std::vector<double> m = floating_beam_moment_per_load(L, ei, k, 8000);
  EXPECT_NEAR(largest(m), std::exp(-M_PI / 4) * std::sin(M_PI / 4) / beta, 1e-3 * 0.3224 / beta);
  EXPECT_NEAR(where(m) * L / 8000, M_PI / (4 * beta), 0.002);
}

TEST(EdgeBreakingLoad, ThePapers06mFloeBreaksAt45N) {
  // docs/model/breakage.md: scripts/edge_load.py solves the same beam with scipy's boundary-
  // value solver (a different method): 45.0 N at the largest moment, s = 0.20 m (to 0.1 N;
  // 0.3 N allowed for the two discretisations), for 0.6 m x 0.6 m x 0.033 m of the paper's ice.
  const EdgeBreak b = edge_breaking_load(0.6, 0.6, 0.033, 60e6, 0.33, 36.4e3, 1000.0, 9.81);
  EXPECT_NEAR(b.load, 45.0, 0.3);
  EXPECT_NEAR(b.crack_distance, 0.20, 0.01);
}
