#include "dem/water/hull_hydrostatics.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dem/core/constants.hpp"

namespace icedem {

HullHydrostatics hull_hydrostatics(const std::vector<ProfileStation>& profile, double waterline_y) {
  if (profile.size() < 2 || waterline_y < profile.front().y || waterline_y > profile.back().y)
    throw std::invalid_argument(fmt::format("the waterline at y = {} m is not on the hull (its stations span {} to {} m)",
                                            waterline_y, profile.empty() ? 0.0 : profile.front().y,
                                            profile.empty() ? 0.0 : profile.back().y));
  HullHydrostatics h;
  double moment = 0;  // m^4, of the volume about y = 0
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) {
    const ProfileStation& lo = profile[i];
    if (lo.y >= waterline_y) break;
    ProfileStation hi = profile[i + 1];
    if (hi.y > waterline_y) {  // the frustum cut at the waterline
      const double t = (waterline_y - lo.y) / (hi.y - lo.y);
      hi = ProfileStation{waterline_y, lo.radius + t * (hi.radius - lo.radius)};
    }
    const double a = lo.radius, b = hi.radius, dy = hi.y - lo.y;
    const double v = kPi * dy / 3 * (a * a + a * b + b * b);
    // a frustum's centroid above its base: dy (a^2 + 2 a b + 3 b^2) / (4 (a^2 + a b + b^2))
    const double above = a * a + a * b + b * b > 0 ? dy * (a * a + 2 * a * b + 3 * b * b) / (4 * (a * a + a * b + b * b)) : 0;
    h.volume += v;
    moment += v * (lo.y + above);
  }
  const double r = profile_radius(profile, waterline_y);
  h.buoyancy_centre_y = h.volume > 0 ? moment / h.volume : waterline_y;
  h.waterplane_area = kPi * r * r;
  h.waterplane_inertia = kPi * std::pow(r, 4) / 4;
  h.metacentric_radius = h.volume > 0 ? h.waterplane_inertia / h.volume : 0;
  return h;
}

double heave_stiffness(const HullHydrostatics& h, double water_density, double gravity) {
  return water_density * gravity * h.waterplane_area;
}

double tilt_stiffness(const HullHydrostatics& h, double gravity_centre_y, double water_density, double gravity) {
  const double gm = h.buoyancy_centre_y + h.metacentric_radius - gravity_centre_y;
  return water_density * gravity * h.volume * gm;
}

}  // namespace icedem
