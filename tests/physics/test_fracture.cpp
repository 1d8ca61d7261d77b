// Breakable floes in the real Bullet world (dem/fracture/fracture, dem/fracture/ice_lattice): joint feedback
// against hand statics (a cantilever under gravity), fragments that collide once broken
// apart, and the joint-load filter.
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

namespace {
// a two-element strip in air with a clamped root element: the root joint carries
// the free element's weight, m g L_e / 2 = 0.51 N m of bending (capacity 0.99 N m)
struct ClampedPair {
  Scene scene;
  State state;
  explicit ClampedPair(std::vector<std::string> set)
      : scene(bench([&] {
          set.insert(set.end(), {"ice.bending_strength=36.4e3", "solver.iterations=100", "fracture.cfm=0"});
          return set;
        }())),
        state(initial_state(scene, {strip(0.3, 0.15)})) {
    lift(*state.world);
    btRigidBody& root = *state.world->floes()[0].body;
    root.setMassProps(0, btVector3(0, 0, 0));
    root.updateInertiaTensor();
  }
  int breaks() const { return state.fracture.breaks_by_mode[static_cast<int>(FailureMode::kBending)]; }
};
}  // namespace

TEST(Breakable, FloeBecomesALatticeOfElementsAndJoints) {
  const Scene scene = bench();
  State state = initial_state(scene, {strip(0.6, 0.6)});
  EXPECT_EQ(state.world->floes().size(), 16u);   // 4 x 4 elements of 0.15 m
  EXPECT_EQ(state.world->joints().size(), 24u);  // 2 n (n - 1)
  // ice mass is unchanged by the lattice: 16 elements of rho L_e^2 h
  double mass = 0;
  for (const FloeBody& f : state.world->floes()) mass += f.shape->mass;
  EXPECT_NEAR(mass, 930.0 * 0.6 * 0.6 * 0.033, 1e-9);
}

TEST(Breakable, CantileverRootJointCarriesShearAndMoment) {
  // a 4 x 1 strip of 0.15 m elements with a fixed root element, in air (docs/model/validation_targets.md §3:
  // feedback shear exact, root moment 0.7 % low from the sag geometry in docs/model/bullet.md)
  const Scene scene = bench({"solver.iterations=200", "fracture.cfm=0"});
  State state = initial_state(scene, {strip(0.6, 0.15)});
  lift(*state.world);
  btRigidBody& root = *state.world->floes()[0].body;
  root.setMassProps(0, btVector3(0, 0, 0));  // the clamped root
  root.updateInertiaTensor();
  for (int i = 0; i < 50; ++i) step(scene, state);

  // the root joint: A = root element, B = the first free one
  const IceJoint& j = state.world->joints()[0];
  ASSERT_EQ(j.body_a, 0);
  const JointLoads l = joint_loads(*state.world, j);
  const double m = state.world->floes()[1].shape->mass, g = scene.water.gravity, Le = 0.15;
  // the root holds the three free elements: shear 3 m g; moment about the joint
  // midpoint m g Le (0.5 + 1.5 + 2.5). 1 %: the converged solve is exact up to the
  // tiny sag of the joints
  EXPECT_NEAR(std::abs(l.shear_vertical), 3 * m * g, 0.01 * 3 * m * g);
  EXPECT_NEAR(std::abs(l.bending_out_of_plane), 4.5 * m * g * Le, 0.01 * 4.5 * m * g * Le);
  EXPECT_NEAR(l.axial, 0.0, 0.01 * m * g);
}

TEST(Breakable, PiecesCollideOnceBrokenApart) {
  const Scene scene = bench();
  State state = initial_state(scene, {strip(0.3, 0.15)});  // two elements, one joint
  World& world = *state.world;
  auto manifold_between = [&] {
    btDispatcher& d = *world.dynamics().getDispatcher();
    for (int i = 0; i < d.getNumManifolds(); ++i) {
      const btPersistentManifold* m = d.getManifoldByIndexInternal(i);
      const bool a0 = m->getBody0() == world.floes()[0].body, a1 = m->getBody1() == world.floes()[0].body;
      const bool b0 = m->getBody0() == world.floes()[1].body, b1 = m->getBody1() == world.floes()[1].body;
      if ((a0 && b1) || (a1 && b0)) return true;
    }
    return false;
  };
  step(scene, state);
  EXPECT_FALSE(manifold_between());  // jointed neighbours do not collide
  EXPECT_EQ(world.floes()[0].fragment, world.floes()[1].fragment);
  break_joint(world, world.joints()[0]);
  EXPECT_NE(world.floes()[0].fragment, world.floes()[1].fragment);
  step(scene, state);
  EXPECT_TRUE(manifold_between());  // the two pieces now touch as separate bodies
  // breaking removes a joint, not ice: both elements are still simulated, mass unchanged
  double mass = 0;
  for (const FloeBody& f : world.floes()) {
    EXPECT_TRUE(f.body->isInWorld());
    mass += 1.0 / f.body->getInvMass();
  }
  EXPECT_NEAR(mass, 930.0 * 0.3 * 0.15 * 0.033, 1e-12);
}

TEST(Breakable, LoadFilterIgnoresAOneStepSpikeButNotASustainedOverload) {
  // a 20 N push on the free element adds 20 N x 0.075 m = 1.5 N m: twice the capacity
  const PointLoads pushed{{{1, Eigen::Vector3d(0, -20.0, 0)}}};
  {
    ClampedPair raw({});
    for (int i = 0; i < 50; ++i) step(raw.scene, raw.state);
    EXPECT_EQ(raw.breaks(), 0);  // the weight alone is half the capacity
    step(raw.scene, raw.state, &pushed);
    EXPECT_EQ(raw.breaks(), 1);  // unfiltered, one step over the capacity breaks it
  }
  ClampedPair filtered({"fracture.load_filter_time=0.2"});
  for (int i = 0; i < 50; ++i) step(filtered.scene, filtered.state);  // 5 time constants
  step(filtered.scene, filtered.state, &pushed);
  // the filter passes h / (tau + h) = 9 % of the spike: 0.51 + 0.14 N m < 0.99 N m
  for (int i = 0; i < 50; ++i) step(filtered.scene, filtered.state);
  EXPECT_EQ(filtered.breaks(), 0);
  // held, the same push breaks it once the filter has caught up: (0.99 - 0.51) / 1.5
  // = 32 % of the step, after -tau ln(1 - 0.32) / h, about 4 steps (give it 10)
  for (int i = 0; i < 10 && filtered.breaks() == 0; ++i) step(filtered.scene, filtered.state, &pushed);
  EXPECT_EQ(filtered.breaks(), 1);
}
