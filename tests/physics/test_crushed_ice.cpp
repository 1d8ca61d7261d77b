// The crushed ice of a crushing contact (dem/world/crushing_contact.hpp, CrushedIce): the overlap a
// contact reached while it crushed stays, and overlap it did not crush is pushed out by the position
// pass, as a rigid contact's is. Without the second, a piece pressed up under the downward cone by
// the rubble slid 4 cm into the hull at a hundredth of its bound and then went through it
// (docs/model/crushing.md, "The crushed ice").
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <btBulletDynamicsCommon.h>

#include "dem/world/contact_solver.hpp"
#include "dem/world/crushing_contact.hpp"
#include "dem/world/world.hpp"
#include "tests/support/box_world.hpp"

using icedem::ContactLaw;
using icedem::ContactSolver;
using icedem::CrushedIce;
using icedem::CrushingLaw;
using icedem::SolverSettings;
using namespace icedem::testing;

namespace {

constexpr double kThickness = 0.033;   // m
constexpr double kStrength = 145.6e3;  // Pa, the paper's compressive strength
constexpr double kSpeed = 0.07;        // m/s along the face's normal

}  // namespace

// A 0.3 m floe's corner driven at 0.07 m/s into a fixed 45-degree face of the structure crushes
// about 4 mm of it and stops (tests/physics/test_crushing_impact.cpp). At rest its contact bears
// nothing, below its bound: the crushed 4 mm stay over 25 steps (to 0.1 mm: not pushed out, which
// would make the contact elastic). Moved 5 mm further in by hand, as a sliding piece's other corner
// comes in, the overlap it did not crush is pushed out to the crushed depth within 50 steps (to
// 0.2 mm), and the floe gains no speed from it (the position pass moves, it does not push)
TEST(CrushedIce, OverlapTheContactDidNotCrushIsPushedOutTheCrushedStays) {
  SolverSettings s = test_solver_settings();
  s.method = "apgd";
  s.merit_tolerance = s.joint_merit_tolerance = s.structure_merit_tolerance = 1e-9;
  s.method_iterations = 20000;
  ContactLaw law;
  law.crushing = CrushingLaw{kStrength, 0.0, kThickness * kThickness};
  Bench bench(std::make_unique<ContactSolver>(s, law));
  bench.world().setGravity(btVector3(0, 0, 0));
  const double beta = M_PI / 4;
  const btVector3 n(-std::cos(beta), std::sin(beta), 0);  // the face's outward normal
  btTransform block = at(0, 0, 0);
  block.setRotation(btQuaternion(btVector3(0, 0, 1), beta));
  block.setOrigin(-n * 0.5);
  btRigidBody* face = bench.box({0.5, 0.5, 0.5}, block, 0.0, 0.0, icedem::kStructure);
  const double side = 0.3, mass = 930.0 * side * side * kThickness;
  btTransform pose = at(0, 0, 0);
  pose.setRotation(btQuaternion(btVector3(0, 1, 0), M_PI / 4));
  btRigidBody* floe = bench.box({side / 2, kThickness / 2, side / 2}, pose, mass, 0.0, icedem::kIce);
  floe->setMassProps(mass, btVector3(1e12, 1e12, 1e12));  // it cannot turn
  floe->updateInertiaTensor();
  pose.setOrigin(n * 1e-3 - btVector3(side / std::sqrt(2.0), -kThickness / 2, 0));  // its corner 1 mm off the face
  floe->setWorldTransform(pose);
  floe->getMotionState()->setWorldTransform(pose);
  floe->setLinearVelocity(-n * kSpeed);
  face->setFriction(0.0);
  floe->setFriction(0.0);

  for (int step = 0; step < 30; ++step) bench.world().stepSimulation(kDt, 0);
  ASSERT_LT(floe->getLinearVelocity().length(), 1e-3 * kSpeed) << "the floe has stopped";
  const double crushed = deepest_overlap(bench.world());
  ASSERT_GT(crushed, 2e-3);
  ASSERT_LT(crushed, 6e-3);
  for (int step = 0; step < 25; ++step) bench.world().stepSimulation(kDt, 0);
  EXPECT_NEAR(deepest_overlap(bench.world()), crushed, 1e-4) << "the crushed ice stays";

  btTransform deeper = floe->getWorldTransform();
  deeper.setOrigin(deeper.getOrigin() - n * 5e-3);
  floe->setWorldTransform(deeper);
  floe->getMotionState()->setWorldTransform(deeper);
  for (int step = 0; step < 50; ++step) bench.world().stepSimulation(kDt, 0);
  EXPECT_NEAR(deepest_overlap(bench.world()), crushed, 2e-4) << "the overlap not crushed is pushed out";
  EXPECT_LT(floe->getLinearVelocity().length(), 1e-3 * kSpeed) << "and the floe gets no speed from it";
}

// The rules of the crushed depth, on one manifold's deepest point: its overlap at first sight; the
// smaller of the two after a step below the bound; the larger after a step at it; a manifold Bullet
// made anew at the same address for two other bodies starts again; a remembered one (a checkpoint's)
// is what the next step starts from
TEST(CrushedIce, DepthGrowsOnlyWhileCrushing) {
  btCollisionObject a, b, c;
  btPersistentManifold manifold(&a, &b, 0, 0.02, 0.02);
  auto overlap = [&](double depth) {
    manifold.clearManifold();
    btManifoldPoint p(btVector3(0, 0, 0), btVector3(0, 0, 0), btVector3(0, 1, 0), -depth);
    manifold.addManifoldPoint(p);
  };
  CrushedIce ice;
  // the crushed depth of the step after one that ended `crushing`, the manifold's overlap now `depth`
  auto after = [&](bool crushing, double depth) {
    ice.set_crushing(manifold, crushing);
    ice.next_step();
    overlap(depth);
    return ice.depth(manifold);
  };
  ice.next_step();
  overlap(0.004);
  EXPECT_DOUBLE_EQ(ice.depth(manifold), 0.004) << "at first sight, the overlap";
  EXPECT_DOUBLE_EQ(after(false, 0.006), 0.004) << "below the bound it crushed nothing";
  EXPECT_DOUBLE_EQ(after(true, 0.008), 0.008) << "at the bound the overlap reached is crushed";
  EXPECT_DOUBLE_EQ(after(false, 0.003), 0.003) << "opened: the crushed ice has left the contact";
  ASSERT_NE(ice.remembered(&manifold), nullptr);
  EXPECT_FALSE(ice.remembered(&manifold)->crushing);

  btPersistentManifold other(&a, &c, 0, 0.02, 0.02);
  CrushedIce restored;
  restored.remember(&other, CrushedIce::Memory{&a, &c, 0.002, true});
  restored.next_step();
  other.addManifoldPoint(btManifoldPoint(btVector3(0, 0, 0), btVector3(0, 0, 0), btVector3(0, 1, 0), -0.005));
  EXPECT_DOUBLE_EQ(restored.depth(other), 0.005) << "a remembered crushing manifold grows to its overlap";

  CrushedIce reused;
  reused.remember(&manifold, CrushedIce::Memory{&a, &c, 0.001, false});  // another pair at this address
  reused.next_step();
  overlap(0.007);
  EXPECT_DOUBLE_EQ(reused.depth(manifold), 0.007) << "another pair's memory is not this manifold's";
}
