// A world rebuilt from a checkpoint's state (dem/output/world_state.hpp): it holds the state it was
// rebuilt from, bit for bit, and continues as the world it was taken from does, up to the
// round-off of its own order of bodies and contacts.
#include "dem/output/world_state.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <tuple>

#include "dem/input/scene_builder.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "tests/support/rebuilt_world.hpp"

namespace icedem {
namespace {

using testing::advanced;
using testing::rebuilt;

Scene short_tow(std::vector<std::string> overrides = {}) {
  return load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/examples/short_tow.toml", overrides);
}

bool same_bytes(const void* a, const void* b, std::size_t n) { return std::memcmp(a, b, n) == 0; }

// a manifold's points by the pair and child shapes they join, body0 first as stored
using Points = std::map<std::tuple<int, int, int, int>, const ManifoldState*>;
Points by_pair(const WorldState& s) {
  Points out;
  for (const ManifoldState& m : s.manifolds)
    out[{m.body0, m.body1, m.points.front().m_index0, m.points.front().m_index1}] = &m;
  return out;
}

long points(const WorldState& s) {
  long n = 0;
  for (const ManifoldState& m : s.manifolds) n += static_cast<long>(m.points.size());
  return n;
}

void expect_rebuilt_state(const Scene& scene, long steps) {
  const State run = advanced(scene, steps);
  const WorldState taken = capture_world(*run.world);
  ASSERT_GT(points(taken), 100) << "the scene should hold a pack in contact";

  const State copy = rebuilt(scene, run);
  const WorldState again = capture_world(*copy.world);
  ASSERT_EQ(again.bodies.size(), taken.bodies.size());
  for (std::size_t i = 0; i < taken.bodies.size(); ++i) {
    const BodyState &a = taken.bodies[i], &b = again.bodies[i];
    EXPECT_TRUE(same_bytes(a.transform, b.transform, sizeof a.transform)) << "body " << i;
    EXPECT_TRUE(same_bytes(a.linear, b.linear, 3 * sizeof(double))) << "body " << i;
    EXPECT_TRUE(same_bytes(a.angular, b.angular, 3 * sizeof(double))) << "body " << i;
    EXPECT_EQ(a.activation, b.activation) << "body " << i;
    EXPECT_EQ(a.deactivation_time, b.deactivation_time) << "body " << i;
    EXPECT_EQ(a.frozen, b.frozen) << "body " << i;
    EXPECT_EQ(a.in_world, b.in_world) << "body " << i;
  }
  // every contact point, with the impulses the next step starts from; a pair Bullet now
  // holds the other way round has its points turned with it
  const Points before = by_pair(taken), after = by_pair(again);
  long kept = 0;
  for (const auto& [key, m] : before) {
    auto it = after.find(key);
    const bool turned = it == after.end();
    if (turned) it = after.find({std::get<1>(key), std::get<0>(key), std::get<3>(key), std::get<2>(key)});
    if (it == after.end()) continue;  // dropped: counted below
    ASSERT_EQ(it->second->points.size(), m->points.size());
    for (std::size_t k = 0; k < m->points.size(); ++k) {
      const btManifoldPoint &p = m->points[k], &q = it->second->points[k];
      EXPECT_EQ(p.m_appliedImpulse, q.m_appliedImpulse);
      EXPECT_EQ(p.m_appliedImpulseLateral1, q.m_appliedImpulseLateral1);
      EXPECT_EQ(p.m_distance1, q.m_distance1);
      EXPECT_EQ(p.m_lifeTime, q.m_lifeTime);
      EXPECT_EQ(p.m_normalWorldOnB, turned ? -q.m_normalWorldOnB : q.m_normalWorldOnB);
      EXPECT_EQ(p.m_localPointA, turned ? q.m_localPointB : q.m_localPointA);
      EXPECT_EQ(m->has_friction_memory[k], it->second->has_friction_memory[k]);
      EXPECT_EQ(m->friction_memory[k], turned ? -it->second->friction_memory[k] : it->second->friction_memory[k]);
    }
    kept += static_cast<long>(m->points.size());
  }
  // every point: the pairs the checkpoint names all touch, so the rebuilt world has them
  EXPECT_EQ(kept, points(taken)) << "of " << points(taken) << " points, " << kept << " kept";

  // the floes the run never moved or touched stay in the broadphase's tree of resting boxes,
  // where the build put them: a large field's restore then costs what its moved floes cost
  const WorldState built = capture_world(*initial_state(scene, scene_layout(scene).floes).world);
  std::vector<char> touching(taken.bodies.size(), 0);
  for (const ManifoldState& m : taken.manifolds) touching[m.body0] = touching[m.body1] = 1;
  int untouched = 0;
  for (std::size_t i = 0; i < taken.bodies.size(); ++i)
    untouched += taken.bodies[i].in_world && !touching[i] &&
                 same_bytes(taken.bodies[i].transform, built.bodies[i].transform, sizeof built.bodies[i].transform);
  auto& dbvt = dynamic_cast<btDbvtBroadphase&>(*copy.world->dynamics().getBroadphase());
  const int resting = dbvt.m_sets[btDbvtBroadphase::FIXED_SET].m_leaves;
  std::printf("%d of %zu bodies untouched, %d boxes in the resting tree after the rebuild\n", untouched,
              taken.bodies.size(), resting);
  ASSERT_GT(untouched, 0) << "the scene should leave part of its field untouched";
  EXPECT_GE(resting, untouched);
}

TEST(WorldState, ARebuiltWorldHoldsTheStateItWasBuiltFrom) {
  expect_rebuilt_state(short_tow(), 1200);  // 24 s: the cone is in the ice, a pack in front of it
}

TEST(WorldState, ARebuiltLatticeWorldHoldsTheStateItWasBuiltFrom) {
  expect_rebuilt_state(load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/bench/large_breakable_short.toml",
                                  {"solver.profile=converged"}), 1800);
}

TEST(WorldState, ARebuiltWorldContinuesAsTheOriginal) {
  const Scene scene = short_tow();
  State run = advanced(scene, 1200);
  State copy = rebuilt(scene, run);
  double load_run = 0, load_copy = 0, largest_gap = 0;
  for (int k = 0; k < 250; ++k) {
    step(scene, run);
    step(scene, copy);
    load_run += run.load.force.x();
    load_copy += copy.load.force.x();
  }
  for (std::size_t i = 0; i < run.world->floes().size(); ++i)
    largest_gap = std::max(largest_gap, (run.world->floes()[i].body->getCenterOfMassPosition() -
                                         copy.world->floes()[i].body->getCenterOfMassPosition())
                                            .length());
  // the rebuilt world may hold its bodies and contacts in another order, which changes the
  // sweeps' round-off, and they stop at solver.tolerance: over 5 s the paths must stay within a
  // micrometre and the mean load within 1 %. Measured (2026-11-25): no difference at all, the
  // rebuilt world continues bit for bit
  std::printf("largest position gap after 250 steps: %.3g m; mean surge %.6g and %.6g N\n", largest_gap,
              -load_run / 250, -load_copy / 250);
  EXPECT_LT(largest_gap, 1e-6);
  EXPECT_NEAR(load_copy, load_run, 0.01 * std::abs(load_run));
}

}  // namespace
}  // namespace icedem

