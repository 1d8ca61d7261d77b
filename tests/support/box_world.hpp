// A small Bullet world of boxes for the contact solver's tests: a floor, boxes,
// a kinematic plate, with Bullet's solver or icedem's (dem/world/contact_solver.hpp).
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "dem/contact/solver_settings.hpp"
#include "dem/world/crushing_contact.hpp"
#include "dem/input/solver_profile.hpp"

namespace icedem::testing {

// The solver settings these tests are written for: the paper profile's (Bullet's own sweeps:
// 10 of them, no tolerance, its warm start and row order) and, for a method other than the
// sweeps, a solve to solver.merit_tolerance alone: no tighter merit for islands with joints or
// on the structure, no breaking solve, no hand-over
inline SolverSettings test_solver_settings() {
  SolverSettings s = solver_settings("paper");
  s.merit_tolerance = s.joint_merit_tolerance = s.structure_merit_tolerance = 1e-6;
  s.breaking_merit_tolerance = s.breaking_check_tolerance = 0.0;
  s.method_iterations = 300;
  s.handover_method = "none";
  s.handover_iterations = 100;
  return s;
}

constexpr double kGravity = 9.81;
constexpr double kDt = 0.02;  // s, icedem's step

// friction of a pair: the floor's (or slope's) coefficient against a box, none between boxes
// (so that the plate's load is the floor friction alone)
inline btScalar pair_friction(const btCollisionObject* a, const btCollisionObject* b) {
  return a->getUserIndex() == 1 && b->getUserIndex() == 1 ? 0.0 : a->getFriction() * b->getFriction();
}

// A Bullet world with either Bullet's solver or icedem's, holding what it creates.
class Bench {
 public:
  explicit Bench(std::unique_ptr<btSequentialImpulseConstraintSolver> solver) : solver_(std::move(solver)) {
    world_ = std::make_unique<btDiscreteDynamicsWorld>(&dispatcher_, &broadphase_, solver_.get(), &config_);
    world_->setGravity(btVector3(0, -kGravity, 0));
    btContactSolverInfo& info = world_->getSolverInfo();
    info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
    info.m_splitImpulse = true;
    info.m_splitImpulsePenetrationThreshold = 0;  // as icedem (dem/world/world.cpp)
    previous_friction_ = gCalculateCombinedFrictionCallback;
    gCalculateCombinedFrictionCallback = &pair_friction;
  }
  ~Bench() {
    for (auto& b : bodies_) world_->removeRigidBody(b.get());
    gCalculateCombinedFrictionCallback = previous_friction_;
  }
  btDiscreteDynamicsWorld& world() { return *world_; }

  // a box; mass 0 and kinematic: moved by set_pose; mass 0 otherwise: fixed
  btRigidBody* box(const btVector3& half, const btTransform& pose, double mass, double friction, int kind,
                   bool kinematic = false) {
    auto shape = std::make_unique<btBoxShape>(half);
    shape->setMargin(0.001);
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    auto motion = std::make_unique<btDefaultMotionState>(pose);
    auto body = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(mass, motion.get(), shape.get(), inertia));
    body->setFriction(friction);
    body->setRestitution(0);
    body->setUserIndex(kind);
    body->setActivationState(DISABLE_DEACTIVATION);
    if (kinematic) body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    world_->addRigidBody(body.get());
    btRigidBody* raw = body.get();
    shapes_.push_back(std::move(shape));
    motions_.push_back(std::move(motion));
    bodies_.push_back(std::move(body));
    return raw;
  }

 private:
  btDefaultCollisionConfiguration config_;
  btCollisionDispatcher dispatcher_{&config_};
  btDbvtBroadphase broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btMotionState>> motions_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  CalculateCombinedCallback previous_friction_;
};

inline btTransform at(double x, double y, double z) {
  btTransform t;
  t.setIdentity();
  t.setOrigin(btVector3(x, y, z));
  return t;
}

// force of every contact on `body` over the last step, N (the load cell's sum)
inline btVector3 contact_force_on(btDiscreteDynamicsWorld& world, const btCollisionObject* body) {
  btVector3 impulse(0, 0, 0);
  btDispatcher& d = *world.getDispatcher();
  for (int i = 0; i < d.getNumManifolds(); ++i) {
    const btPersistentManifold* m = d.getManifoldByIndexInternal(i);
    const double sign = m->getBody0() == body ? 1.0 : m->getBody1() == body ? -1.0 : 0.0;
    if (sign == 0.0) continue;
    for (int p = 0; p < m->getNumContacts(); ++p) {
      const btManifoldPoint& c = m->getContactPoint(p);
      impulse += sign * (c.m_normalWorldOnB * c.m_appliedImpulse + c.m_lateralFrictionDir1 * c.m_appliedImpulseLateral1 +
                         c.m_lateralFrictionDir2 * c.m_appliedImpulseLateral2);
    }
  }
  return impulse / kDt;
}

// the deepest overlap of any contact manifold in the world, m (crushing_contact.hpp's manifold_overlap of each)
inline double deepest_overlap(btDiscreteDynamicsWorld& world) {
  double depth = 0;
  btDispatcher& d = *world.getDispatcher();
  for (int m = 0; m < d.getNumManifolds(); ++m)
    depth = std::max(depth, manifold_overlap(*d.getManifoldByIndexInternal(m)));
  return depth;
}

}  // namespace icedem::testing
