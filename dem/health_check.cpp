#include "dem/health_check.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/constants.hpp"
#include "dem/errors.hpp"

namespace icedem {
namespace {

[[noreturn]] void blow_up(const State& state, const std::string& what, const std::string& quantity,
                          double value, const std::string& limit) {
  throw NumericalError(fmt::format("numerical blow-up at step {} (t = {:.3f} s): {}: {} = {:.6g} {}",
                                   state.step, state.time, what, quantity, value, limit));
}

}  // namespace

double check_health(const Scene& scene, const State& state) {
  double max_angular_speed = 0;
  for (const FloeBody& floe : state.world->floes()) {
    const btRigidBody* body = floe.body;
    if (!body->isActive()) continue;  // a sleeping body does not move
    // an element of a breakable floe is named by its body index too (HDF5 /bodies order
    // differs only by the stand-ins of a lattice region)
    const std::string who = floe.fragment >= 0 ? fmt::format("floe {} (element body {})", floe.floe_id,
                                                              body->getUserIndex2())
                                               : fmt::format("floe {}", floe.floe_id);
    const btVector3& x = body->getCenterOfMassPosition();
    const btScalar v = body->getLinearVelocity().length();
    const btScalar w = body->getAngularVelocity().length();
    max_angular_speed = std::max(max_angular_speed, static_cast<double>(w));
    if (!std::isfinite(x.length())) blow_up(state, who, "|position|", x.length(), "m (not finite)");
    if (x.length() > kBlowUpDistance)
      blow_up(state, who, "|position|", x.length(), fmt::format("m, beyond {} m", kBlowUpDistance));
    if (!std::isfinite(v) || v > kBlowUpSpeed)
      blow_up(state, who, "speed", v, fmt::format("m/s, beyond {} m/s", kBlowUpSpeed));
    // a 0.3 m floe spinning at kBlowUpSpeed / 0.15 m would shed its edges at that speed
    const double size = std::max(scene.ice.floe_size, 1e-3);
    if (!std::isfinite(w) || w * size / 2 > kBlowUpSpeed)
      blow_up(state, who, "angular speed", w, "rad/s, edge speed beyond the blow-up speed");
  }
  if (!state.load.force.allFinite() || !state.load.moment.allFinite())
    blow_up(state, "structure", "ice load |F|", state.load.force.norm(), "N (not finite)");
  return max_angular_speed;
}

}  // namespace icedem