namespace icedem {
namespace {

using testing::advanced;
using testing::gap_after;
using testing::rebuilt;

TEST(WorldState, ARebuiltLatticeWorldContinuesAsTheOriginal) {
  // 0.20 m lattices in the structure's path, some of them woken from their stand-ins; the
  // joints' rows too are made in the canonical order (solver.order; the paper profile keeps
  // Bullet's, whose rebuilt world departs at once)
  const std::string path = std::string(ICEDEM_SOURCE_DIR) + "/scenarios/bench/large_breakable_short.toml";
  // without friction warm starting the rebuilt world continues bit for bit (measured over 5 s)
  {
    const Scene scene = load_scene(path, {"solver.profile=converged", "solver.friction_warm_start=false"});
    State run = advanced(scene, 1800);
    State copy = rebuilt(scene, run);
    EXPECT_EQ(gap_after(scene, run, copy, 250), 0.0);
  }
  // with it (the default) a position differs in its last bit after 9 steps (measured
  // 2026-11-25, 1.7e-18 m; the cause is not found yet), and the chaotic pack grows that as it
  // grows any round-off: 0.1 m and 7 % of the mean load after 5 s. A resumed run is not
  // affected: it rebuilds from the checkpoint as the run that wrote it did
  const Scene scene = load_scene(path, {"solver.profile=converged"});  // the scenario has the paper's
  State run = advanced(scene, 1800);
  State copy = rebuilt(scene, run);
  EXPECT_LT(gap_after(scene, run, copy, 25), 1e-12);
}

}  // namespace
}  // namespace icedem
