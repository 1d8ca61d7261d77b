#include "dem/iso19906.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/cone_geometry.hpp"
#include "dem/errors.hpp"

namespace icedem {

ConeLoad iso19906_cone_load(const ConeLoadInputs& in) {
  const double a = in.slope, mu = in.friction, h = in.thickness, g = in.gravity;
  const double s = std::sin(a), c = std::cos(a);
  if (c - mu * s <= 0 || s - mu * c <= 0)
    throw InputError(fmt::format("ISO 19906 cone load: friction {} on a {:.1f} degree slope locks the ice on it "
                                 "(the method needs mu < tan a and mu < 1 / tan a)",
                                 mu, a * 180.0 / M_PI));
  const double ride_density = in.downward ? in.water_density - in.ice_density : in.ice_density;
  ConeLoad r{};
  r.characteristic_length = std::pow(in.elastic_modulus * h * h * h /
                                         (12.0 * in.water_density * g * (1.0 - in.poisson_ratio * in.poisson_ratio)),
                                     0.25);
  r.crack_width = in.waterline_diameter + M_PI * M_PI * r.characteristic_length / 4.0;
  r.slope_factor = (s + mu * c) / (c - mu * s);
  r.breaking = 0.68 * r.slope_factor * in.flexural_strength *
               std::pow(in.water_density * g * std::pow(h, 5) / in.elastic_modulus, 0.25) * r.crack_width;
  r.ride = in.waterline_diameter * in.ride_height * h * ride_density * g * (s + mu * c) / (s * (c - mu * s));
  r.turning = 1.5 * in.waterline_diameter * h * h * ride_density * g * c / (s - mu * c);
  // the sheet must also carry the breaking load over its crack width: the amplification in H
  const double amplification = 1.0 / (1.0 - r.breaking / (in.flexural_strength * r.crack_width * h));
  r.total = (r.breaking + r.ride + r.turning) * amplification;
  r.breaking_only = r.breaking * amplification;
  return r;
}

ConeLoadInputs cone_load_inputs(const Scene& scene) {
  const std::vector<ProfileStation>& p = scene.structure.profile;
  // the profile segment through the waterline: the one just below it carries a downward
  // slope, the one just above an upward one
  std::size_t below = 0;
  while (below + 1 < p.size() && p[below + 1].y < 0) ++below;
  if (p.front().y >= 0 || below + 1 >= p.size())
    throw InputError("ISO 19906 cone load: structure.profile does not cross the waterline (y = 0)");
  const double r0 = profile_radius(p, 0.0);
  const bool downward = p[below].radius < r0;
  ProfileStation from = p[below], to = p[below + 1];
  if (!downward) {  // the slope above the waterline
    std::size_t above = below + 1;
    while (above + 1 < p.size() && p[above].y <= 0) ++above;
    from = p[above - 1];
    to = p[above];
  }
  const double rise = std::abs(to.y - from.y), run = std::abs(to.radius - from.radius);
  if (run <= 0)
    throw InputError("ISO 19906 cone load: the hull is vertical at the waterline (structure.profile); the method "
                     "is for sloping structures");
  ConeLoadInputs in{};
  in.waterline_diameter = 2.0 * r0;
  in.slope = std::atan2(rise, run);
  in.downward = downward;
  in.ride_height = downward ? -from.y : to.y;
  in.thickness = scene.ice.thickness;
  in.flexural_strength = scene.ice.bending_strength;
  in.elastic_modulus = scene.ice.elastic_modulus;
  in.poisson_ratio = scene.ice.poisson_ratio;
  in.ice_density = scene.ice.density;
  in.water_density = scene.water.density;
  in.gravity = scene.water.gravity;
  in.friction = scene.friction.ice_structure;
  return in;
}

}  // namespace icedem
