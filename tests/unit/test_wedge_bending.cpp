// The wedge of floating ice (dem/fracture/wedge_bending.hpp): the solver against Hetenyi's semi-infinite beam
// (its constant-width case), against an independent solution of the narrow wedge (the breaking factor S and
// the crack's distance for five load patches), its convergence in the mesh, and the breaking load of the
// paper's ice.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dem/fracture/wedge_bending.hpp"

namespace icedem {
namespace {

// Hetenyi: a semi-infinite beam on an elastic foundation under an end load has M = (P / beta) e^(-beta x)
// sin(beta x), largest e^(-pi/4) sin(pi/4) = 0.32240 P / beta at beta x = pi / 4. The FEM's curvature at the
// nodes converges at O(h^2): 1e-4 relative at 400 elements a characteristic length
TEST(WedgeBending, AConstantWidthIsHetenyisBeam) {
  const WedgeBending b = constant_width_bending();
  EXPECT_NEAR(b.stress_factor, std::exp(-M_PI / 4) * std::sin(M_PI / 4), 1e-4);
  EXPECT_NEAR(b.crack_distance, M_PI / 4, 2e-3) << "the vertex of the parabola through the nodes' moments";
}

// The narrow wedge loaded in uniform pressure over its first a: S and x* / l against an independent solution of
// the same equation (three digits for S, two for x*, as given; 0.5 % and 0.02 l allow their last digit)
TEST(WedgeBending, TheNarrowWedgeAgreesWithAnIndependentSolution) {
  struct Row { double patch, s, x; };
  const Row rows[] = {{0.05, 0.866, 0.39}, {0.1, 0.795, 0.51}, {0.2, 0.688, 0.68}, {0.3, 0.605, 0.81}, {0.5, 0.476, 1.04}};
  for (const Row& r : rows) {
    const WedgeBending b = wedge_bending(r.patch);
    EXPECT_NEAR(b.stress_factor, r.s, 0.005 * r.s) << "a / l " << r.patch;
    EXPECT_NEAR(b.crack_distance, r.x, 0.02) << "a / l " << r.patch;
  }
}

// A load at the apex (the patch shrinking) breaks the wedge at its apex: S -> 1, x* -> 0; S falls as the load
// spreads
TEST(WedgeBending, APointLoadBreaksTheApex) {
  double last = 1.0;
  for (double patch : {0.01, 0.05, 0.2, 1.0, 3.0}) {
    const WedgeBending b = wedge_bending(patch);
    EXPECT_LT(b.stress_factor, last) << patch;
    last = b.stress_factor;
  }
  EXPECT_GT(wedge_bending(0.005, 2000).stress_factor, 0.95);
}

TEST(WedgeBending, ConvergesInTheMesh) {
  const WedgeBending coarse = wedge_bending(0.2, 200), fine = wedge_bending(0.2, 800);
  EXPECT_NEAR(coarse.stress_factor, fine.stress_factor, 1e-3 * fine.stress_factor);
  EXPECT_NEAR(coarse.crack_distance, fine.crack_distance, 0.01);
}

// The paper's ice (E 60 MPa, nu 0.33, h 33 mm, sigma_b 36.4 kPa... as the reference's table: l = 0.3786 m):
// a 90-degree wedge loaded over its first 76 mm (a / l = 0.2) breaks at 19.2 N, 0.26 m from the apex
TEST(WedgeBending, ThePapersIceBreaksAsTheTableSays) {
  const double e = 60e6, nu = 0.33, h = 0.033, rho = 1000, g = 9.81;
  const double l = std::pow(e * h * h * h / (12 * (1 - nu * nu) * rho * g), 0.25);
  EXPECT_NEAR(l, 0.3786, 5e-4);
  const WedgeBreak w = wedge_breaking_load(M_PI / 2, 0.2 * l, h, e, nu, 36.4e3, rho, g);
  EXPECT_NEAR(w.load, 36.4e3 * h * h / (3 * wedge_bending(0.2).stress_factor), 1e-9);
  EXPECT_NEAR(w.load, 19.2, 0.2);
  EXPECT_NEAR(w.crack_distance, 0.26, 0.01);
  EXPECT_THROW(wedge_breaking_load(0.0, 0.05, h, e, nu, 36.4e3, rho, g), std::invalid_argument);
  EXPECT_THROW(wedge_bending(-1.0), std::invalid_argument);
}

}  // namespace
}  // namespace icedem
