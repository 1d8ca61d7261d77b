// Breakable floes as one rigid body away from the structure (dem/fracture/lattice_region).
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

TEST(LatticeRegion, AFarFloeIsOneRigidBodyAndItsElementsFollowIt) {
  // structure parked at x = -50, floe at x = 10: far outside a 1 m lattice region
  const Scene scene = bench({"fracture.lattice_radius=1.0"});
  State state = initial_state(scene, {strip(0.6, 0.6)});
  World& world = *state.world;
  ASSERT_EQ(world.lattices().size(), 1u);
  const DormantLattice& d = world.lattices()[0];
  EXPECT_EQ(d.elements, 16);
  // in the Bullet world: the stand-in, no element, no joint
  EXPECT_TRUE(world.floes()[d.stand_in].body->isInWorld());
  for (int i = 0; i < d.elements; ++i) EXPECT_FALSE(world.floes()[d.first_element + i].body->isInWorld());
  EXPECT_EQ(world.dynamics().getNumConstraints(), 0);
  // the stand-in weighs what its elements weigh
  double mass = 0;
  for (int i = 0; i < d.elements; ++i) mass += world.floes()[d.first_element + i].shape->mass;
  EXPECT_NEAR(world.floes()[d.stand_in].shape->mass, mass, 1e-12);

  btRigidBody& whole = *world.floes()[d.stand_in].body;
  whole.setLinearVelocity(btVector3(0.1, 0, 0.05));
  whole.setAngularVelocity(btVector3(0, 0.2, 0));
  for (int i = 0; i < 10; ++i) step(scene, state);
  EXPECT_FALSE(d.replaced);
  // an element's output pose is its place in the moved and turned stand-in
  const FloeBody& corner = world.floes()[d.first_element];
  const Eigen::Isometry3d expected = body_pose(whole) * to_eigen(d.offsets[0]);
  EXPECT_LT((output_pose(world, corner).translation() - expected.translation()).norm(), 1e-12);
  EXPECT_TRUE(output_awake(world, corner));
  EXPECT_GT((output_pose(world, corner).translation() - to_eigen(d.offsets[0]).translation()).norm(), 5.0);
}

TEST(LatticeRegion, TheLatticeTakesOverTheStandInsMotionWhenTheStructureComesNear) {
  // floe centred at x = 10 (half-diagonal 0.42 m); the structure axis at x = 8.5: the floe's
  // nearest possible point is 1.08 m away, so a 1.2 m region reaches it, a 1.0 m one does not
  for (const double radius : {1.0, 1.2}) {
    const Scene scene = bench({"fracture.lattice_radius=" + std::to_string(radius), "structure.start_x=8.5"});
    State state = initial_state(scene, {strip(0.6, 0.6)});
    World& world = *state.world;
    const DormantLattice& d = world.lattices()[0];
    btRigidBody& whole = *world.floes()[d.stand_in].body;
    const btVector3 v(0.1, 0, 0.05), w(0, 0.2, 0);
    whole.setLinearVelocity(v);
    whole.setAngularVelocity(w);
    const btTransform T = whole.getCenterOfMassTransform();
    update_lattice_region(scene, state.structure_position, *state.world, state.fracture);
    EXPECT_EQ(d.replaced, radius > 1.1) << radius;
    if (!d.replaced) continue;
    EXPECT_FALSE(whole.isInWorld());
    EXPECT_EQ(world.dynamics().getNumConstraints(), 24);
    for (int i = 0; i < d.elements; ++i) {
      const btRigidBody& e = *world.floes()[d.first_element + i].body;
      EXPECT_TRUE(e.isInWorld());
      EXPECT_TRUE(e.isActive());
      // each element moves as the point of the rigid stand-in it sits at
      const btVector3 r = e.getCenterOfMassPosition() - T.getOrigin();
      EXPECT_LT((e.getLinearVelocity() - (v + w.cross(r))).length(), 1e-12);
      EXPECT_LT((e.getCenterOfMassPosition() - T * d.offsets[i].getOrigin()).length(), 1e-12);
    }
    // and carries on without a jolt: the mean element velocity after a step is within
    // the water's drag and damping of the stand-in's (1 cm/s)
    step(scene, state);
    btVector3 mean(0, 0, 0);
    for (int i = 0; i < d.elements; ++i) mean += world.floes()[d.first_element + i].body->getLinearVelocity();
    mean /= d.elements;
    EXPECT_LT((mean - v).length(), 0.01);
    EXPECT_EQ(state.fracture.breaks_by_mode[static_cast<int>(FailureMode::kBending)], 0);
  }
}

