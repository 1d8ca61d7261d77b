// The Bullet world and its registry alone (dem/world/world): bodies and their liveness, freezing,
// shared shapes. What the builder puts in it: test_world_builder.cpp.
#include <gtest/gtest.h>

#include <btBulletDynamicsCommon.h>

#include "dem/step/world_builder.hpp"  // world_settings
#include "dem/world/world.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

namespace {

btTransform at(double x, double y, double z) {
  btTransform t;
  t.setIdentity();
  t.setOrigin(btVector3(x, y, z));
  return t;
}

const Polygon kSquare{{-0.15, -0.15}, {0.15, -0.15}, {0.15, 0.15}, {-0.15, 0.15}};

}  // namespace

TEST(World, BodiesAreRegisteredWithTheirLivenessAndShareTheirShape) {
  World world(world_settings(bench_scene({"activation.sleeping=true"})));
  const FloeShape& shape = world.shape(kSquare);
  EXPECT_EQ(&world.shape(kSquare), &shape);  // one shape per outline, made once
  const int in = world.add_body(shape, at(0, 0, 0), 0, 0.5);
  const int out = world.add_body(shape, at(2, 0, 0), 1, 0.5, -1, false);
  ASSERT_EQ(world.floes().size(), 2u);
  EXPECT_EQ(world.floes()[in].floe_id, 0);
  EXPECT_EQ(world.floes()[out].floe_id, 1);
  // at rest with sleeping on: in the world but asleep; the other not in the world at all
  EXPECT_EQ(liveness(*world.floes()[in].body), Liveness::kAsleep);
  EXPECT_EQ(liveness(*world.floes()[out].body), Liveness::kOutside);
  EXPECT_EQ(world.awake_floes(), 0);
  world.floes()[in].body->activate(true);
  EXPECT_EQ(liveness(*world.floes()[in].body), Liveness::kAwake);
  EXPECT_EQ(world.awake_floes(), 1);
}

TEST(World, AFrozenFloeIsAFixedObstacleUntilUnfrozenWithItsMass) {
  World world(world_settings(bench_scene()));
  const FloeShape& shape = world.shape(kSquare);
  FloeBody& floe = world.floes()[world.add_body(shape, at(0, 0, 0), 0, 0.5)];
  const double inverse_mass = floe.body->getInvMass();
  ASSERT_GT(inverse_mass, 0);
  world.freeze(floe);
  EXPECT_TRUE(floe.frozen);
  EXPECT_EQ(floe.body->getInvMass(), 0);
  EXPECT_EQ(liveness(*floe.body), Liveness::kAsleep);
  EXPECT_EQ(world.frozen_floe(floe.body), &floe);
  world.unfreeze(floe);
  EXPECT_FALSE(floe.frozen);
  EXPECT_EQ(floe.body->getInvMass(), inverse_mass);
  EXPECT_EQ(liveness(*floe.body), Liveness::kAwake);
  EXPECT_EQ(world.frozen_floe(floe.body), nullptr);
}
