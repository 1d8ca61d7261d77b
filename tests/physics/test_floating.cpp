// A floating floe in the real Bullet world with the water stage: Archimedes
// draft, reserve buoyancy, righting, terminal drift speed, and a still field.
// References: docs/model/validation_targets.md §1 (draft 30.69 mm, reserve buoyancy
// 2.04 N for a 0.3 m floe) and the drag law of dem/water/water_forces.hpp.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/core/constants.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using icedem::testing::bench_scene;
using icedem::testing::square_floe;

namespace {

double roll_pitch_deg(const btRigidBody& body) {
  // angle between the floe's normal (body y) and the vertical
  const btVector3 up = body.getWorldTransform().getBasis().getColumn(1);
  return std::acos(std::min(1.0, static_cast<double>(up.y()))) * 180 / kPi;
}

void run_for(const Scene& scene, State& state, double seconds) {
  const long n = std::lround(seconds / scene.time.dt);
  for (long i = 0; i < n; ++i) step(scene, state);
}

}  // namespace

TEST(Floating, FloeSettlesAtArchimedesDraft) {
  const Scene scene = bench_scene();
  State state = initial_state(scene, {square_floe(10, 0)});
  btRigidBody& body = *state.world->floes()[0].body;
  // release it 10 mm too high: it must fall and settle
  btTransform t = body.getWorldTransform();
  t.getOrigin() += btVector3(0, 0.010, 0);
  body.setWorldTransform(t);
  run_for(scene, state, 10.0);
  const double draft = scene.ice.thickness / 2 - body.getCenterOfMassPosition().y();
  // reference rho_i h / rho_w = 30.69 mm; 1 % (docs/model/validation_targets.md §1), the equilibrium is exact
  // up to the residual of the damped heave oscillation after 10 s
  EXPECT_NEAR(draft, 0.03069, 0.01 * 0.03069);
  EXPECT_NEAR(draft, 0.033 * 930.0 / 1000.0, 1e-6);  // settled to a micrometre
}

TEST(Floating, RaftedFloeRestsOnTheOneBelowAtTheirCombinedDraft) {
  // layout.layers: a floe of layer 1 starts on top of the floating layer; the
  // pair then floats as one plate of twice the thickness (Archimedes: its
  // bottom at 2 h rho_i / rho_w = 61.38 mm), the upper one resting on the lower
  const Scene scene = bench_scene();
  Floe upper = square_floe(10, 0);
  upper.layer = 1;
  State state = initial_state(scene, {square_floe(10, 0), upper});
  const double h = scene.ice.thickness;
  const btRigidBody& lower_body = *state.world->floes()[0].body;
  const btRigidBody& upper_body = *state.world->floes()[1].body;
  ASSERT_NEAR(upper_body.getCenterOfMassPosition().y() - lower_body.getCenterOfMassPosition().y(),
              h + scene.layout.min_gap, 1e-12);
  run_for(scene, state, 10.0);
  const double bottom = lower_body.getCenterOfMassPosition().y() - h / 2;
  // 1 mm: the contact between the floes keeps up to about one collision margin
  // (1 mm) of overlap or gap
  EXPECT_NEAR(-bottom, 2 * h * 930.0 / 1000.0, 0.001);
  EXPECT_NEAR(upper_body.getCenterOfMassPosition().y() - lower_body.getCenterOfMassPosition().y(), h, 0.001);
  EXPECT_LT(roll_pitch_deg(upper_body), 0.5);  // still a flat stack
}

TEST(Floating, TiltedFloeRightsItself) {
  const Scene scene = bench_scene();
  State state = initial_state(scene, {square_floe(10, 0)});
  btRigidBody& body = *state.world->floes()[0].body;
  btTransform t = body.getWorldTransform();
  t.setRotation(btQuaternion(btVector3(1, 0, 1).normalized(), 15 * kPi / 180));
  body.setWorldTransform(t);
  ASSERT_NEAR(roll_pitch_deg(body), 15.0, 1e-6);
  run_for(scene, state, 10.0);
  // GM = 0.243 m > 0 (docs/model/validation_targets.md §1): the heel decays; after 10 s (~28 natural
  // periods, damping ratio 0.5) anything above 0.1 degree means it did not right itself
  EXPECT_LT(roll_pitch_deg(body), 0.1);
}

TEST(Floating, FloeFieldInStillWaterStaysAtRest) {
  // a 75 % field of 0.3 m floes, all awake, 60 s: nothing may drift
  const Scene scene = bench_scene({"channel.start_x=0.0", "channel.length=3.0", "channel.width=2.4"});
  const Layout layout = scene_layout(scene);
  State state = initial_state(scene, layout.floes);
  ASSERT_GT(state.world->floes().size(), 50u);
  std::vector<btVector3> start;
  for (const FloeBody& f : state.world->floes()) start.push_back(f.body->getCenterOfMassPosition());
  run_for(scene, state, 60.0);
  double max_shift = 0, max_speed = 0;
  for (std::size_t i = 0; i < start.size(); ++i) {
    const btRigidBody& b = *state.world->floes()[i].body;
    max_shift = std::max(max_shift, static_cast<double>((b.getCenterOfMassPosition() - start[i]).length()));
    max_speed = std::max(max_speed, static_cast<double>(b.getLinearVelocity().length()));
  }
  // floes start at their exact equilibrium draft with gaps between them: any force
  // imbalance would show as drift. 1 micrometre and 1 micrometre/s leave room only
  // for round-off (docs/model/bullet.md measured 3e-17 m/s in double)
  EXPECT_LT(max_shift, 1e-6);
  EXPECT_LT(max_speed, 1e-6);
}

TEST(Floating, PushedFloeReachesItsTerminalSpeed) {
  const Scene scene = bench_scene();
  State state = initial_state(scene, {square_floe(10, 0)});
  btRigidBody& body = *state.world->floes()[0].body;
  const double F = 0.02;  // N, constant push in +x
  const long n = std::lround(40.0 / scene.time.dt);
  for (long i = 0; i < n; ++i) {
    body.applyCentralForce(btVector3(F, 0, 0));  // cleared by Bullet after each step
    step(scene, state);
  }
  // drag law (water_forces.hpp): form drag on the advancing edge L x d, skin friction
  // on the bottom L x L and both side faces L x d:
  //   F = 1/2 rho v^2 (C_d L d + C_f (L^2 + 2 L d))
  const double L = 0.3, d = 0.033 * 0.93, rho = 1000;
  const double cd = scene.water.drag_coefficient, cf = scene.water.skin_friction_coefficient;
  const double v_ref = std::sqrt(2 * F / (rho * (cd * L * d + cf * (L * L + 2 * L * d))));
  // 40 s is ~9 time constants m/(rho C A v); 1 %: the drag couple trims the floe
  // slightly, which changes the wetted areas a little
  EXPECT_NEAR(body.getLinearVelocity().x(), v_ref, 0.01 * v_ref);
  EXPECT_NEAR(body.getLinearVelocity().z(), 0.0, 1e-9);
}
