#include "dem/input/step_size_advice.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "dem/input/scenario_keys.hpp"

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
        "out low (-19 % at 0.72 on the short tow; a blow-up above about 1.24, dem/input/step_size_advice.hpp); "
        "{}",
        h, scene.ice.thickness, omega, omega * h, kMaxHeaveStep, advice(dt, kMaxHeaveStep / omega)));
  // the water's damping is explicit too: semi-implicit Euler on x'' = -omega^2 x - 2 zeta omega x'
  // has eigenvalues inside the unit circle only while (omega h)^2 + 4 zeta omega h < 4 (Jury's
  // conditions); omega bounds the roll and pitch frequencies as well (a floe's pitch inertia only
  // adds to its mass's)
  const double zeta = std::max(scene.water.heave_damping_ratio, scene.water.roll_pitch_damping_ratio);
  const double wh = omega * h;
  if (wh * wh + 4 * zeta * wh >= 4)
    out.push_back(fmt::format(
        "the floes' water damping cannot be integrated at this step: with damping ratio {:.3g} "
        "(water.heave_damping_ratio, water.roll_pitch_damping_ratio) and omega h = {:.2f}, (omega h)^2 + 4 "
        "zeta omega h = {:.2f} is not below 4, and the floating floes' motion grows without bound (a "
        "blow-up, dem/input/step_size_advice.cpp); {}",
        zeta, wh, wh * wh + 4 * zeta * wh, advice(dt, 0.9 * 2 * (std::sqrt(zeta * zeta + 1) - zeta) / omega)));
  const double travel = scene.structure.speed * h / scene.ice.thickness;
  if (travel > kMaxTravelPerStep)
    out.push_back(fmt::format(
        "the structure moves {:.0f} % of the ice thickness per Bullet step (structure.speed x time.dt / "
        "time.substeps): above {:.0f} % ice is pushed into the hull and the load comes out low "
        "(scenarios/stress/fast_tow.toml); {}",
        100 * travel, 100 * kMaxTravelPerStep, advice(dt, kMaxTravelPerStep * scene.ice.thickness / scene.structure.speed)));
  // lattices: any scene whose fracture.mode can make them (generated floes, a level sheet, a
  // layout's lattice region); smaller elements than the 0.15 m measured are stiffer still
  const bool lattices = scene.fracture.mode == FractureMode::kOn || scene.fracture.mode == FractureMode::kAuto;
  if (lattices && scene.fracture.element_size < kConvergedElementSize - 1e-9 && h > kMaxLatticeStep * (1 + 1e-9))
    out.push_back(fmt::format(
        "Bullet step {:.3g} s (time.dt / time.substeps) with breakable elements of {:.3g} m "
        "(fracture.element_size): lattices of 0.15 m elements break with the step above {:.3g} s (at 0.02 s "
        "their mean of maxima is 28 % below 0.01 s's and breaks in the rubble are missing; from 0.01 s to 0.005 s "
        "nothing moves resolvably: docs/model/step_convergence_dt_half.md), and smaller elements are "
        "stiffer; {}",
        h, scene.fracture.element_size, kMaxLatticeStep, advice(dt, kMaxLatticeStep)));
  return out;
}

}  // namespace icedem
