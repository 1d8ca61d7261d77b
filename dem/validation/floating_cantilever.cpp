// The floating cantilever, the paper's test (dem/validation/cantilever.hpp).
#include <btBulletDynamicsCommon.h>

#include "dem/validation/cantilever.hpp"

namespace icedem {

// A kinematic body pinned to the beam's tip element by a ball joint, moved down at
// validation.tip_speed: displacement control, with the push force from the joint's
// feedback. It has no contact response and collides with nothing.
struct FloatingCantilever::Pusher {
  DynamicsWorld* dynamics;
  btSphereShape shape{0.01};
  btDefaultMotionState motion;
  std::unique_ptr<btRigidBody> body;
  std::unique_ptr<btPoint2PointConstraint> pin;
  btJointFeedback feedback;
  btVector3 start;  // m, tip element centre at t = 0

  Pusher(DynamicsWorld& world, btRigidBody& tip, int iterations) : dynamics(&world) {
    start = tip.getCenterOfMassPosition();
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(start);
    motion.setWorldTransform(pose);
    body = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, &motion, &shape));
    body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT |
                            btCollisionObject::CF_NO_CONTACT_RESPONSE);
    body->setActivationState(DISABLE_DEACTIVATION);
    dynamics->addRigidBody(body.get(), 0, 0);  // no collision group: never a pair
    pin = std::make_unique<btPoint2PointConstraint>(tip, *body, btVector3(0, 0, 0), btVector3(0, 0, 0));
    pin->setOverrideNumSolverIterations(iterations);
    pin->setJointFeedback(&feedback);
    dynamics->addConstraint(pin.get(), true);
  }
  ~Pusher() {
    dynamics->removeConstraint(pin.get());
    dynamics->removeRigidBody(body.get());
  }
  // put the pusher `depth` m below the tip's start for the next step (Bullet moves a
  // kinematic body to its motion state's pose over the step)
  void move_to(double depth) {
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(start - btVector3(0, depth, 0));
    motion.setWorldTransform(pose);
  }
  // N, downward force the pusher puts on the tip in the last step
  double push() const { return -feedback.m_appliedForceBodyA.y(); }
};

FloatingCantilever::FloatingCantilever(const Scene& scene, State& state) {
  // the beam floats at its draft, its root element clamped there
  clamp_root(state);
  std::vector<FloeBody>& bodies = state.world->floes();
  for (FloeBody& f : bodies) f.body->activate(true);
  pusher_ = std::make_unique<Pusher>(state.world->dynamics(), *bodies.back().body, joint_sweeps(scene));
  pusher_->move_to(scene.validation.tip_speed * scene.time.dt);
}

// the pusher leaves the world (which outlives the case) before the world goes
FloatingCantilever::~FloatingCantilever() = default;

void FloatingCantilever::after_step(const Scene& scene, State& state) {
  const double push = pusher_->push();
  note_first_break(state, push);  // the peak: the force of the step in which it broke
  history_time_.push_back(state.time);
  history_load_.push_back(push);
  history_depth_.push_back(pusher_->start.y() - state.world->floes().back().body->getCenterOfMassPosition().y());
  if (!broken_) last_root_stress_ = root_stress(scene, state);
  history_root_stress_.push_back(broken_ ? 0.0 : last_root_stress_);
  pusher_->move_to(scene.validation.tip_speed * (state.time + scene.time.dt));
}

std::optional<double> FloatingCantilever::fragment_buoyancy() const {
  // the mean push 0.5-1.5 s after the break, when the fragment hangs on the pusher alone
  // (the paper's Fig. 7a)
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < history_time_.size(); ++i) {
    const double after = history_time_[i] - first_break_.time;
    if (after >= 0.5 && after <= 1.5) {
      sum += history_load_[i];
      ++n;
    }
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

}  // namespace icedem
