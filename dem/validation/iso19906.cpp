#include "dem/validation/iso19906.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "dem/core/errors.hpp"
#include "dem/world/cone_geometry.hpp"

namespace icedem {

namespace {

// A pile's values in their ranges, or an InputError naming the value and the range.
void check_rubble(const RubblePile& p, double slope) {
  const auto fail = [](const std::string& what) {
    throw InputError("ISO 19906 cone load: rubble pile " + what);
  };
  if (!(p.height >= 0)) fail(fmt::format("height {} m: expected >= 0", p.height));
  if (p.height == 0) return;
  if (!(p.porosity >= 0 && p.porosity < 1)) fail(fmt::format("porosity {}: expected 0 <= e < 1", p.porosity));
  if (!(p.angle > 0 && p.angle <= slope))
    fail(fmt::format("angle {:.1f} deg: expected above 0 and at most the slope's {:.1f} deg", p.angle * 180 / M_PI,
                     slope * 180 / M_PI));
  if (!(p.friction_angle >= 0 && p.friction_angle < M_PI / 2))
    fail(fmt::format("friction angle {:.1f} deg: expected 0 to 90 deg", p.friction_angle * 180 / M_PI));
  if (!(p.cohesion >= 0)) fail(fmt::format("cohesion {} Pa: expected >= 0", p.cohesion));
}

}  // namespace

ConeLoad iso19906_cone_load(const ConeLoadInputs& in) {
  const double a = in.slope, mu = in.friction, mu_i = in.ice_friction, h = in.thickness, g = in.gravity;
  const double s = std::sin(a), c = std::cos(a), D = in.waterline_diameter;
  if (c - mu * s <= 0 || s - mu * c <= 0)
    throw InputError(fmt::format("ISO 19906 cone load: friction {} on a {:.1f} degree slope locks the ice on it "
                                 "(the method needs mu < tan a and mu < 1 / tan a)",
                                 mu, a * 180.0 / M_PI));
  check_rubble(in.rubble, a);
  const double ride_density = in.downward ? in.water_density - in.ice_density : in.ice_density;
  ConeLoad r{};
  r.characteristic_length = std::pow(in.elastic_modulus * h * h * h /
                                         (12.0 * in.water_density * g * (1.0 - in.poisson_ratio * in.poisson_ratio)),
                                     0.25);
  r.crack_width = D + M_PI * M_PI * r.characteristic_length / 4.0;
  r.slope_factor = (s + mu * c) / (c - mu * s);
  r.breaking = 0.68 * r.slope_factor * in.flexural_strength *
               std::pow(in.water_density * g * std::pow(h, 5) / in.elastic_modulus, 0.25) * r.crack_width;
  // with a pile the ice rides under it to its top; without, the given ride height
  const RubblePile& pile = in.rubble;
  const double h_r = r.ride_height = pile.height > 0 ? pile.height : in.ride_height;
  double P = h_r * h * ride_density * g * (s + mu * c) / s;  // the broken ice's own weight (or buoyancy)
  if (pile.height > 0) {
    const double k = 1.0 - std::tan(pile.angle) / std::tan(a);
    const double cot_t = 1.0 / std::tan(pile.angle), cot_a = c / s;
    const double w_pile = ride_density * g * (1.0 - pile.porosity);  // the pile's weight (or buoyancy) per volume
    // the pile's weight on the riding ice: friction on its top (mu_i) and on the slope (mu)
    P += 0.5 * mu_i * (mu_i + mu) * w_pile * h_r * h_r * s * (cot_t - cot_a) * k +
         0.5 * (mu_i + mu) * w_pile * h_r * h_r * c * cot_a * k;
    r.pile_push = D * h_r * h_r * mu_i * w_pile * k * k / (2.0 * std::tan(pile.angle));
    r.pile_lift = r.slope_factor * D * h_r * k *
                  (0.5 * h_r * w_pile * (cot_t - cot_a + std::tan(pile.friction_angle) * k) + pile.cohesion);
  }
  r.ride = D * P / (c - mu * s);
  r.turning = 1.5 * D * h * h * ride_density * g * c / (s - mu * c);
  // the sheet must also carry the breaking load over its crack width: the amplification in H
  const double carried = 1.0 - r.breaking / (in.flexural_strength * r.crack_width * h);
  if (carried <= 0)
    throw InputError(fmt::format("ISO 19906 cone load: the breaking load H_B {:.4g} N exceeds what the sheet carries "
                                 "over its crack width, sigma_f w h = {:.4g} N: the method does not apply",
                                 r.breaking, in.flexural_strength * r.crack_width * h));
  const double amplification = 1.0 / carried;
  r.total = (r.breaking + r.pile_push + r.ride + r.pile_lift + r.turning) * amplification;
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
  in.end_diameter = 2.0 * (downward ? from.radius : to.radius);
  in.thickness = scene.ice.thickness;
  in.flexural_strength = scene.ice.bending_strength;
  in.elastic_modulus = scene.ice.elastic_modulus;
  in.poisson_ratio = scene.ice.poisson_ratio;
  in.ice_density = scene.ice.density;
  in.water_density = scene.water.density;
  in.gravity = scene.water.gravity;
  in.friction = scene.friction.ice_structure;
  in.ice_friction = scene.friction.ice_ice;
  return in;
}

}  // namespace icedem