TEST(LatticeRegion, AnIntactLatticeThatLeavesTheRegionIsOneBodyAgainABrokenOneStays) {
  // the structure axis at x = 11.5 (its waterline edge at 10.89 m), the floe at x = 10 (edge at
  // 10.3 m): the floe's nearest point is 1.08 m away, inside a 1.2 m region. The structure then
  // moves off at 0.5 m/s: past 1.2 + 0.5 m after about 1.3 s
  const Scene scene = bench({"fracture.lattice_radius=1.2", "structure.start_x=11.5", "structure.speed=0.5"});
  State state = initial_state(scene, {strip(0.6, 0.6)});
  World& world = *state.world;
  DormantLattice& d = world.lattices()[0];
  update_lattice_region(scene, state.structure_position, *state.world, state.fracture);
  ASSERT_TRUE(d.replaced);
  // the lattice drifts and turns slowly as one piece
  const btVector3 v(-0.05, 0, 0.02), w(0, 0.1, 0);
  btVector3 centre(0, 0, 0);
  for (int i = 0; i < d.elements; ++i) centre += world.floes()[d.first_element + i].body->getCenterOfMassPosition();
  centre /= d.elements;
  for (int i = 0; i < d.elements; ++i) {
    btRigidBody& e = *world.floes()[d.first_element + i].body;
    e.setLinearVelocity(v + w.cross(e.getCenterOfMassPosition() - centre));
    e.setAngularVelocity(w);
  }
  std::vector<Eigen::Vector3d> before(d.elements);
  for (int i = 0; i < 150 && d.replaced; ++i) {
    for (int k = 0; k < d.elements; ++k) before[k] = body_pose(*world.floes()[d.first_element + k].body).translation();
    step(scene, state);
  }
  ASSERT_FALSE(d.replaced);
  const btRigidBody& whole = *world.floes()[d.stand_in].body;
  EXPECT_TRUE(whole.isInWorld());
  EXPECT_EQ(world.dynamics().getNumConstraints(), 0);
  // the stand-in took over where the elements were: each element's output pose is within
  // one step's motion (under 2 mm at these speeds) of its place before that step
  for (int k = 0; k < d.elements; ++k) {
    EXPECT_FALSE(world.floes()[d.first_element + k].body->isInWorld());
    EXPECT_LT((output_pose(world, world.floes()[d.first_element + k]).translation() - before[k]).norm(), 0.002);
  }
  // with the elements' mean motion (water drag has slowed it, but not reversed it)
  EXPECT_LT(whole.getLinearVelocity().x(), 0.0);
  EXPECT_GT(whole.getAngularVelocity().y(), 0.0);

  // a broken lattice stays a lattice
  Scene near = scene;
  State s2 = initial_state(near, {strip(0.6, 0.6)});
  DormantLattice& d2 = s2.world->lattices()[0];
  update_lattice_region(near, s2.structure_position, *s2.world, s2.fracture);
  ASSERT_TRUE(d2.replaced);
  break_joint(*s2.world, s2.world->joints()[0]);
  EXPECT_TRUE(d2.broken);
  EXPECT_FALSE(make_dormant(*s2.world, d2));
  EXPECT_TRUE(d2.replaced);
}

TEST(LatticeRegion, AHexagonalLatticeThatLeavesTheRegionIsOneBodyAgainWithItsMomentum) {
  // hexagons cut at the outline are of unequal masses: the stand-in takes the rigid motion of
  // the elements' momentum, at the centre their poses put it (a plain mean of the elements'
  // centres and velocities would be off by the cut elements' share). Tolerances: round-off.
  const Scene scene =
      bench({"fracture.lattice_radius=1.2", "structure.start_x=11.5", "fracture.element_shape=\"hexagon\""});
  State state = initial_state(scene, {strip(0.6, 0.6)});
  World& world = *state.world;
  DormantLattice& d = world.lattices()[0];
  ASSERT_FALSE(d.equal_elements);
  btRigidBody& whole = *world.floes()[d.stand_in].body;
  const btTransform T = whole.getCenterOfMassTransform();
  update_lattice_region(scene, state.structure_position, world, state.fracture);
  ASSERT_TRUE(d.replaced);
  // unequal elements (the point of the test)
  double lightest = 1e9, heaviest = 0;
  for (int i = 0; i < d.elements; ++i) {
    const double m = 1.0 / world.floes()[d.first_element + i].body->getInvMass();
    lightest = std::min(lightest, m), heaviest = std::max(heaviest, m);
  }
  ASSERT_LT(lightest, 0.8 * heaviest);
  EXPECT_LT((lattice_centre(world, d) - T.getOrigin()).length(), 1e-12);

  // a rigid motion about a point off the centre: the elements' momentum is the stand-in's
  const btVector3 v(-0.05, 0, 0.02), w(0, 0.1, 0), pivot = T.getOrigin() + btVector3(0.3, 0, -0.2);
  btVector3 momentum(0, 0, 0);
  double mass = 0;
  for (int i = 0; i < d.elements; ++i) {
    btRigidBody& e = *world.floes()[d.first_element + i].body;
    e.setLinearVelocity(v + w.cross(e.getCenterOfMassPosition() - pivot));
    e.setAngularVelocity(w);
    momentum += e.getLinearVelocity() / e.getInvMass();
    mass += 1.0 / e.getInvMass();
  }
  ASSERT_TRUE(make_dormant(world, d));
  EXPECT_FALSE(d.replaced);
  EXPECT_TRUE(whole.isInWorld());
  EXPECT_EQ(world.dynamics().getNumConstraints(), 0);
  EXPECT_LT((whole.getCenterOfMassPosition() - T.getOrigin()).length(), 1e-12);
  EXPECT_LT((whole.getLinearVelocity() - (v + w.cross(T.getOrigin() - pivot))).length(), 1e-12);
  EXPECT_LT((whole.getAngularVelocity() - w).length(), 1e-12);
  EXPECT_LT((whole.getLinearVelocity() * mass - momentum).length(), 1e-12 * momentum.length());
  // the stand-in weighs what its elements weigh, so the momentum is the same
  EXPECT_NEAR(1.0 / whole.getInvMass(), mass, 1e-9 * mass);
  // and its elements' output poses are where the elements were
  for (int i = 0; i < d.elements; ++i) {
    const FloeBody& e = world.floes()[d.first_element + i];
    EXPECT_LT((output_pose(world, e).translation() - body_pose(*e.body).translation()).norm(), 1e-12);
  }
}
