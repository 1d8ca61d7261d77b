#include "dem/mooring/floating_structure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/water/hull_hydrostatics.hpp"

namespace icedem {
namespace {

// integral of f(y, r(y)) dy over the profile between y0 and y1 by Gauss-Legendre on each frustum
// (5 points: exact for the polynomials of degree 9 and below a frustum's integrands are)
template <typename F>
double integrate(const std::vector<ProfileStation>& p, double y0, double y1, F f) {
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                              0.2369268850561891};
  double sum = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const double a = std::max(p[i].y, y0), b = std::min(p[i + 1].y, y1);
    if (b <= a) continue;
    for (int k = 0; k < 5; ++k) {
      const double y = 0.5 * (a + b) + 0.5 * (b - a) * x[k];
      sum += 0.5 * (b - a) * w[k] * f(y, profile_radius(p, y));
    }
  }
  return sum;
}

}  // namespace

HullSolid hull_solid(const std::vector<ProfileStation>& p) {
  const double lo = p.front().y, hi = p.back().y;
  HullSolid s;
  s.volume = integrate(p, lo, hi, [](double, double r) { return kPi * r * r; });
  if (!(s.volume > 0)) return s;
  s.centroid_y = integrate(p, lo, hi, [](double y, double r) { return kPi * r * r * y; }) / s.volume;
  const double yc = s.centroid_y;
  // a disc of radius r: r^2 / 4 about a diameter, r^2 / 2 about its axis, per unit mass
  s.tilt_gyration2 =
      integrate(p, lo, hi, [yc](double y, double r) { return kPi * r * r * (r * r / 4 + (y - yc) * (y - yc)); }) / s.volume;
  s.axial_gyration2 = integrate(p, lo, hi, [](double, double r) { return kPi * r * r * r * r / 2; }) / s.volume;
  return s;
}

AddedMass6 hull_added_mass(const std::vector<ProfileStation>& p, double rho, double yg) {
  const double keel = p.front().y, waterline = std::min(0.0, p.back().y);
  AddedMass6 a;
  if (waterline <= keel) return a;
  // the widest section at or below the waterline: the disc the hull pushes when it heaves
  const double r = hull_radius_over(p, keel, waterline);
  const double strips = rho * integrate(p, keel, waterline, [](double, double rr) { return kPi * rr * rr; });
  a.linear = Eigen::Vector3d(strips, 4.0 / 3.0 * rho * r * r * r, strips);
  const double tilt = rho * integrate(p, keel, waterline, [yg](double y, double rr) { return kPi * rr * rr * (y - yg) * (y - yg); }) +
                      8.0 / 45.0 * rho * std::pow(r, 5);
  a.angular = Eigen::Vector3d(tilt, 0, tilt);
  return a;
}

double hull_buoyancy(const Scene& scene, double heave) {
  const std::vector<ProfileStation>& p = scene.structure.profile;
  // the water stands at -heave in the hull's own frame
  const double w = std::clamp(-heave, p.front().y, p.back().y);
  const double volume = -heave <= p.front().y ? 0.0 : hull_hydrostatics(p, w).volume;
  return scene.water.density * scene.water.gravity * volume;
}

