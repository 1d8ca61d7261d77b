// What a broken floe was doing (dem/fracture/break_context).
#include <gtest/gtest.h>

#include <cmath>

#include "dem/fracture/break_context.hpp"
#include "dem/fracture/fracture.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/lattice_region.hpp"
#include "dem/input/scenario.hpp"
#include "dem/run/simulation.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/validation/calibration.hpp"
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
  ASSERT_EQ(state.fracture.breaks_by_mode[static_cast<int>(FailureMode::kBending)], 0);
  scene.ice.bending_strength = 30e3;
  step(scene, state);
  ASSERT_EQ(state.fracture.events.size(), 1u);
  const FractureEvent& e = state.fracture.events.front();
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
  EXPECT_EQ(state.fracture.breaks_by_mechanism[static_cast<int>(BreakMechanism::kInPack)], 1);
}

// Scenes with the structure, where what the floe was doing is known by construction
// (issue: the mechanism classifier tested on constructed scenes). A 0.6 m floe A of
// 4 x 4 elements of 0.15 m floats in front of the cone; the channel's end wall (rigid
// mother ice) 1 cm behind it holds it, as the pack ahead holds a floe in the paper's runs,
// so the cone's push bends it instead of pushing it away. The ice's bending strength is
// lowered once the scene has settled, so that the break comes within a second of contact:
// the classifier reads only the contacts, the joint's depth and whether the floe touches
// the structure, none of which depends on the strength.
namespace {

constexpr double kFloeA = 10.0;  // m, x of floe A's centre; its near edge is at 9.7
constexpr double kConeWaterlineRadius = 0.614;  // m, the default hull (Table 2)

// The cone `gap` m from floe A's near edge, towed at `speed` towards it; the end wall 1 cm
// behind A. Joints unbreakable until the test lowers the strength.
Scene cone_scene(double gap, double speed) {
  std::vector<std::string> keys(kUnbreakable.begin(), kUnbreakable.end());
  keys.push_back("structure.speed=" + std::to_string(speed));
  keys.push_back("structure.start_x=" + std::to_string(kFloeA - 0.3 - kConeWaterlineRadius - gap));
  keys.push_back("channel.start_x=6");
  keys.push_back("channel.length=" + std::to_string(kFloeA + 0.31 - 6.0));
  return bench_scene(keys);
}

// Floe A alone, or with a square floe B of side `b_side` laid on its centre (rafted: one
// thickness plus 1 mm above A, so it lands on A): B's weight sinks A under the waterline.
State floe_a(const Scene& scene, double b_side) {
  std::vector<Floe> floes{square_floe(kFloeA, 0.0, 0.6)};
  if (b_side > 0) floes.push_back(square_floe(kFloeA, 3.0, b_side));  // placed apart, moved below
  State state = initial_state(scene, floes);
  for (FloeBody& f : state.world->floes()) {
    if (f.floe_id != 1) continue;
    btTransform t = f.body->getWorldTransform();
    t.getOrigin() += btVector3(0, scene.ice.thickness + 0.001, -3.0);
    f.body->setWorldTransform(t);
  }
  return state;
}

// Settle the scene for `settle` s with the joints unbreakable, lower the bending strength
// to `strength`, then step until floe A (layout floe 0) breaks, at most `within` s: the
// events of A's first break step (none, and a failure, if anything broke while settling).
std::vector<FractureEvent> first_breaks_of_a(Scene& scene, State& state, double settle, double strength,
                                             double within) {
  for (long i = 0; i < std::lround(settle / scene.time.dt); ++i) step(scene, state);
  if (!state.fracture.events.empty()) {
    ADD_FAILURE() << "a joint broke while the scene settled";
    return {};
  }
  scene.ice.bending_strength = strength;
  for (int i = 0; i < static_cast<int>(within / scene.time.dt); ++i) {
    step(scene, state);
    std::vector<FractureEvent> of_a;
    for (const FractureEvent& e : state.fracture.events)
      if (e.floe == 0) of_a.push_back(e);
    if (!of_a.empty()) return of_a;
  }
  return {};
}

}  // namespace

