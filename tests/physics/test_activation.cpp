// Sleeping and freezing (dem/activation/activation, dem/world/contact_islands): floes at rest cost nothing,
// and a disturbance wakes only the floes it touches. Bullet builds sleeping islands from
// overlapping bounding boxes, which joins a whole 75 % field into one island
// (docs/model/bullet.md); the contact island manager joins only touching floes.
// Floes far behind the structure leave the run (dem/activation/left_behind) and stay ice in the tank.
#include <gtest/gtest.h>

#include "dem/core/errors.hpp"
#include "dem/step/health_check.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using icedem::testing::scene_from;
using icedem::testing::square_floe;

namespace {

const char* kField = R"(
[flow]
model = "still"
[structure]
speed = 0.0
start_x = -50.0
[channel]
start_x = 0.0
length = 3.0
width = 2.4
[activation]
freeze_outside_region = false
)";

// a floe near the middle of the field, set bobbing (heave only, so it touches nobody)
btRigidBody& poke_middle_floe(State& state) {
  FloeBody* best = nullptr;
  double best_d = 1e9;
  for (FloeBody& f : state.world->floes()) {
    const btVector3 p = f.body->getCenterOfMassPosition();
    const double d = std::hypot(p.x() - 1.5, p.z());
    if (d < best_d) best_d = d, best = &f;
  }
  // a floe nothing has reached waits out of the world (dem/world/unreached_floes.hpp): it enters first
  state.world->enter_reached(static_cast<int>(best - state.world->floes().data()));
  best->body->activate(true);
  best->body->setLinearVelocity(btVector3(0, 0.05, 0));
  return *best->body;
}

int awake_after(const Scene& scene, State& state, double seconds) {
  for (long i = 0; i < std::lround(seconds / scene.time.dt); ++i) step(scene, state);
  return state.world->awake_floes();
}

}  // namespace

TEST(Sleeping, FloesAtRestStartAsleepAndStayAsleep) {
  const Scene scene = scene_from(kField);
  State state = initial_state(scene, scene_layout(scene).floes);
  EXPECT_EQ(state.world->awake_floes(), 0);
  EXPECT_EQ(awake_after(scene, state, 2.0), 0);
}

TEST(Sleeping, ContactIslandsWakeOnlyTheDisturbedFloe) {
  const Scene scene = scene_from(kField, {"activation.islands=contact"});
  State state = initial_state(scene, scene_layout(scene).floes);
  ASSERT_GT(state.world->floes().size(), 50u);
  poke_middle_floe(state);
  // the bobbing floe keeps its 2 mm gaps: it touches no neighbour, so it is alone
  EXPECT_EQ(awake_after(scene, state, 0.5), 1);
  // and it falls asleep again once its heave has decayed (damping ratio 0.5)
  EXPECT_EQ(awake_after(scene, state, 5.0), 0);
}

TEST(Sleeping, BulletIslandsWakeTheWholeField) {
  // the behaviour the contact islands fix: same disturbance, Bullet's islands
  const Scene scene = scene_from(kField, {"activation.islands=bullet"});
  State state = initial_state(scene, scene_layout(scene).floes);
  poke_middle_floe(state);
  const int awake = awake_after(scene, state, 0.5);
  EXPECT_GT(awake, static_cast<int>(state.world->floes().size()) / 2) << "awake " << awake;
}