FloatingStructure make_floating_structure(const Scene& scene) {
  const StructureSettings& st = scene.structure;
  const std::vector<ProfileStation>& p = st.profile;
  const double rho = scene.water.density, g = scene.water.gravity;
  FloatingStructure b;
  const HullHydrostatics rest = hull_hydrostatics(p, std::clamp(0.0, p.front().y, p.back().y));
  // the mooring as laid out from the structure's axis at the still-water line
  const Eigen::Vector3d axis(st.start_x, 0, st.start_z);
  std::unique_ptr<Mooring> mooring = make_mooring(scene, axis);
  // mass 0: what floats at the still-water line with the mooring pulling (its lines' weight held there)
  const double pull_up = mooring->load(axis, Eigen::Matrix3d::Identity(), 0).force.y();
  b.mass = st.mass > 0 ? st.mass : rho * rest.volume + pull_up / g;
  if (!(b.mass > 0))
    throw std::invalid_argument(fmt::format("the mooring pulls the hull down by {:.1f} N, more than its buoyancy at the "
                                            "waterline holds ({:.1f} N)",
                                            -pull_up, rho * g * rest.volume));
  const HullSolid solid = hull_solid(p);
  b.gravity_centre_y = st.gravity_centre_y;
  b.solid_centroid_y = solid.centroid_y;
  const Eigen::Vector3d solid_inertia(b.mass * solid.tilt_gyration2, b.mass * solid.axial_gyration2,
                                      b.mass * solid.tilt_gyration2);
  for (int i = 0; i < 3; ++i) b.inertia[i] = st.inertia[i] > 0 ? st.inertia[i] : solid_inertia[i];
  const AddedMass6 estimate = hull_added_mass(p, rho, b.gravity_centre_y);
  for (int i = 0; i < 3; ++i) {
    b.added_mass[i] = st.added_mass[i] >= 0 ? st.added_mass[i] : estimate.linear[i];
    b.added_inertia[i] = st.added_inertia[i] >= 0 ? st.added_inertia[i] : estimate.angular[i];
  }

  // the rest: weight, buoyancy and the mooring's vertical pull in balance (bisection on the heave,
  // the buoyancy growing as the hull sinks)
  const auto net_up = [&](double heave) {
    return hull_buoyancy(scene, heave) - b.mass * g +
           mooring->load(axis + Eigen::Vector3d(0, heave, 0), Eigen::Matrix3d::Identity(), 0).force.y();
  };
  double sink = -(p.back().y - p.front().y), rise = -p.front().y;  // the deck at the water, the keel at it
  if (net_up(sink) < 0)
    throw std::invalid_argument(fmt::format("the hull cannot float {:.1f} kg (structure.mass) with its mooring's pull: "
                                            "it sinks past its deck", b.mass));
  for (int i = 0; i < 200 && rise - sink > 1e-12; ++i) {
    const double mid = 0.5 * (sink + rise);
    (net_up(mid) > 0 ? sink : rise) = mid;
  }
  b.rest_heave = 0.5 * (sink + rise);
  b.start = axis + Eigen::Vector3d(0, b.rest_heave, 0);
  // the mooring as laid out from the structure at rest (its linear springs are unstretched there)
  b.mooring = std::shared_ptr<const Mooring>(make_mooring(scene, b.start).release());

  const HullHydrostatics h = hull_hydrostatics(p, std::clamp(-b.rest_heave, p.front().y, p.back().y));
  b.displaced_volume = h.volume;
  b.heave_stiffness = heave_stiffness(h, rho, g);
  // GM in the hull's frame: the centre of gravity's height there is gravity_centre_y
  b.tilt_stiffness = tilt_stiffness(h, b.gravity_centre_y, rho, g);
  if (!(b.tilt_stiffness > 0))
    throw std::invalid_argument(fmt::format("the structure does not float upright: its metacentric height is {:.3f} m "
                                            "(centre of gravity at {:.3f} m above the waterline, structure.gravity_centre_y)",
                                            b.tilt_stiffness / (rho * g * h.volume), b.gravity_centre_y));

  // each motion's stiffness: the water's (heave, roll, pitch) and the mooring's
  const DiagonalStiffness k = mooring_stiffness(*b.mooring, b.start);
  const Eigen::Vector3d k_lin = k.linear + Eigen::Vector3d(0, b.heave_stiffness, 0);
  const Eigen::Vector3d k_ang = k.angular + Eigen::Vector3d(b.tilt_stiffness, 0, b.tilt_stiffness);
  for (int i = 0; i < 3; ++i) {
    const double m = b.mass + b.added_mass[i], j = b.inertia[i] + b.added_inertia[i];
    b.damping[i] = 2 * st.damping_ratio[i] * std::sqrt(std::max(k_lin[i], 0.0) * m);
    b.angular_damping[i] = 2 * st.angular_damping_ratio[i] * std::sqrt(std::max(k_ang[i], 0.0) * j);
    b.linear_frequency[i] = std::sqrt(std::max(k_lin[i], 0.0) / m);
    b.angular_frequency[i] = std::sqrt(std::max(k_ang[i], 0.0) / j);
  }
  b.highest_frequency = std::max(b.linear_frequency.maxCoeff(), b.angular_frequency.maxCoeff());
  return b;
}

