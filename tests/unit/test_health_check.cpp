// A numerical blow-up stops with a message naming the step, the body and the
// quantity (DESIGN.md, "Exit codes").
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dem/errors.hpp"
#include "dem/health_check.hpp"
#include "dem/initial_state.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using icedem::testing::bench_scene;

namespace {

State two_floes(const Scene& scene) {
  State state = initial_state(scene, {icedem::testing::square_floe(10.0, 0.0), icedem::testing::square_floe(11.0, 0.0)});
  state.step = 1234;
  state.time = 24.68;
  return state;
}

std::string error_of(const Scene& scene, const State& state) {
  try {
    check_health(scene, state);
  } catch (const NumericalError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(HealthCheck, HealthyStatePasses) {
  const Scene scene = bench_scene();
  const State state = two_floes(scene);
  EXPECT_EQ(error_of(scene, state), "");
}

TEST(HealthCheck, RunawaySpeedNamesStepFloeAndQuantity) {
  const Scene scene = bench_scene();
  State state = two_floes(scene);
  state.world->floes()[1].body->setLinearVelocity(btVector3(300.0, 0, 0));
  const std::string msg = error_of(scene, state);
  EXPECT_NE(msg.find("step 1234"), std::string::npos) << msg;
  EXPECT_NE(msg.find("t = 24.680 s"), std::string::npos) << msg;
  EXPECT_NE(msg.find("floe 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("speed = 300"), std::string::npos) << msg;
}

TEST(HealthCheck, NotANumberPositionIsCaught) {
  const Scene scene = bench_scene();
  State state = two_floes(scene);
  btTransform t = state.world->floes()[0].body->getWorldTransform();
  t.setOrigin(btVector3(std::numeric_limits<double>::quiet_NaN(), 0, 0));
  state.world->floes()[0].body->setWorldTransform(t);
  const std::string msg = error_of(scene, state);
  EXPECT_NE(msg.find("floe 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("position"), std::string::npos) << msg;
}

TEST(HealthCheck, NonFiniteLoadIsCaught) {
  const Scene scene = bench_scene();
  State state = two_floes(scene);
  state.load.force.x() = std::numeric_limits<double>::infinity();
  const std::string msg = error_of(scene, state);
  EXPECT_NE(msg.find("structure"), std::string::npos) << msg;
}
