// The semi-infinite floating plate loaded at its edge (dem/fracture/plate_edge_load.hpp) against an independent
// Fourier solution of the same problem: the edge deflection under a point load, the radial moment under a load
// spread over three widths, and the largest moment across the axis and where it is; then the breaking loads of
// the paper's ice.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dem/fracture/plate_edge_load.hpp"

namespace icedem {
namespace {

// w = 0.4693 P l^2 / D at nu = 0.33 and 0.4620 at nu = 0.3, as given to four digits (5e-4 allows the last)
TEST(PlateEdgeLoad, APointLoadsDeflection) {
  EXPECT_NEAR(plate_edge_response(0.0, 0.33).deflection, 0.4693, 5e-4);
  EXPECT_NEAR(plate_edge_response(0.0, 0.3).deflection, 0.4620, 5e-4);
  EXPECT_TRUE(std::isinf(plate_edge_response(0.0, 0.33).radial_moment)) << "a point load's moment beneath it";
}

// the radial moment under a load spread over |y| < a (m_y = 0.921, 0.745, 0.569 at a / l = 0.05, 0.1, 0.2, three
// digits: 1e-3), which falls as the load spreads; the largest moment across the axis, 0.126 P at 0.81 l (as given),
// hardly moved by the spread (within 2 % of the point load's)
TEST(PlateEdgeLoad, TheMomentsUnderAndBeyondTheLoad) {
  struct Row { double patch, my; };
  const Row rows[] = {{0.05, 0.921}, {0.1, 0.745}, {0.2, 0.569}};
  const PlateEdgeResponse point = plate_edge_response(0.0, 0.33);
  for (const Row& r : rows) {
    const PlateEdgeResponse p = plate_edge_response(r.patch, 0.33);
    EXPECT_NEAR(p.radial_moment, r.my, 1e-3) << r.patch;
    EXPECT_NEAR(p.circumferential_moment, point.circumferential_moment, 0.02 * point.circumferential_moment) << r.patch;
  }
  const PlateEdgeResponse p = plate_edge_response(0.1, 0.33);
  EXPECT_NEAR(p.circumferential_moment, 0.1264, 1e-3);
  EXPECT_NEAR(p.circumferential_distance, 0.81, 0.01);
  EXPECT_LT(p.circumferential_moment, p.radial_moment / 5) << "the sheet cracks radially first";
}

// The paper's ice (E 60 MPa, nu 0.33, h 33 mm, sigma_b 36.4 kPa; l = 0.3786 m) loaded over 2a = 76 mm: a radial
// crack at sigma_b h^2 / (6 m_y) = 8.87 N, a circumferential one only at 52.3 N, 0.31 m out
TEST(PlateEdgeLoad, ThePapersIceCracksRadiallyFirst) {
  const double e = 60e6, nu = 0.33, h = 0.033, rho = 1000, g = 9.81, sigma = 36.4e3;
  const double l = std::pow(e * h * h * h / (12 * (1 - nu * nu) * rho * g), 0.25);
  const PlateEdgeBreak b = plate_edge_breaking_load(0.1 * l, h, e, nu, sigma, rho, g);
  EXPECT_NEAR(b.radial_load, 8.87, 0.02);
  EXPECT_NEAR(b.circumferential_load, 52.3, 0.5);
  EXPECT_NEAR(b.circumferential_distance, 0.31, 0.01);
  EXPECT_THROW(plate_edge_response(-0.1, 0.33), std::invalid_argument);
  EXPECT_THROW(plate_edge_response(0.1, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace icedem
