// The hydrostatics of the structure floating upright (dem/water/hull_hydrostatics.hpp): the paper's cone
// continued as a 45 degree frustum to its keel against the reference's hand-computed numbers, a vertical
// cylinder against its closed form, and heave's stiffness against the volume's own change.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dem/water/hull_hydrostatics.hpp"

namespace icedem {
namespace {

const std::vector<ProfileStation> kCone = {{-0.443, 0.171}, {0.0, 0.614}, {0.122, 0.736}};  // Table 2

// V = pi 0.443 / 3 (0.614^2 + 0.614 0.171 + 0.171^2) = 0.2372 m^3, A_wp = pi 0.614^2 = 1.1844 m^2,
// C33 = rho g A_wp = 11,619 N/m, KB = 0.2968 m above the keel, BM = 0.4707 m; with KG 0.30 m:
// GM 0.4675 m, C55 = 1,088 N m/rad (the reference's digits)
TEST(HullHydrostatics, ThePapersConeFloatingAtItsWaterline) {
  const HullHydrostatics h = hull_hydrostatics(kCone);
  EXPECT_NEAR(h.volume, 0.2372, 5e-5);
  EXPECT_NEAR(h.waterplane_area, 1.1844, 5e-5);
  EXPECT_NEAR(heave_stiffness(h, 1000, 9.81), 11619, 1);
  EXPECT_NEAR(h.buoyancy_centre_y + 0.443, 0.2968, 5e-5) << "KB above the keel";
  EXPECT_NEAR(h.metacentric_radius, 0.4707, 5e-5);
  EXPECT_NEAR(tilt_stiffness(h, -0.443 + 0.30, 1000, 9.81), 1088, 1);
}

// a vertical cylinder of radius r at draft d: V = pi r^2 d, KB = d / 2, BM = r^2 / (4 d), to round-off
TEST(HullHydrostatics, AVerticalCylinderIsItsClosedForm) {
  const double r = 0.5, d = 0.8;
  const HullHydrostatics h = hull_hydrostatics({{-d, r}, {0.0, r}, {0.3, r}});
  EXPECT_NEAR(h.volume, M_PI * r * r * d, 1e-14);
  EXPECT_NEAR(h.buoyancy_centre_y, -d / 2, 1e-14);
  EXPECT_NEAR(h.metacentric_radius, r * r / (4 * d), 1e-14);
}

// heave's stiffness is the displaced volume's change with the waterline: rho g dV/dz = rho g A_wp, the
// derivative taken by central differences (1e-6 m)
TEST(HullHydrostatics, HeaveStiffnessIsTheVolumesChange) {
  const double dz = 1e-6;
  const double dv = (hull_hydrostatics(kCone, dz).volume - hull_hydrostatics(kCone, -dz).volume) / (2 * dz);
  EXPECT_NEAR(dv, hull_hydrostatics(kCone).waterplane_area, 1e-8);
  EXPECT_THROW(hull_hydrostatics(kCone, -0.5), std::invalid_argument) << "a waterline below the keel";
  EXPECT_THROW(hull_hydrostatics(kCone, 0.2), std::invalid_argument) << "above the deck";
}

}  // namespace
}  // namespace icedem
