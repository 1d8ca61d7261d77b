// The hull's contact zones with the analytic level sheet (dem/fracture/sheet_contact.hpp): the crushed ice's
// nominal area at a straight edge against the circle segments' closed form, the forces' resolution on the
// cone's slope, one zone per connected part of the crushed ice, and the refusal of a vertical wall.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dem/fracture/sheet_contact.hpp"
#include "dem/layout/polygon_set.hpp"

namespace icedem {
namespace {

// the paper's cone where the paper's ice meets it: 45 degrees, 0.617 m at the ice's top, 33 mm thick
HullInIce paper_cone() {
  HullInIce hull;
  hull.thickness = 0.033;
  hull.radius_top = 0.617;
  hull.radius_bottom = 0.617 - 0.033;
  return hull;
}

// the area of a circle of radius r beyond a chord at distance d from its centre
double segment(double r, double d) {
  if (d >= r) return 0.0;
  return r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d);
}

Polygon sheet_beyond(double edge) { return make_ccw({{edge, -5}, {edge + 10, -5}, {edge + 10, 5}, {edge, 5}}); }

const CrushingLaw kLaw{1.0e6, 0.0, 0.033 * 0.033};  // 1 MPa, constant pressure

// A straight edge 20 mm inside the larger section (and so, at 45 degrees, 13 mm beyond the smaller): the
// crushed ice's horizontal projection is the difference of the two circle segments, and the nominal area is
// that over cos 45. The sections are polygons of 256 segments, whose boundary lies at most r (1 - cos(pi /
// 256)) = 46 um inside the circle: over a segment 20 mm deep that is 0.35 % of its area, so 0.5 %
TEST(SheetContact, TheNominalAreaIsTheSlopesOverTheCrushedIce) {
  const HullInIce hull = paper_cone();
  const double edge = hull.radius_top - 0.020;
  const std::vector<SheetContact> zones = sheet_contacts(sheet_beyond(edge), hull, kLaw, 0.0);
  ASSERT_EQ(zones.size(), 1u);
  const double projected = segment(hull.radius_top, edge) - segment(hull.radius_bottom, edge);
  EXPECT_NEAR(zones[0].nominal_area, projected * std::sqrt(2.0), 5e-3 * projected * std::sqrt(2.0));
  EXPECT_NEAR(zones[0].direction.x(), 1.0, 1e-9);
  EXPECT_NEAR(zones[0].half_width, std::sqrt(hull.radius_top * hull.radius_top - edge * edge), 1e-3);
  EXPECT_GT(zones[0].centre.x(), edge);
  EXPECT_LT(zones[0].centre.x(), hull.radius_top);
}

// The forces on a 45-degree cone: normal N = sigma_c A; horizontal N (sin + mu cos), bending N (cos - mu sin);
// a downward-breaking cone (wider at the top) pushes the ice down, an upward one lifts it
TEST(SheetContact, TheForcesAreResolvedOnTheSlope) {
  HullInIce hull = paper_cone();
  const double edge = hull.radius_top - 0.010, mu = 0.2;
  const SheetContact c = sheet_contacts(sheet_beyond(edge), hull, kLaw, mu).at(0);
  EXPECT_NEAR(c.normal_force, kLaw.strength * c.nominal_area, 1e-9 * c.normal_force);
  EXPECT_NEAR(c.horizontal_force, c.normal_force * (1 + mu) / std::sqrt(2.0), 1e-9 * c.normal_force);
  EXPECT_NEAR(c.bending_force, c.normal_force * (1 - mu) / std::sqrt(2.0), 1e-9 * c.normal_force);
  EXPECT_LT(c.force_on_ice(hull).y(), 0) << "wider at the top: the ice goes down";
  EXPECT_NEAR(c.force_on_ice(hull).x(), c.horizontal_force, 1e-9 * c.normal_force);
  std::swap(hull.radius_top, hull.radius_bottom);
  const SheetContact up = sheet_contacts(sheet_beyond(hull.radius_bottom - 0.010), hull, kLaw, mu).at(0);
  EXPECT_GT(up.force_on_ice(hull).y(), 0) << "wider at the bottom: the ice rides up";
}

// A channel cut into the sheet, narrower than the hull, which stands in it: the ice either side of the channel
// within the larger section is crushed, two parts, two zones, one each side of the axis
TEST(SheetContact, EachPartOfCrushedIceIsAZone) {
  const HullInIce hull = paper_cone();
  const std::vector<Polygon> notched = subtract(sheet_beyond(-1.0), make_ccw({{-2, -0.3}, {0.7, -0.3}, {0.7, 0.3}, {-2, 0.3}}));
  ASSERT_EQ(notched.size(), 1u);
  const std::vector<SheetContact> zones = sheet_contacts(notched[0], hull, kLaw, 0.1);
  ASSERT_EQ(zones.size(), 2u);
  EXPECT_LT(zones[0].centre.y() * zones[1].centre.y(), 0.0) << "one each side";
  EXPECT_NEAR(std::abs(zones[0].direction.y()), std::abs(zones[1].direction.y()), 1e-6) << "mirror images";
}

// A wall as steep in the ice as a vertical one crushes the ice and does not bend it: refused
TEST(SheetContact, AVerticalWallIsRefused) {
  HullInIce hull = paper_cone();
  hull.radius_bottom = hull.radius_top - 0.001;
  EXPECT_THROW(sheet_contacts(sheet_beyond(0.6), hull, kLaw, 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace icedem
