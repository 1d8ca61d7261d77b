// A numerical blow-up stops with a message naming the step, the body and the
// quantity (docs/user/commands.md, exit codes).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dem/core/errors.hpp"
#include "dem/step/health_check.hpp"
#include "dem/step/initial_state.hpp"
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

// The diagnostics the stress suite bounds, against hand formulas.
TEST(HealthCheck, DiagnosticsMeasureSpeedEnergyAndMass) {
  const Scene scene = bench_scene();
  State state = two_floes(scene);
  const double side = 0.3, mass = scene.ice.density * side * side * scene.ice.thickness;
  btRigidBody& body = *state.world->floes()[1].body;
  body.setLinearVelocity(btVector3(0.1, 0.0, 0.2));
  body.setAngularVelocity(btVector3(0.0, 0.5, 0.0));  // yaw, about the plate's normal
  const StepDiagnostics d = check_health(scene, state);
  const double yaw_inertia = mass * (side * side + side * side) / 12;  // thin square plate
  EXPECT_NEAR(d.max_speed, std::sqrt(0.05), 1e-12);
  EXPECT_NEAR(d.max_angular_speed, 0.5, 1e-12);
  EXPECT_NEAR(d.kinetic_energy, 0.5 * mass * 0.05 + 0.5 * yaw_inertia * 0.25, 1e-9 * mass);
  EXPECT_NEAR(d.ice_mass, 2 * mass, 1e-12);
  EXPECT_EQ(d.max_cone_penetration, 0.0);  // the structure is parked 60 m away
  EXPECT_EQ(d.max_joint_gap, 0.0);         // rigid floes have no joints
}

TEST(HealthCheck, IceThatLeftTheTankIsMissingFromTheMass) {
  const Scene scene = bench_scene();
  State state = two_floes(scene);
  btTransform t = state.world->floes()[0].body->getWorldTransform();
  t.setOrigin(btVector3(10.0, -scene.channel.tank_depth - 1.0, 0.0));  // under the tank floor
  state.world->floes()[0].body->setWorldTransform(t);
  const double mass = scene.ice.density * 0.09 * scene.ice.thickness;
  EXPECT_NEAR(check_health(scene, state).ice_mass, mass, 1e-12);
}

TEST(HealthCheck, FloeInsideTheConeShowsAsPenetration) {
  // the structure axis at x = 10 m; a 0.3 m floe centred 0.3 m from the axis
  // reaches to 0.15 m from it, far inside the 0.614 m waterline radius
  const Scene scene = bench_scene({"structure.start_x=10.0"});
  State state = initial_state(scene, {icedem::testing::square_floe(10.3, 0.0)});
  state.structure_position = Eigen::Vector3d(10.0, 0.0, 0.0);
  const double top = scene.ice.thickness * (1 - scene.ice.density / scene.water.density);  // freeboard
  // deepest vertex: a top corner at (0.15, +-0.15) from the axis; the facets
  // stay within 0.3 % of the circle's radius
  const double expected = (0.614 + top) - std::hypot(0.15, 0.15);
  EXPECT_NEAR(check_health(scene, state).max_cone_penetration, expected, 0.003 * 0.614);
}

TEST(HealthCheck, DisplacedElementOpensItsJoints) {
  const Scene scene = bench_scene({"fracture.mode=on", "fracture.element_size=0.15"});
  State state = initial_state(scene, {icedem::testing::square_floe(10.0, 0.0)});
  ASSERT_EQ(state.world->joints().size(), 4u);  // 2 x 2 elements
  EXPECT_LT(check_health(scene, state).max_joint_gap, 1e-12);  // built closed
  btRigidBody& element = *state.world->floes()[0].body;
  btTransform t = element.getWorldTransform();
  t.setOrigin(t.getOrigin() + btVector3(0.01, 0.0, 0.0));  // pure translation: every anchor moves 1 cm
  element.setWorldTransform(t);
  EXPECT_NEAR(check_health(scene, state).max_joint_gap, 0.01, 1e-12);
}
