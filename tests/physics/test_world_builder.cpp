// What the builder puts in the world (dem/world_builder): the structure, rigid floes as one
// body each, breakable floes as lattices of elements and joints that share the floe's id and mass.
#include <gtest/gtest.h>

#include "dem/world.hpp"
#include "dem/world_builder.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

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
