#include "dem/fracture/sheet_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dem/layout/polygon_set.hpp"

namespace icedem {

Eigen::Vector3d SheetContact::force_on_ice(const HullInIce& hull) const {
  return Eigen::Vector3d(horizontal_force * direction.x(), -hull.breaking_sign() * bending_force,
                         horizontal_force * direction.y());
}

Polygon larger_section(const HullInIce& hull) { return disc(hull.axis, hull.larger(), kSectionSegments); }
Polygon smaller_section(const HullInIce& hull) { return disc(hull.axis, hull.smaller(), kSectionSegments); }

std::vector<SheetContact> sheet_contacts(const Polygon& sheet, const HullInIce& hull, const CrushingLaw& law,
                                         double friction) {
  const double flare = hull.larger() - hull.smaller();
  if (!(flare >= kSteepestSheetFlare * hull.thickness))
    throw std::invalid_argument("sheet_contacts: the hull's radius changes by " + std::to_string(flare) +
                                " m across the ice's thickness, too steep a wall to bend the ice");
  const double slant = std::hypot(flare, hull.thickness);
  const double cos_a = flare / slant, sin_a = hull.thickness / slant;
  const Polygon small = smaller_section(hull);

  std::vector<SheetContact> out;
  for (Polygon& zone : intersect(sheet, larger_section(hull))) {
    SheetContact c;
    double inner = 0;
    for (const Polygon& p : intersect(zone, small)) inner += area(p);
    const double projected = std::max(area(zone) - inner, 0.0);
    c.centre = centroid(zone);
    const Eigen::Vector2d radial = c.centre - hull.axis;
    if (radial.norm() > 0) c.direction = radial.normalized();
    const Eigen::Vector2d across(-c.direction.y(), c.direction.x());
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const Eigen::Vector2d& v : zone) {
      low = std::min(low, v.dot(across));
      high = std::max(high, v.dot(across));
    }
    c.half_width = (high - low) / 2;
    c.nominal_area = projected / cos_a;
    c.normal_force = crushing_force(law, c.nominal_area);
    c.horizontal_force = c.normal_force * (sin_a + friction * cos_a);
    c.bending_force = c.normal_force * (cos_a - friction * sin_a);
    c.zone = std::move(zone);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace icedem
