#include "dem/step_size_advice.hpp"

#include <cmath>

#include <fmt/format.h>

namespace icedem {

std::vector<std::string> step_size_warnings(const Scene& scene) {
  std::vector<std::string> out;
  const double dt = scene.time.dt, h = dt / scene.time.substeps;
  const double omega = std::sqrt(scene.water.density * scene.water.gravity / (scene.ice.density * scene.ice.thickness));
  if (omega * h > kMaxHeaveStep)
    out.push_back(fmt::format(
        "Bullet step {:.3g} s (time.dt / time.substeps) times the heave and pitch frequency of {} m ice "
        "({:.1f} rad/s) is {:.2f}: above {} the floating floes' motion loses accuracy and the load comes "
        "out low (-19 % at 0.72 on the short tow; a blow-up above about 1.24, dem/step_size_advice.hpp); "
        "use time.substeps >= {}",
        h, scene.ice.thickness, omega, omega * h, kMaxHeaveStep, static_cast<int>(std::ceil(omega * dt / kMaxHeaveStep))));
  const double travel = scene.structure.speed * h / scene.ice.thickness;
  if (travel > kMaxTravelPerStep)
    out.push_back(fmt::format(
        "the structure moves {:.0f} % of the ice thickness per Bullet step (structure.speed x time.dt / "
        "time.substeps): above {:.0f} % ice is pushed into the hull and the load comes out low "
        "(scenarios/stress/fast_tow.toml); use time.substeps >= {}",
        100 * travel, 100 * kMaxTravelPerStep,
        static_cast<int>(std::ceil(scene.structure.speed * dt / scene.ice.thickness / kMaxTravelPerStep))));
  return out;
}

}  // namespace icedem
