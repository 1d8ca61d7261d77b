// Floes kept out of Bullet's world until something reaches them (dem/world/unreached_floes.hpp,
// dem/activation/reach.hpp): a run is the same run, bit for bit, as with every floe in the world from the
// start, and the floes nothing reached stay out of it.
#include "dem/activation/reach.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "dem/input/scene_builder.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"

namespace icedem {
namespace {

struct Outcome {
  std::vector<btTransform> poses;  // World::floes() order
  std::vector<double> surge;       // N, per step
  int out_of_world_at_start = 0, out_of_world_at_end = 0, in_bullet_at_end = 0;
};

Outcome run(const std::string& scenario, std::vector<std::string> overrides, long steps) {
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + scenario, overrides);
  State state = initial_state(scene, scene_layout(scene).floes);
  Outcome o;
  o.out_of_world_at_start = state.world->unreached().size();
  while (state.step < steps) {
    step(scene, state);
    o.surge.push_back(state.load.force.x());
  }
  for (const FloeBody& f : state.world->floes()) o.poses.push_back(f.body->getWorldTransform());
  o.out_of_world_at_end = state.world->unreached().size();
  o.in_bullet_at_end = state.world->dynamics().getNumCollisionObjects();
  return o;
}

void expect_same_run(const std::string& scenario, std::vector<std::string> overrides, long steps) {
  std::vector<std::string> all_in = overrides;
  all_in.push_back("activation.unreached_out_of_world=false");
  const Outcome kept = run(scenario, overrides, steps), in = run(scenario, all_in, steps);
  std::printf("%s: %d floes out of the world at the start, %d after %ld steps (%d bodies in Bullet's world, %d "
              "with all in)\n",
              scenario.c_str(), kept.out_of_world_at_start, kept.out_of_world_at_end, steps, kept.in_bullet_at_end,
              in.in_bullet_at_end);
  // the test means something only if floes were kept out, some entered and some never did
  EXPECT_GT(kept.out_of_world_at_start, kept.out_of_world_at_end);
  EXPECT_GT(kept.out_of_world_at_end, 0);
  EXPECT_EQ(in.out_of_world_at_start, 0);
  // the same run: every pose and every step's load, bit for bit (a floe entering when reached
  // is the floe that rested in the world all along; its pairs are oriented by the order of
  // making, its island's bodies solved in the canonical order)
  ASSERT_EQ(kept.poses.size(), in.poses.size());
  int differ = 0;
  for (std::size_t i = 0; i < kept.poses.size(); ++i)
    differ += !(kept.poses[i] == in.poses[i]);
  EXPECT_EQ(differ, 0) << "floes whose pose differs";
  ASSERT_EQ(kept.surge.size(), in.surge.size());
  long first = -1;
  for (std::size_t k = 0; k < kept.surge.size() && first < 0; ++k)
    if (std::memcmp(&kept.surge[k], &in.surge[k], sizeof(double)) != 0) first = static_cast<long>(k);
  EXPECT_EQ(first, -1) << "first step whose load differs";
}

TEST(Reach, FloesEnteringWhenReachedMakeTheSameRun) {
  // 40 s of the short tow: the cone crosses a 4 m channel of small floes, the far ones untouched
  expect_same_run("/scenarios/examples/short_tow.toml", {"channel.length=20.0"}, 1000);
}

TEST(Reach, BreakableFloesEnteringWhenReachedMakeTheSameRun) {
  // large breakable floes: a stand-in kept out of the world enters before its lattice wakes
  expect_same_run("/scenarios/bench/large_breakable_short.toml", {"solver.profile=converged", "channel.length=16.0", "fracture.lattice_radius=1.0"},
                  1500);
}

TEST(Reach, FreezingKeepsEveryFloeInTheWorld) {
  // frozen floes entering when reached have not yet been made exact (dem/world/world.hpp): with
  // activation.freeze_outside_region every floe is in the world from the start
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/examples/short_tow.toml",
                                 {"activation.freeze_outside_region=true", "activation.region_ahead=1.5"});
  const State state = initial_state(scene, scene_layout(scene).floes);
  EXPECT_EQ(state.world->unreached().size(), 0);
  EXPECT_EQ(state.world->dynamics().getNumCollisionObjects(), static_cast<int>(state.world->bodies().size()));
}

}  // namespace
}  // namespace icedem