// Bullet gives both bodies of every manifold a solver body in the solve of body
// 0's island, empty manifolds included. With contact islands, neighbours 2 mm
// apart share a manifold but not an island, so a floe was solved in its own
// island and again in its neighbour's, and got its weight and water forces once
// per solve: it heaved as if several times lighter, which made the explicit
// heave and roll damping unstable (a blow-up in the paper grid, docs/model/stability.md). Bullet
// batches islands for the solver (128 rows by default), which hid this in small
// fields; batches of one island show it in any field.
TEST(Sleeping, FloesThatDoNotTouchHeaveAsIfAlone) {
  const Scene scene = scene_from(kField, {"activation.islands=contact", "activation.sleeping=false"});
  State field = initial_state(scene, scene_layout(scene).floes);
  State alone = initial_state(scene, {square_floe(1.5, 0.0)});
  ASSERT_GT(field.world->floes().size(), 50u);
  const auto lift = [](State& state, double dy) {
    for (FloeBody& f : state.world->floes()) {
      btTransform pose = f.body->getCenterOfMassTransform();
      pose.getOrigin() += btVector3(0, dy, 0);
      f.body->setCenterOfMassTransform(pose);
      f.body->getMotionState()->setWorldTransform(pose);
    }
  };
  field.world->dynamics().getSolverInfo().m_minimumSolverBatchSize = 1;  // one island per solve
  alone.world->dynamics().getSolverInfo().m_minimumSolverBatchSize = 1;
  lift(field, 0.005);
  lift(alone, 0.005);
  std::vector<double> y0;
  for (const FloeBody& f : field.world->floes()) y0.push_back(f.body->getCenterOfMassPosition().y());
  const double alone_y0 = alone.world->floes()[0].body->getCenterOfMassPosition().y();
  for (int i = 0; i < 10; ++i) {  // 0.2 s: the floe falls through its equilibrium and rebounds
    step(scene, field);
    step(scene, alone);
  }
  const double expected = alone.world->floes()[0].body->getCenterOfMassPosition().y() - alone_y0;
  ASSERT_LT(expected, -0.003);  // it did move
  // the same arithmetic for every floe, in another order: round-off only
  for (std::size_t i = 0; i < y0.size(); ++i)
    EXPECT_NEAR(field.world->floes()[i].body->getCenterOfMassPosition().y() - y0[i], expected, 1e-9) << "floe " << i;
}

// Freezing (dem/activation/activation.hpp): resting floes outside the activation region are
// fixed obstacles until struck faster than the wake speed or reached by the region.
namespace {
const char* kPair = R"(
[flow]
model = "still"
[structure]
speed = 0.0
start_x = -50.0
[activation]
freeze_outside_region = true
)";

}  // namespace

TEST(Freezing, RestingFloesOutsideTheRegionAreFrozen) {
  const Scene scene = scene_from(kPair);
  State state = initial_state(scene, {square_floe(10.0, 0.0), square_floe(10.5, 0.0)});
  step(scene, state);
  for (const FloeBody& f : state.world->floes()) {
    EXPECT_TRUE(f.frozen);
    EXPECT_EQ(f.body->getInvMass(), 0.0);  // a fixed obstacle for the solver
  }
}

TEST(Freezing, FloesInsideTheRegionAreNeverFrozen) {
  // the structure 1 m behind the floes: they are inside region_ahead (3 m)
  const Scene scene = scene_from(kPair, {"structure.start_x=9.0"});
  State state = initial_state(scene, {square_floe(10.0, 0.0), square_floe(10.5, 0.0)});
  for (int i = 0; i < 100; ++i) step(scene, state);
  for (const FloeBody& f : state.world->floes()) EXPECT_FALSE(f.frozen);
}

TEST(Freezing, StruckFloeIsReleasedAndCarriesOn) {
  const Scene scene = scene_from(kPair);
  State state = initial_state(scene, {square_floe(10.0, 0.0), square_floe(10.5, 0.0)});
  step(scene, state);
  FloeBody& striker = state.world->floes()[0];
  FloeBody& target = state.world->floes()[1];
  ASSERT_TRUE(target.frozen);
  // throw the first floe at the second at 5 cm/s (10x the wake speed)
  state.world->unfreeze(striker);
  striker.body->setLinearVelocity(btVector3(0.05, 0, 0));
  const double x0 = target.body->getCenterOfMassPosition().x();
  for (int i = 0; i < 400; ++i) step(scene, state);
  // drag slows it (time constant ~11 s) but the 0.2 m gap closes within ~5 s; inelastic contact then shares the momentum: the
  // target must have moved on by millimetres at least (frozen, it would not move at all)
  EXPECT_GT(target.body->getCenterOfMassPosition().x() - x0, 0.005);
}

