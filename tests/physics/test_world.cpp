// The Bullet world and its registry alone (dem/world), and what the builder puts in it
// (dem/world_builder): bodies and their liveness, freezing, shared shapes, the structure and
// the lattices of breakable floes.
#include <gtest/gtest.h>

#include <btBulletDynamicsCommon.h>

#include "dem/world.hpp"
#include "dem/world_builder.hpp"
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

TEST(WorldBuilder, RigidFloesAreOneBodyEachAndBreakableOnesLatticesOfElementsAndJoints) {
  const std::vector<Floe> floes{square_floe(10, 0, 0.6), square_floe(12, 0, 0.6)};
  {
    const Scene rigid = bench_scene({"ice.floe_size=0.6"});
    World world(world_settings(rigid));
    add_profile_structure(world, rigid);
    add_floes(world, rigid, floes);
    ASSERT_NE(world.structure(), nullptr);
    EXPECT_EQ(world.floes().size(), 2u);
    EXPECT_TRUE(world.joints().empty());
  }
  // 0.6 m floes of 0.15 m elements, lattices everywhere: 4 x 4 elements and 2 x 4 x 3 joints each
  const Scene breakable = bench_scene({"ice.floe_size=0.6", "fracture.mode=on", "fracture.element_size=0.15",
                                       "fracture.lattice_radius=0"});
  World world(world_settings(breakable));
  add_floes(world, breakable, floes);
  EXPECT_EQ(world.floes().size(), 32u);
  EXPECT_EQ(world.joints().size(), 48u);
  for (const FloeBody& f : world.floes()) EXPECT_GE(f.fragment, 0);  // elements of a breakable floe
  // the elements of one floe carry its id and its mass between them
  double mass = 0;
  for (const FloeBody& f : world.floes())
    if (f.floe_id == 0) mass += f.shape->mass;
  EXPECT_NEAR(mass, breakable.ice.density * 0.6 * 0.6 * breakable.ice.thickness, 1e-12);
}
