// What a broken floe was doing (dem/break_context).
#include <gtest/gtest.h>

#include <cmath>

#include "dem/break_context.hpp"
#include "dem/calibration.hpp"
#include "dem/fracture.hpp"
#include "dem/ice_lattice.hpp"
#include "dem/initial_state.hpp"
#include "dem/lattice_region.hpp"
#include "dem/scenario.hpp"
#include "dem/simulation.hpp"
#include "dem/step.hpp"
#include "dem/validation/case.hpp"
#include "dem/validation/plate_theory.hpp"
#include "tests/physics/breakable_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

TEST(BreakContext, AFloeLyingOnAnElementPressesItDownAndTheBreakRecordsIt) {
  // the clamped pair in air, with a 0.15 m element-sized floe laid on the free
  // element's centre. Once it rests there, the root joint's strength drops to
  // sigma_b 30 kPa (capacity 0.82 N m): it holds the free element's own weight
  // (0.51 N m) but not that plus the floe's (6.7 N x 0.075 m = 0.50 N m). The break
  // must name the resting floe's weight as press_down and no contact with the
  // structure (parked 60 m away).
  const double h = 0.033;
  Scene scene = icedem::testing::bench_scene({"fracture.mode=on", "fracture.element_size=0.15",
                                              "ice.bending_strength=1e9", "ice.compressive_strength=1e9",
                                              "ice.shear_strength=1e9", "solver.iterations=100",
                                              "fracture.cfm=0"});
  State state = initial_state(scene, {strip(0.3, 0.15), icedem::testing::square_floe(10.075, 0.0, 0.15)});
  lift(*state.world);
  std::vector<FloeBody>& bodies = state.world->floes();
  ASSERT_EQ(bodies.size(), 3u);  // two elements of the strip, the floe on top
  btRigidBody& root = *bodies[0].body;
  root.setMassProps(0, btVector3(0, 0, 0));
  root.updateInertiaTensor();
  btRigidBody& top = *bodies[2].body;
  btTransform t = top.getWorldTransform();
  t.getOrigin() += btVector3(0, h + 0.001, 0);  // resting on the free element after a 1 mm drop
  top.setWorldTransform(t);
  const double weight = scene.ice.density * 0.15 * 0.15 * h * scene.water.gravity;  // N, the floe on top

  for (int i = 0; i < 50; ++i) step(scene, state);  // 1 s: landed and at rest
  ASSERT_EQ(state.breaks_by_mode[static_cast<int>(FailureMode::kBending)], 0);
  scene.ice.bending_strength = 30e3;
  step(scene, state);
  ASSERT_EQ(state.fracture_events.size(), 1u);
  const FractureEvent& e = state.fracture_events.front();
  EXPECT_EQ(e.mode, static_cast<int>(FailureMode::kBending));
  EXPECT_DOUBLE_EQ(e.ratio_bending, e.ratio);  // the criterion that fired is the largest ratio
  EXPECT_LT(e.ratio_compression, 0.01);        // strengths of 1e9 Pa: nothing near those criteria
  EXPECT_EQ(e.touching_structure, 0);
  EXPECT_EQ(e.structure_force, 0.0);
  EXPECT_EQ(e.mechanism, static_cast<int>(BreakMechanism::kInPack));  // not touching, above water
  EXPECT_NEAR(e.depth, -1.0, 0.05);  // lifted 1 m
  EXPECT_GT(e.distance, 50.0);
  // the contact force of the resting floe is its weight (2 %: the contact solve's residual)
  EXPECT_NEAR(e.press_down, weight, 0.02 * weight) << "weight " << weight;
  EXPECT_EQ(state.breaks_by_mechanism[static_cast<int>(BreakMechanism::kInPack)], 1);
}