FloatingStructure checked_floating_structure(const Scene& scene) {
  const std::string& file = scene.source_path;
  for (const MooringLine& l : scene.mooring.model == MooringModel::kCatenary
                                  ? catenary_lines(scene, Eigen::Vector3d(scene.structure.start_x, 0, scene.structure.start_z))
                                  : std::vector<MooringLine>{})
    if (std::abs(l.anchor.z()) > 0.5 * scene.channel.tank_width)
      throw InputError(fmt::format("{}: mooring.anchor_radius: an anchor at z = {:.3f} m lies beyond the tank's side "
                                   "(tank.width = {} m); expected anchors within it (a shorter radius, or "
                                   "mooring.first_line_angle turning the lines)",
                                   file, l.anchor.z(), scene.channel.tank_width));
  FloatingStructure b;
  try {
    b = make_floating_structure(scene);
  } catch (const std::exception& e) {
    throw InputError(fmt::format("{}: structure.motion = \"moored\": {}", file, e.what()));
  }
  const double h = scene.time.dt / scene.time.substeps;
  if (b.highest_frequency * h > 1) {
    const int substeps = static_cast<int>(std::ceil(b.highest_frequency * scene.time.dt));
    throw InputError(fmt::format("{}: time.substeps: the Bullet step {} s is too long for the moored structure's "
                                 "stiffest motion (natural frequency {:.3g} rad/s, period {:.3g} s): w h = {:.2f}, "
                                 "expected at most 1; use time.substeps = {} or more, or a softer mooring",
                                 file, h, b.highest_frequency, 2 * kPi / b.highest_frequency, b.highest_frequency * h,
                                 substeps));
  }
  return b;
}

std::string describe(const FloatingStructure& b) {
  const auto period = [](double w) { return w > 0 ? fmt::format("{:.3g} s", 2 * kPi / w) : std::string("free"); };
  const DiagonalStiffness k = mooring_stiffness(*b.mooring, b.start);
  std::string out;
  out += fmt::format("moored structure: mass {:.1f} kg, centre of gravity {:.4f} m above the waterline (the hull as a "
                     "uniform solid: {:.4f} m), resting {:.1f} mm {} it; inertia (roll, yaw, pitch) {:.2f}, {:.2f}, "
                     "{:.2f} kg m^2\n",
                     b.mass, b.gravity_centre_y, b.solid_centroid_y, 1e3 * std::abs(b.rest_heave),
                     b.rest_heave < 0 ? "below" : "above", b.inertia.x(), b.inertia.y(), b.inertia.z());
  out += fmt::format("  added mass (surge, heave, sway) {:.1f}, {:.1f}, {:.1f} kg; added inertia (roll, yaw, pitch) {:.2f}, "
                     "{:.2f}, {:.2f} kg m^2\n",
                     b.added_mass.x(), b.added_mass.y(), b.added_mass.z(), b.added_inertia.x(), b.added_inertia.y(),
                     b.added_inertia.z());
  out += fmt::format("  stiffness: heave {:.0f} N/m (water), roll and pitch {:.0f} N m/rad (water); mooring at rest: surge {:.0f}, "
                     "sway {:.0f}, heave {:.0f} N/m, yaw {:.0f} N m/rad\n",
                     b.heave_stiffness, b.tilt_stiffness, k.linear.x(), k.linear.z(), k.linear.y(), k.angular.y());
  out += fmt::format("  natural periods: surge {}, heave {}, sway {}, roll {}, yaw {}, pitch {}\n",
                     period(b.linear_frequency.x()), period(b.linear_frequency.y()), period(b.linear_frequency.z()),
                     period(b.angular_frequency.x()), period(b.angular_frequency.y()), period(b.angular_frequency.z()));
  out += fmt::format("  damping: {:.1f}, {:.1f}, {:.1f} N s/m (surge, heave, sway); {:.2f}, {:.2f}, {:.2f} N m s/rad (roll, yaw, pitch)\n",
                     b.damping.x(), b.damping.y(), b.damping.z(), b.angular_damping.x(), b.angular_damping.y(),
                     b.angular_damping.z());
  return out;
}

}  // namespace icedem