TEST(Freezing, SlowContactDoesNotReleaseAFrozenFloe) {
  const Scene scene = scene_from(kPair);
  State state = initial_state(scene, {square_floe(10.0, 0.0), square_floe(10.302, 0.0)});
  step(scene, state);
  FloeBody& pusher = state.world->floes()[0];
  FloeBody& target = state.world->floes()[1];
  state.world->unfreeze(pusher);
  // creep into it at a fifth of the wake speed: the frozen floe stays fixed
  const double v = 0.2 * scene.activation.linear_threshold;
  const double x0 = target.body->getCenterOfMassPosition().x();
  for (int i = 0; i < 100; ++i) {
    pusher.body->activate(true);
    pusher.body->setLinearVelocity(btVector3(v, 0, 0));
    step(scene, state);
  }
  EXPECT_TRUE(target.frozen);
  EXPECT_EQ(target.body->getCenterOfMassPosition().x(), x0);
}

// activation.leave_behind (dem/activation/left_behind.hpp): a rigid floe leaves the run when all of it lies
// farther than the distance behind the structure's axis; one across the line stays. The structure stands 1 m
// ahead of the field (its hull clear of it) and the line is 2.5 m behind it, 1.5 m into the 3 m field
TEST(LeftBehind, FloesWhollyBehindTheLineLeaveTheRunAndStayIce) {
  const Scene scene = scene_from(kField, {"structure.start_x=4.0", "activation.leave_behind=2.5",
                                          "activation.unreached_out_of_world=false"});
  State state = initial_state(scene, scene_layout(scene).floes);
  std::vector<char> behind;
  for (const FloeBody& f : state.world->floes()) {
    btVector3 lo, hi;
    f.body->getCollisionShape()->getAabb(f.body->getWorldTransform(), lo, hi);
    behind.push_back(hi.x() < 4.0 - 2.5 ? 1 : 0);
  }
  const double mass = check_health(scene, state).ice_mass;
  step(scene, state);
  int left = 0;
  for (std::size_t i = 0; i < behind.size(); ++i) {
    const FloeBody& f = state.world->floes()[i];
    EXPECT_EQ(f.left, behind[i] != 0) << "floe " << i;
    EXPECT_EQ(f.body->isInWorld(), !f.left) << "floe " << i;
    left += f.left;
  }
  EXPECT_GT(left, 0);
  EXPECT_LT(left, static_cast<int>(behind.size()));
  EXPECT_EQ(state.world->left_floes().size(), static_cast<std::size_t>(left));
  // the floes that left are still ice in the tank: the mass the health check counts is unchanged (to round-off
  // of the sum's order)
  EXPECT_NEAR(state.diagnostics.ice_mass, mass, 1e-12 * mass);
}

// a floe that nothing has reached waits out of the world where the layout put it: it does not leave
TEST(LeftBehind, FloesKeptOutUntilReachedDoNotLeave) {
  const Scene scene = scene_from(kField, {"structure.start_x=4.0", "activation.leave_behind=2.5"});
  State state = initial_state(scene, scene_layout(scene).floes);
  step(scene, state);
  EXPECT_TRUE(state.world->left_floes().empty());
}

// a distance the hull reaches past would take out a floe the structure touches: refused, naming the key
TEST(LeftBehind, ADistanceInsideTheHullIsRefused) {
  try {
    scene_from(kField, {"activation.leave_behind=0.3"});
    FAIL() << "activation.leave_behind = 0.3 m, inside the hull, was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("activation.leave_behind"), std::string::npos) << e.what();
  }
}