TEST(BreakMechanismScene, AFloeBentDownTheSlopeAloneBreaksOnTheSlope) {
  // A alone: the cone arrives at 0.7 s and pushes its edge down the 45 degree slope while
  // the wall holds it. Every joint that fails in the break step is on the slope: A touches
  // the structure, and no other floe is there to press it (press exactly 0).
  Scene scene = cone_scene(0.05, 0.07);
  State state = floe_a(scene, 0.0);
  // 1 s: settled, the cone on A's edge
  const std::vector<FractureEvent> breaks = first_breaks_of_a(scene, state, 1.0, 10e3, 5.0);
  ASSERT_FALSE(breaks.empty()) << "A did not break within 5 s";
  for (const FractureEvent& e : breaks) {
    EXPECT_EQ(e.mechanism, static_cast<int>(BreakMechanism::kOnSlope)) << "joint " << e.joint;
    EXPECT_EQ(e.touching_structure, 1) << "joint " << e.joint;
    EXPECT_GT(e.structure_force, kPressingForce) << "joint " << e.joint;
    EXPECT_EQ(e.press_down + e.press_toward, 0.0) << "joint " << e.joint;
  }
}

TEST(BreakMechanismScene, AFloeUnderAnotherBrokenAgainstTheConeIsPressedUnder) {
  // B (0.3 m) rafted on A's centre sinks A under the waterline (A's mid-plane about 38 mm
  // deep, more than the 33 mm thickness); the cone then pushes A's edge down the slope,
  // with B on top pressing it: A's breaks are pressed under. Several joints fail in one
  // step; each must carry the same floe context (the contacts are read before any joint
  // of the step is broken).
  Scene scene = cone_scene(0.05, 0.07);
  State state = floe_a(scene, 0.3);
  const std::vector<FractureEvent> breaks = first_breaks_of_a(scene, state, 1.0, 10e3, 5.0);
  ASSERT_FALSE(breaks.empty()) << "A did not break within 5 s";
  for (const FractureEvent& e : breaks) {
    EXPECT_EQ(e.mechanism, static_cast<int>(BreakMechanism::kPressedUnder)) << "joint " << e.joint;
    EXPECT_EQ(e.touching_structure, 1) << "joint " << e.joint;
    EXPECT_GE(e.depth, scene.ice.thickness) << "joint " << e.joint;
    EXPECT_GT(e.press_down + e.press_toward, kPressingForce) << "joint " << e.joint;
  }
}

TEST(BreakMechanismScene, AFloeSunkUnderAnotherAwayFromTheConeBreaksInTheRubble) {
  // The same stack with the structure parked 5 m away. At rest, A is fully submerged and
  // B floats with part of its thickness above water: A's buoyancy minus its weight holds
  // B's weight minus B's buoyancy, so A's top is d = (m_A + m_B - rho_w V_A) / (rho_w
  // A_B) deep and its mid-plane d + h/2 (38.0 mm); B presses A with that net force
  // (8.16 N). Then the strength is lowered until B's load breaks A: in the rubble (not
  // touching, submerged), with the depth within 2 mm of the hydrostatic one (the lattice
  // bends under B) and the press within 2 % of B's net weight (the contact solve's merit),
  // none of it towards the structure. B's edges lie on A's element edges, so many of
  // its contacts are on side faces, with friction pushing some elements up and others
  // down: only the net force equals B's net weight (the per-point downward parts summed
  // to 11.3 N, which is why the press is a net force).
  Scene scene = cone_scene(5.0, 0.0);
  State state = floe_a(scene, 0.3);
  const double h = scene.ice.thickness, rho_i = scene.ice.density, rho_w = scene.water.density;
  const double area_a = 0.36, area_b = 0.09;  // m^2
  const double top = ((area_a + area_b) * h * rho_i - rho_w * area_a * h) / (rho_w * area_b);  // m
  const double mid_plane = top + h / 2;
  const double press = scene.water.gravity * (rho_i * area_b * h - rho_w * area_b * top);  // N
  // 5 s: the stack at rest
  const std::vector<FractureEvent> breaks = first_breaks_of_a(scene, state, 5.0, 1.2e3, 2.0);
  ASSERT_FALSE(breaks.empty()) << "A did not break within 2 s";
  for (const FractureEvent& e : breaks) {
    EXPECT_EQ(e.mechanism, static_cast<int>(BreakMechanism::kInRubble)) << "joint " << e.joint;
    EXPECT_EQ(e.touching_structure, 0) << "joint " << e.joint;
    EXPECT_NEAR(e.depth, mid_plane, 0.002) << "joint " << e.joint;
    EXPECT_NEAR(e.press_down, press, 0.02 * press) << "joint " << e.joint;
    EXPECT_LT(e.press_toward, 0.02 * press) << "joint " << e.joint;
  }
}
