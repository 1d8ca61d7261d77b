#include "dem/step_size_advice.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/scenario_keys.hpp"

namespace icedem {
namespace {

// "use time.substeps >= n", or, beyond the key's largest value, the time.dt that gives a
// Bullet step of at most h_max at that many substeps
std::string advice(double dt, double h_max) {
  const int max_substeps = static_cast<int>(find_key("time.substeps")->max);
  const double needed = std::ceil(dt / h_max);
  if (needed <= max_substeps) return fmt::format("use time.substeps >= {}", static_cast<long>(needed));
  return fmt::format("use a Bullet step of at most {:.3g} s: time.dt <= {:.3g} s with time.substeps = {} (its "
                     "largest value)",
                     h_max, h_max * max_substeps, max_substeps);
}

}  // namespace

std::vector<std::string> step_size_warnings(const Scene& scene) {
  std::vector<std::string> out;
  const double dt = scene.time.dt, h = dt / scene.time.substeps;
  const double omega = std::sqrt(scene.water.density * scene.water.gravity / (scene.ice.density * scene.ice.thickness));
  if (omega * h > kMaxHeaveStep)
    out.push_back(fmt::format(
        "Bullet step {:.3g} s (time.dt / time.substeps) times the heave and pitch frequency of {} m ice "
        "({:.1f} rad/s) is {:.2f}: above {} the floating floes' motion loses accuracy and the load comes "
        "out low (-19 % at 0.72 on the short tow; a blow-up above about 1.24, dem/step_size_advice.hpp); "
        "{}",
        h, scene.ice.thickness, omega, omega * h, kMaxHeaveStep, advice(dt, kMaxHeaveStep / omega)));
  const double travel = scene.structure.speed * h / scene.ice.thickness;
  if (travel > kMaxTravelPerStep)
    out.push_back(fmt::format(
        "the structure moves {:.0f} % of the ice thickness per Bullet step (structure.speed x time.dt / "
        "time.substeps): above {:.0f} % ice is pushed into the hull and the load comes out low "
        "(scenarios/stress/fast_tow.toml); {}",
        100 * travel, 100 * kMaxTravelPerStep, advice(dt, kMaxTravelPerStep * scene.ice.thickness / scene.structure.speed)));
  return out;
}

}  // namespace icedem
