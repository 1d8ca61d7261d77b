#include "dem/validation.hpp"

#include <array>
#include <cmath>

#include <btBulletDynamicsCommon.h>

#include "dem/constants.hpp"
#include "dem/fracture.hpp"
#include "dem/joint_loads.hpp"

namespace icedem {

double finite_plate_factor(double a_over_lc) {
  // docs/model/validation_targets.md §2: exact free-edge circular plate, w0 / w0_inf against a / l_c
  static const std::array<std::array<double, 2>, 10> table{{{1, 2.70}, {1.5, 1.46}, {2, 1.165}, {2.5, 1.106},
                                                            {3, 1.088}, {3.5, 1.064}, {4, 1.038}, {5, 1.008},
                                                            {6, 1.001}, {8, 1.000}}};
  if (a_over_lc <= table.front()[0]) return table.front()[1];
  if (a_over_lc >= table.back()[0]) return 1.0;
  for (std::size_t i = 1; i < table.size(); ++i) {
    if (a_over_lc <= table[i][0]) {
      const double s = (a_over_lc - table[i - 1][0]) / (table[i][0] - table[i - 1][0]);
      return table[i - 1][1] + s * (table[i][1] - table[i - 1][1]);
    }
  }
  return 1.0;
}

double plate_finite_factor(const Scene& s) {
  // the plate's equal-area radius over the characteristic length
  return finite_plate_factor(s.validation.plate_size / std::sqrt(kPi) / s.fracture.characteristic_length);
}

double hertz_plate_compliance(const Scene& s) {
  return 1.0 / (8.0 * std::sqrt(s.ice.flexural_rigidity * s.water.density * s.water.gravity));
}

double modulus_from_compliance(const Scene& s, double compliance, double factor) {
  const double h = s.ice.thickness, nu = s.ice.poisson_ratio;
  return 3 * (1 - nu * nu) * factor * factor / (16 * s.water.density * s.water.gravity * h * h * h * compliance * compliance);
}

// A kinematic body pinned to the beam's tip element by a ball joint, moved down at
// validation.tip_speed: displacement control, with the push force from the joint's
// feedback. It has no contact response and collides with nothing.
struct Validation::Pusher {
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

Validation::~Validation() = default;

namespace {
// kPa, the bending stress of the beam's root joint from its feedback: 6 M / (L_e T_e^2)
double root_stress(const Scene& scene, const State& state) {
  const double Le = scene.fracture.element_size, h = scene.ice.thickness;
  const JointLoads root = joint_loads(*state.world, state.world->joints().front());
  return 6 * std::abs(root.bending_out_of_plane) / (Le * h * h) / 1e3;
}
}  // namespace

Validation::Validation(const Scene& scene, State& state) : kind_(scene.validation.kind) {
  if (kind_ == ValidationCase::kCantilever && scene.validation.tip_speed > 0) {
    // the paper's test: the beam floats at its draft, its root element clamped there
    std::vector<FloeBody>& bodies = state.world->floes();
    for (FloeBody& f : bodies) x0_.push_back(f.body->getCenterOfMassPosition().x());
    element_mass_ = bodies.front().shape->mass;
    bodies.front().body->setMassProps(0, btVector3(0, 0, 0));
    bodies.front().body->updateInertiaTensor();
    for (FloeBody& f : bodies) f.body->activate(true);
    pusher_ = std::make_unique<Pusher>(state.world->dynamics(), *bodies.back().body, joint_sweeps(scene));
    pusher_->move_to(scene.validation.tip_speed * scene.time.dt);
    return;
  }
  if (kind_ == ValidationCase::kCantilever) {
    // the beam 1 m up in the air, its root element clamped (zero inverse mass)
    std::vector<FloeBody>& bodies = state.world->floes();
    for (FloeBody& f : bodies) {
      btTransform t = f.body->getWorldTransform();
      t.getOrigin() += btVector3(0, 1.0, 0);
      f.body->setWorldTransform(t);
      x0_.push_back(t.getOrigin().x());
    }
    element_mass_ = bodies.front().shape->mass;
    bodies.front().body->setMassProps(0, btVector3(0, 0, 0));
    bodies.front().body->updateInertiaTensor();
    after_step(scene, state);  // the weight supports from the first step on
    return;
  }
  if (kind_ != ValidationCase::kPlateDeflection) return;
  // the element(s) at the plate centre: one for an odd count across, four for even
  const std::vector<FloeBody>& bodies = state.world->floes();
  btVector3 centre(0, 0, 0);
  for (const FloeBody& f : bodies) centre += f.body->getCenterOfMassPosition();
  centre /= static_cast<double>(bodies.size());
  const double reach = 0.51 * scene.fracture.element_size;
  for (int i = 0; i < static_cast<int>(bodies.size()); ++i) {
    const btVector3 p = bodies[i].body->getCenterOfMassPosition();
    if (std::abs(p.x() - centre.x()) < reach + 1e-9 && std::abs(p.z() - centre.z()) < reach + 1e-9) {
      centre_.push_back(i);
      y0_ += p.y();
    }
  }
  y0_ /= static_cast<double>(centre_.size());
  for (int i : centre_)
    state.point_loads.emplace_back(i, Eigen::Vector3d(0, -scene.validation.load / centre_.size(), 0));
}

void Validation::note_first_break(const State& state, double tip_load) {
  if (broken_ || state.fracture_events.empty()) return;
  broken_ = true;
  first_break_ = state.fracture_events.front();
  load_at_break_ = tip_load;
}

void Validation::after_step(const Scene& scene, State& state) {
  if (kind_ == ValidationCase::kCantilever && pusher_) {
    const double push = pusher_->push();
    note_first_break(state, push);  // the peak: the force of the step in which it broke
    history_time_.push_back(state.time);
    history_load_.push_back(push);
    history_depth_.push_back(pusher_->start.y() - state.world->floes().back().body->getCenterOfMassPosition().y());
    if (!broken_) last_root_stress_ = root_stress(scene, state);
    history_root_stress_.push_back(broken_ ? 0.0 : last_root_stress_);
    pusher_->move_to(scene.validation.tip_speed * (state.time + scene.time.dt));
    return;
  }
  if (kind_ == ValidationCase::kCantilever) {
    note_first_break(state, tip_load_);
    if (!broken_) {
      // the root joint's bending stress as the model sees it, beside the applied load
      last_root_stress_ = root_stress(scene, state);
      history_time_.push_back(state.time);
      history_load_.push_back(tip_load_);
      history_root_stress_.push_back(last_root_stress_);
    }
    // the tip load of the next step grows linearly (quasi-static: slow against the beam's response)
    tip_load_ = broken_ ? 0.0 : scene.validation.load_rate * state.time;
    // each free element's weight is carried by an upward force, as buoyancy carries a
    // floating beam (the P_b of eq. 6), so the tip load alone bends the beam
    state.point_loads.clear();
    for (int i = 1; i < static_cast<int>(x0_.size()); ++i)
      state.point_loads.emplace_back(i, Eigen::Vector3d(0, element_mass_ * scene.water.gravity, 0));
    state.point_loads.emplace_back(static_cast<int>(x0_.size()) - 1, Eigen::Vector3d(0, -tip_load_, 0));
    return;
  }
  if (centre_.empty()) return;
  // measure over the second half of the run, after the plate has settled
  if (state.time < scene.time.duration / 2) return;
  double y = 0;
  for (int i : centre_) y += state.world->floes()[i].body->getCenterOfMassPosition().y();
  sum_ += y0_ - y / centre_.size();
  ++samples_;
}

nlohmann::json Validation::result(const Scene& scene) const {
  if (kind_ == ValidationCase::kPlateDeflection) return plate_result(scene);
  if (kind_ == ValidationCase::kCantilever) return cantilever_result(scene);
  return nullptr;
}

nlohmann::json Validation::cantilever_result(const Scene& scene) const {
  nlohmann::json j;
  j["case"] = "cantilever";
  j["metric"] = "bending stress at failure, kPa";
  j["reference"] = scene.ice.bending_strength / 1e3;
  j["tolerance"] = scene.validation.tolerance;
  if (!broken_) {
    j["value"] = nullptr;
    j["rel_error"] = nullptr;
    j["passed"] = false;
    j["note"] = "the beam did not break within time.duration";
    return j;
  }
  // joint k joins elements k and k+1 of the beam; its midpoint is half an element past k
  const int k = first_break_.joint;
  const double Le = scene.fracture.element_size, h = scene.ice.thickness;
  const double x_joint = x0_[k] + Le / 2;
  const double lever = x0_.back() - x_joint;  // m, joint to the load point (the tip element's centre)
  // eq. 6, sigma' = 6 (P_c - P_b) l / (L_e T_e^2). In air the weight is balanced, so
  // P_b = 0; floating, P_b is the fragment's buoyancy: the mean push 0.5-1.5 s after the
  // break, when the fragment hangs on the pusher alone (the paper's Fig. 7a)
  double buoyancy = 0;
  if (pusher_) {
    int n = 0;
    for (std::size_t i = 0; i < history_time_.size(); ++i) {
      const double after = history_time_[i] - first_break_.time;
      if (after >= 0.5 && after <= 1.5) {
        buoyancy += history_load_[i];
        ++n;
      }
    }
    if (n == 0) {
      j["value"] = nullptr;
      j["rel_error"] = nullptr;
      j["passed"] = false;
      j["note"] = "the run ended less than 0.5 s after the break: no fragment buoyancy P_b";
      return j;
    }
    buoyancy /= n;
  }
  const double sigma = 6 * (load_at_break_ - buoyancy) * lever / (Le * h * h);
  const double rel_error = (sigma - scene.ice.bending_strength) / scene.ice.bending_strength;
  j["value"] = sigma / 1e3;
  j["rel_error"] = rel_error;
  j["failure_mode"] = failure_mode_name(static_cast<FailureMode>(first_break_.mode));
  j["failed_joint"] = k;
  j["at_root"] = k == 0;
  j["load_at_failure_N"] = load_at_break_;
  j["time_of_failure_s"] = first_break_.time;
  j["lever_m"] = lever;
  j["fragment_buoyancy_N"] = buoyancy;
  j["root_joint_stress_at_failure_kPa"] = last_root_stress_;
  j["floating"] = static_cast<bool>(pusher_);
  j["history"] = {{"time_s", history_time_}, {"tip_load_N", history_load_},
                  {"root_joint_stress_kPa", history_root_stress_}};
  if (pusher_) j["history"]["tip_depth_m"] = history_depth_;
  j["passed"] = std::abs(rel_error) <= scene.validation.tolerance && k == 0 &&
                first_break_.mode == static_cast<int>(FailureMode::kBending);
  return j;
}

nlohmann::json Validation::plate_result(const Scene& scene) const {
  if (centre_.empty() || samples_ == 0) return nullptr;
  const double compliance = sum_ / samples_ / scene.validation.load;  // m/N
  const double factor = plate_finite_factor(scene);
  const double reference = hertz_plate_compliance(scene) * factor;
  const double rel_error = (compliance - reference) / reference;
  nlohmann::json j;
  j["case"] = "plate_deflection";
  j["metric"] = "centre deflection per unit load, mm/N";
  j["value"] = compliance * 1e3;
  j["reference"] = reference * 1e3;
  j["rel_error"] = rel_error;
  j["tolerance"] = scene.validation.tolerance;
  j["passed"] = std::abs(rel_error) <= scene.validation.tolerance;
  j["infinite_plate_mm_per_N"] = hertz_plate_compliance(scene) * 1e3;
  j["finite_plate_factor"] = factor;
  j["elastic_modulus_MPa"] = modulus_from_compliance(scene, compliance, factor) / 1e6;
  j["elastic_modulus_target_MPa"] = scene.ice.elastic_modulus / 1e6;
  return j;
}

}  // namespace icedem
