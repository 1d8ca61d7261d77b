// What the builder puts in the world (dem/step/world_builder): the structure, rigid floes as one
// body each, breakable floes as lattices of elements and joints that share the floe's id and mass.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "dem/step/step.hpp"
#include "dem/step/world_builder.hpp"
#include "dem/world/world.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

TEST(WorldBuilder, RigidFloesAreOneBodyEachAndBreakableOnesLatticesOfElementsAndJoints) {
  const std::vector<Floe> floes{square_floe(10, 0, 0.6), square_floe(12, 0, 0.6)};
  {
    const Scene rigid = bench_scene({"ice.floe_size=0.6"});
    World world(world_settings(rigid));
    add_profile_structure(world, rigid, structure_position_at(rigid, 0.0));
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

TEST(WorldBuilder, TheHullsMarginGrowsTheConeByIt) {
  // structure.collision_margin: Bullet rounds a convex hull and grows it by its margin, so the
  // cone's widest station (radius 0.736 m, Table 2) reaches out by the margin: 1 mm by default,
  // 40 mm at Bullet's default margin. Measured by the pieces' support along the tank's width, the
  // point of the shape contacts are found against
  auto widest = [](double margin) {
    const Scene scene = bench_scene({"structure.collision_margin=" + std::to_string(margin)});
    World world(world_settings(scene));
    add_profile_structure(world, scene, structure_position_at(scene, 0.0));
    const auto* hull = static_cast<const btCompoundShape*>(world.structure()->getCollisionShape());
    double reach = 0;
    for (int i = 0; i < hull->getNumChildShapes(); ++i) {
      const auto* piece = static_cast<const btConvexShape*>(hull->getChildShape(i));
      reach = std::max(reach, double(piece->localGetSupportingVertex(btVector3(0, 0, 1)).z()));
    }
    return reach;
  };
  const double thin = widest(0.001), thick = widest(0.04);
  std::printf("the hull's half-width: %.4f m at 1 mm margin, %.4f m at 40 mm\n", thin, thick);
  // exact to round-off: the support is a vertex plus the margin along the direction
  EXPECT_NEAR(thick - thin, 0.039, 1e-9);
  // the polygon keeps each station's area (its vertices 0.14 % outside the circle at 48 sides),
  // plus the 1 mm margin: 0.7381 m
  EXPECT_NEAR(thin, 0.736 + 0.001, 2e-3);
}

TEST(WorldBuilder, TheMotherIceEdgesCarryTheirOwnFriction) {
  // channel.edge_friction_factor scales the mother ice's friction (both edges and the end wall)
  // from friction.ice_ice; the tank's walls and floor keep friction.ice_ice
  const Scene scene = bench_scene({"friction.ice_ice=0.4", "channel.edge_friction_factor=0.25"});
  World world(world_settings(scene));
  add_boundaries(world, scene);
  std::vector<double> found;
  const btCollisionObjectArray& objects = world.dynamics().getCollisionObjectArray();
  for (int i = 0; i < objects.size(); ++i) found.push_back(objects[i]->getFriction());
  const auto edges = std::count(found.begin(), found.end(), btScalar(0.4 * 0.25));
  const auto walls = std::count(found.begin(), found.end(), btScalar(0.4));
  EXPECT_EQ(edges, scene.channel.end_wall ? 3 : 2);  // two edges and the end wall
  EXPECT_EQ(edges + walls, static_cast<long>(found.size())) << "every boundary is mother ice or the tank";
  EXPECT_GE(walls, 3);  // two side walls and the floor at least
}

// A field made row by row (10,000 floes) settles into the broadphase's tree of resting boxes
// built balanced (World::settle_broadphase): its depth is of order log2 of the bodies, where
// Bullet's own one-at-a-time move into that tree two steps later had made a chain (the first
// steps of a 96,000-floe field took 22 s). It finds the pairs an unsettled world finds.
TEST(WorldBuilder, AFieldSettlesIntoABalancedTreeOfRestingBoxes) {
  // floes at rest asleep, as in a run: they stay in the tree of resting boxes. All of them in
  // the world (none kept out until reached, dem/world/unreached_floes.hpp): that tree is the subject
  const Scene scene =
      bench_scene({"ice.floe_size=0.3", "activation.sleeping=true", "activation.unreached_out_of_world=false"});
  std::vector<Floe> floes;
  constexpr int kRows = 100, kColumns = 100;
  for (int i = 0; i < kColumns; ++i)
    for (int k = 0; k < kRows; ++k) floes.push_back(square_floe(10.0 + 0.3 * i, -15.0 + 0.3 * k, 0.29));
  // the same field settled or not, stepped once, then with a floe dropped over four of them
  auto pairs_of = [&](bool settle, int& depth) {
    World world(world_settings(scene));
    add_floes(world, scene, floes);
    if (settle) world.settle_broadphase();
    auto& dbvt = dynamic_cast<btDbvtBroadphase&>(*world.dynamics().getBroadphase());
    if (settle) {
      EXPECT_EQ(dbvt.m_sets[btDbvtBroadphase::DYNAMIC_SET].m_leaves, 0);
      EXPECT_EQ(dbvt.m_sets[btDbvtBroadphase::FIXED_SET].m_leaves, kRows * kColumns);
    }
    world.dynamics().stepSimulation(scene.time.dt, 0);
    world.dynamics().stepSimulation(scene.time.dt, 0);
    depth = btDbvt::maxdepth(dbvt.m_sets[btDbvtBroadphase::FIXED_SET].m_root);
    btOverlappingPairCache& pairs = *dbvt.getOverlappingPairCache();
    const int resting = pairs.getNumOverlappingPairs();
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(btVector3(10.0 + 0.3 * 50 + 0.15, 0.02, -15.0 + 0.3 * 40 + 0.15));
    const int dropped = world.add_body(world.shape(floes.front().shape), pose, kRows * kColumns, 0.5);
    world.floes()[dropped].body->forceActivationState(ACTIVE_TAG);
    world.dynamics().stepSimulation(scene.time.dt, 0);
    return std::make_pair(resting, pairs.getNumOverlappingPairs() - resting);
  };
  int settled_depth = 0, bullet_depth = 0;
  const auto settled = pairs_of(true, settled_depth), bullet = pairs_of(false, bullet_depth);
  EXPECT_EQ(settled.first, bullet.first);
  EXPECT_EQ(settled.second, 4);  // the four floes under the dropped one
  EXPECT_EQ(bullet.second, 4);
  // a balanced binary tree of 10,000 leaves is 14 deep; top-down splits by the median centre
  // are close to that (2 log2 N is room for uneven splits)
  EXPECT_LE(settled_depth, 2 * 14);
  std::printf("10,000 floes: fixed tree %d deep settled, %d as Bullet moves them; %d pairs\n", settled_depth,
              bullet_depth, settled.first);
}
