// Where the structure's hull crushes the edge of the analytic level sheet, and the load it puts on it
// (ice.cover = "level", fracture.mode = "analytic": docs/model/breakage.md, "Level ice cut by closed forms").
//
// The sheet is held where it lies, a slab from y_b = -draft to y_t = thickness - draft, and the hull is a
// body of revolution: its section at a height is a disc of the profile's radius there. Between the ice's
// two faces the hull is taken as the frustum from r_b = r(y_b) to r_t = r(y_t), inclined at alpha to the
// horizontal (tan alpha = h / |r_t - r_b|). The ice the hull's larger section holds is crushed ice: it
// stays in the sheet's outline, as the overlap of a crushing contact does (dem/contact/crushing.hpp), and
// each of its connected parts is one contact zone. The hull's surface in contact with a zone is the part
// of the frustum over it; its horizontal projection is the zone less the ice within the smaller section,
// so its nominal area is
//   A = (|Z ∩ C_large| - |Z ∩ C_small|) / cos(alpha),
// the ice crushes at p(A) (Daley's pressure-area, the project's crushing law) and the hull pushes the ice
// with N = p(A) A along the surface's normal, the ice sliding along the surface against friction mu:
//   horizontal  N (sin alpha + mu cos alpha)  away from the axis,
//   vertical    N (cos alpha - mu sin alpha)  down on a downward-breaking cone (r_t > r_b), up on an upward
// (Ralston's resolution of the normal and friction forces on a cone). The vertical part bends the sheet.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dem/contact/crushing.hpp"
#include "dem/input/scene.hpp"
#include "dem/layout/polygon.hpp"

namespace icedem {

/// The hull where it meets the sheet.
struct HullInIce {
  Eigen::Vector2d axis = Eigen::Vector2d::Zero();  // m, (x, z) of the hull's axis
  double radius_top = 0;                           // m, at the ice's top face
  double radius_bottom = 0;                        // m, at its bottom face
  double thickness = 0;                            // m, the ice's
  double larger() const { return radius_top > radius_bottom ? radius_top : radius_bottom; }
  double smaller() const { return radius_top > radius_bottom ? radius_bottom : radius_top; }
  /// +1 where the hull pushes the ice down (wider at the top), -1 where it lifts it.
  double breaking_sign() const { return radius_top > radius_bottom ? 1.0 : -1.0; }
};

/// One connected zone of crushed ice at the sheet's edge and its load.
struct SheetContact {
  Polygon zone;                                          // m, the ice within the hull's larger section
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();      // m, its centroid: where the load acts
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit, from the axis towards the centre
  double half_width = 0;       // m, half the zone's extent across `direction`: the load's patch
  double nominal_area = 0;     // m^2, A
  double normal_force = 0;     // N, p(A) A
  double horizontal_force = 0;  // N, on the ice along `direction`
  double bending_force = 0;     // N, on the ice normal to the sheet, in the sense the cone breaks it (>= 0
                                //    unless friction turns it)
  /// The force on the ice (x, y, z), N: horizontal along `direction`, vertical by the hull's breaking sign.
  Eigen::Vector3d force_on_ice(const HullInIce& hull) const;
};

/// Segments of the discs that stand for the hull's sections: their area is the circle's to 1e-4
/// (1 - sin(2 pi / n) n / (2 pi)).
constexpr int kSectionSegments = 256;

/// The hull's sections as polygons of kSectionSegments, the larger first.
Polygon larger_section(const HullInIce& hull);
Polygon smaller_section(const HullInIce& hull);

/// The contact zones of the hull with the sheet `sheet` (m, ccw), crushing by `law`, the ice sliding on the
/// hull with friction coefficient `friction`. None where they do not meet. Throws std::invalid_argument for
/// a hull steeper in the ice than kSteepestSheetFlare allows (dem/input/scene.hpp).
std::vector<SheetContact> sheet_contacts(const Polygon& sheet, const HullInIce& hull, const CrushingLaw& law,
                                         double friction);

}  // namespace icedem
