#include "dem/world.hpp"

#include <cmath>

#include <functional>

#include <Eigen/Eigenvalues>

#include "dem/cone_geometry.hpp"
#include "dem/constants.hpp"
#include "dem/element_lattice.hpp"

namespace icedem {
namespace {

// Coulomb friction of a contact pair. Bullet multiplies the two bodies'
// coefficients by default, which would make f_ii = 0.5 act as 0.25. Here each
// body carries its coefficient *against ice*: ice-ice contacts use f_ii (ice's
// own value), ice against the structure or a boundary uses that body's value.
btScalar combined_friction(const btCollisionObject* a, const btCollisionObject* b) {
  return a->getUserIndex() == kIce ? b->getFriction() : a->getFriction();
}

// restitution is zero for every body (paper, Table 3); max keeps it explicit
btScalar combined_restitution(const btCollisionObject* a, const btCollisionObject* b) {
  return std::max(a->getRestitution(), b->getRestitution());
}

// area moments of a polygon about its centroid: {A, Sxx = int x^2, Szz = int z^2, Sxz = int xz}
Eigen::Vector4d area_moments(const Polygon& p) {
  double a = 0, sxx = 0, szz = 0, sxz = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& u = p[i];
    const Eigen::Vector2d& v = p[(i + 1) % p.size()];
    const double c = u.x() * v.y() - v.x() * u.y();
    a += c / 2;
    sxx += c * (u.x() * u.x() + u.x() * v.x() + v.x() * v.x()) / 12;
    szz += c * (u.y() * u.y() + u.y() * v.y() + v.y() * v.y()) / 12;
    sxz += c * (u.x() * v.y() + 2 * u.x() * u.y() + 2 * v.x() * v.y() + v.x() * u.y()) / 24;
  }
  const double s = a < 0 ? -1.0 : 1.0;  // either vertex order
  return {s * a, s * sxx, s * szz, s * sxz};
}

// yaw that turns the outline frame into the principal frame of its area moments
double principal_yaw(const Polygon& outline) {
  const Eigen::Vector4d m = area_moments(outline);
  const double scale = m[1] + m[2];
  if (std::abs(m[3]) <= 1e-12 * scale && std::abs(m[1] - m[2]) <= 1e-12 * scale) return 0.0;
  Eigen::Matrix2d tensor;
  tensor << m[1], m[3], m[3], m[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(tensor);
  const Eigen::Vector2d e1 = eig.eigenvectors().col(1);  // the long axis becomes body x
  return std::atan2(-e1.y(), e1.x());  // body +x maps to (cos, -sin) under yaw (polygon.hpp)
}

// an axis-aligned rectangle centred at the origin: its half extents, else none
bool rectangle_half_extents(const Polygon& p, double& hx, double& hz) {
  if (p.size() != 4) return false;
  hx = std::abs(p[0].x());
  hz = std::abs(p[0].y());
  const double tol = 1e-9 * (hx + hz);
  for (const Eigen::Vector2d& v : p)
    if (std::abs(std::abs(v.x()) - hx) > tol || std::abs(std::abs(v.y()) - hz) > tol) return false;
  return hx > 0 && hz > 0;
}

}  // namespace

// Elements of one fragment of a breakable floe are held together by joints and
// must not collide with each other (diagonal neighbours would); pieces that
// have come apart collide like any two floes.
class FragmentFilter : public btOverlapFilterCallback {
 public:
  explicit FragmentFilter(const std::vector<FloeBody>& bodies) : bodies_(bodies) {}
  bool needBroadphaseCollision(btBroadphaseProxy* p0, btBroadphaseProxy* p1) const override {
    if (!(p0->m_collisionFilterGroup & p1->m_collisionFilterMask) ||
        !(p1->m_collisionFilterGroup & p0->m_collisionFilterMask))
      return false;
    const auto* a = static_cast<const btCollisionObject*>(p0->m_clientObject);
    const auto* b = static_cast<const btCollisionObject*>(p1->m_clientObject);
    if (a->getUserIndex() != kIce || b->getUserIndex() != kIce) return true;
    const FloeBody& fa = bodies_[a->getUserIndex2()];
    const FloeBody& fb = bodies_[b->getUserIndex2()];
    return !(fa.fragment >= 0 && fa.floe_id == fb.floe_id && fa.fragment == fb.fragment);
  }

 private:
  const std::vector<FloeBody>& bodies_;
};

World::World(const Scene& scene) : scene_(scene) {
  collision_config_ = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher_ = std::make_unique<btCollisionDispatcher>(collision_config_.get());
  if (scene.solver.broadphase == Broadphase::kSweepAndPrune) {
    // sweep and prune needs the world's bounds: the tank with a margin
    const ChannelSettings& c = scene.channel;
    const double x0 = std::min(scene.structure.start_x, c.start_x) - 10.0;
    const double x1 = c.start_x + c.length + 10.0;
    const double z = c.tank_width / 2 + 5.0;
    broadphase_ = std::make_unique<bt32BitAxisSweep3>(btVector3(x0, -c.tank_depth - 5.0, -z),
                                                     btVector3(x1, 10.0, z), 65536);
  } else {
    broadphase_ = std::make_unique<btDbvtBroadphase>();
  }
  ContactSolverSettings contact;
  contact.iterations = scene.solver.iterations;
  contact.tolerance = scene.solver.tolerance;
  contact.friction_warm_start = scene.solver.friction_warm_start;
  contact.order = scene.solver.order_from_structure ? SweepOrder::kFromStructure : SweepOrder::kBullet;
  contact.crushing_force = scene.ice.contact_crushing ? crushing_force(scene.ice) : 0.0;
  solver_ = std::make_unique<ContactSolver>(contact);
  dynamics_ = std::make_unique<DynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                              collision_config_.get());
  dynamics_->setGravity(btVector3(0, -scene.water.gravity, 0));
  // sleeping and frozen bodies do not move: only update the bounding boxes of awake ones
  dynamics_->setForceUpdateAllAabbs(false);

  fragment_filter_ = std::make_unique<FragmentFilter>(floes_);
  broadphase_->getOverlappingPairCache()->setOverlapFilterCallback(fragment_filter_.get());

  // sleeping islands from touching contacts (see contact_islands.hpp for why)
  if (scene.activation.islands == IslandMode::kContact) {
    island_manager_ = std::make_unique<ContactIslandManager>();
    dynamics_->replace_island_manager(island_manager_.get());
  }
  // Bullet hands every manifold of an awake body to the solver, empty ones too, and
  // the solver gives both bodies of a manifold a solver body. A body whose empty
  // manifold lands in another island's solve is then solved twice, and each solve
  // adds its applied forces again: a floe near (not touching) floes of other islands
  // got its water forces and weight several times per step, and one went unstable
  // in the paper grid (README, "Numerical stability"). With this flag Bullet skips
  // manifolds without contact points when it builds islands (and sorts pairs so
  // that the order is reproducible, which it already was here).
  dynamics_->getDispatchInfo().m_deterministicOverlappingPairs = true;

  btContactSolverInfo& info = dynamics_->getSolverInfo();
  info.m_numIterations = scene.solver.iterations;
  info.m_warmstartingFactor = scene.solver.warm_start;
  info.m_sor = scene.solver.sor;
  // with a tolerance, one solve per island instead of Bullet's batches of islands
  // (about 128 rows each), so that each island stops sweeping when it has converged;
  // without one, Bullet's batches, which the paper profile's results were made with
  // (the batching changes round-off, and so a chaotic run's path)
  if (scene.solver.tolerance > 0) info.m_minimumSolverBatchSize = 1;
  info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  info.m_restitution = 0;
  info.m_splitImpulse = scene.solver.split_impulse;
  // Bullet only splits penetrations deeper than 4 cm by default, i.e. never for
  // 33 mm ice; a zero threshold splits every penetrating contact
  info.m_splitImpulsePenetrationThreshold = 0;
  // Bullet 3 uses m_erp2 for every contact (split or not); m_erp is for joints
  info.m_erp2 = scene.solver.contact_erp;

  gCalculateCombinedFrictionCallback = &combined_friction;
  gCalculateCombinedRestitutionCallback = &combined_restitution;
  // a body sleeps after this long below its thresholds (a process-wide Bullet global)
  gDeactivationTime = scene.activation.time;
}

World::~World() {
  // joints and bodies out of the world before the world goes
  for (IceJoint& j : joints_)
    if (j.constraint) dynamics_->removeConstraint(j.constraint.get());
  for (auto& body : bodies_) dynamics_->removeRigidBody(body.get());
  broadphase_->getOverlappingPairCache()->setOverlapFilterCallback(nullptr);
}

void World::add_structure(std::unique_ptr<btCollisionShape> shape, const Eigen::Vector3d& position) {
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(position));
  auto motion = std::make_unique<btDefaultMotionState>(pose);
  btRigidBody::btRigidBodyConstructionInfo ci(0.0, motion.get(), shape.get());
  auto body = std::make_unique<btRigidBody>(ci);
  // kinematic: moved by us, infinite mass for the solver, never asleep
  body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  body->setActivationState(DISABLE_DEACTIVATION);
  body->setFriction(scene_.friction.ice_structure);
  body->setRestitution(0);
  body->setUserIndex(kStructure);
  dynamics_->addRigidBody(body.get());
  structure_ = body.get();
  solver_->set_structure(structure_);
  shapes_.push_back(std::move(shape));
  motion_states_.push_back(std::move(motion));
  bodies_.push_back(std::move(body));
}

void World::add_profile_structure() {
  auto compound = std::make_unique<btCompoundShape>();
  btTransform identity;
  identity.setIdentity();
  for (const auto& piece : hull_pieces(scene_.structure.profile, scene_.structure.segments)) {
    auto hull = std::make_unique<btConvexHullShape>();
    for (const Eigen::Vector3d& p : piece) hull->addPoint(to_bt(p), false);
    hull->recalcLocalAabb();
    hull->setMargin(kDefaultCollisionMargin);
    compound->addChildShape(identity, hull.get());
    shapes_.push_back(std::move(hull));
  }
  add_structure(std::move(compound),
                Eigen::Vector3d(scene_.structure.start_x, 0.0, scene_.structure.start_z));
}

btRigidBody* World::add_static_box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half,
                                   Material material) {
  auto shape = std::make_unique<btBoxShape>(to_bt(half));
  shape->setMargin(kDefaultCollisionMargin);
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(centre));
  btRigidBody::btRigidBodyConstructionInfo ci(0.0, nullptr, shape.get());
  ci.m_startWorldTransform = pose;
  auto body = std::make_unique<btRigidBody>(ci);
  body->setFriction(scene_.friction.ice_ice);  // mother ice is ice
  body->setRestitution(0);
  body->setUserIndex(material);
  dynamics_->addRigidBody(body.get());
  btRigidBody* raw = body.get();
  shapes_.push_back(std::move(shape));
  bodies_.push_back(std::move(body));
  return raw;
}

namespace {
constexpr double kTankWallTop = 0.5;  // m above the still-water line
}

Eigen::AlignedBox3d World::tank_box() const {
  const ChannelSettings& c = scene_.channel;
  const double x0 = std::min(scene_.structure.start_x, c.start_x) - 2.0;  // tank start, behind the carriage
  const double x1 = c.start_x + c.length + 1.0;                           // 1 m beyond the channel end
  return {Eigen::Vector3d(x0, -c.tank_depth, -c.tank_width / 2),
          Eigen::Vector3d(x1, kTankWallTop, c.tank_width / 2)};
}

void World::add_boundaries() {
  const ChannelSettings& c = scene_.channel;
  const double h = scene_.ice.thickness;
  const double draft = h * scene_.ice.density / scene_.water.density;
  const double y_ice = h / 2 - draft;  // centre of a floating sheet
  const Eigen::AlignedBox3d tank = tank_box();
  const double x0 = tank.min().x(), x1 = tank.max().x();
  const double x_end = c.start_x + c.length;
  const double side = (c.tank_width - c.width) / 2;  // mother ice left along each wall

  // mother ice along both sides of the channel: fixed sheets at the waterline
  if (side > 0)
    for (double sign : {-1.0, 1.0})
      add_static_box({(x0 + x1) / 2, y_ice, sign * (c.width / 2 + side / 2)},
                     {(x1 - x0) / 2, h / 2, side / 2}, kBoundary);
  // mother ice closing the far end of the channel
  if (c.end_wall) add_static_box({x_end + 0.5, y_ice, 0.0}, {0.5, h / 2, c.width / 2}, kBoundary);

  // tank walls, ends and floor (floes pushed under the ice must not fall out)
  const double wall = 0.1, top = kTankWallTop;
  const double ymid = (top - c.tank_depth) / 2, yhalf = (top + c.tank_depth) / 2;
  for (double sign : {-1.0, 1.0})
    add_static_box({(x0 + x1) / 2, ymid, sign * (c.tank_width / 2 + wall)},
                   {(x1 - x0) / 2 + 2 * wall, yhalf, wall}, kBoundary);
  add_static_box({x0 - wall, ymid, 0.0}, {wall, yhalf, c.tank_width / 2}, kBoundary);
  add_static_box({x1 + wall, ymid, 0.0}, {wall, yhalf, c.tank_width / 2}, kBoundary);
  add_static_box({(x0 + x1) / 2, -c.tank_depth - wall, 0.0},
                 {(x1 - x0) / 2 + 2 * wall, wall, c.tank_width / 2 + 2 * wall}, kBoundary);
}

const FloeShape& World::shape_for(const Polygon& outline) {
  std::vector<double> key;
  for (const Eigen::Vector2d& v : outline) key.insert(key.end(), {v.x(), v.y()});
  if (auto it = shape_cache_.find(key); it != shape_cache_.end()) return *it->second;

  const double h = scene_.ice.thickness;
  auto s = std::make_unique<FloeShape>();
  // body axes along the principal axes of the outline, so Bullet's diagonal inertia is right
  s->principal_yaw = principal_yaw(outline);
  for (const Eigen::Vector2d& v : outline) s->outline.push_back(rotate(v, -s->principal_yaw));
  s->prism = make_prism(s->outline, h);

  const Eigen::Vector4d m = area_moments(s->outline);
  s->mass = scene_.ice.density * m[0] * h;
  const double rho_h = scene_.ice.density * h;
  const double plate = s->mass * h * h / 12;  // thickness contribution about horizontal axes
  s->inertia = {rho_h * m[2] + plate, rho_h * (m[1] + m[2]), rho_h * m[1] + plate};

  s->damping = damping_coefficients(s->prism, s->mass, std::min(s->inertia.x(), s->inertia.z()),
                                    water_params(scene_.water));

  // boxes keep their outer size under a margin and collide box-box (several points at
  // once); other convex outlines become hulls (the margin adds 1 mm around them)
  double hx, hz;
  if (rectangle_half_extents(s->outline, hx, hz)) {
    s->collision = std::make_unique<btBoxShape>(btVector3(hx, h / 2, hz));
  } else {
    auto hull = std::make_unique<btConvexHullShape>();
    for (const Eigen::Vector3d& p : s->prism.vertices) hull->addPoint(to_bt(p), false);
    hull->recalcLocalAabb();
    s->collision = std::move(hull);
  }
  s->collision->setMargin(kDefaultCollisionMargin);

  FloeShape* raw = s.get();
  floe_shapes_.push_back(std::move(s));
  shape_cache_[key] = raw;
  return *raw;
}

int World::add_body(const FloeShape& shape, const btTransform& pose, int floe_id, int fragment, bool in_world) {
  auto motion = std::make_unique<btDefaultMotionState>(pose);
  btRigidBody::btRigidBodyConstructionInfo ci(shape.mass, motion.get(), shape.collision.get(),
                                              to_bt(shape.inertia));
  auto body = std::make_unique<btRigidBody>(ci);
  body->setFriction(scene_.friction.ice_ice);
  body->setRestitution(0);
  body->setUserIndex(kIce);
  body->setUserIndex2(static_cast<int>(floes_.size()));  // body index, for frozen_floe() and the filter
  body->setSleepingThresholds(scene_.activation.linear_threshold, scene_.activation.angular_threshold);

  // registered before it enters the broadphase, which asks the fragment filter at once
  const int index = static_cast<int>(floes_.size());
  floes_.push_back(FloeBody{body.get(), floe_id, &shape, false, fragment});
  if (in_world) {
    dynamics_->addRigidBody(body.get());
    // floes start at rest at their equilibrium draft: asleep until something touches them
    body->setActivationState(scene_.activation.sleeping ? ISLAND_SLEEPING : DISABLE_DEACTIVATION);
  } else {
    // not simulated: isActive() is false, so water forces, health checks and counts skip it
    body->forceActivationState(DISABLE_SIMULATION);
  }
  motion_states_.push_back(std::move(motion));
  bodies_.push_back(std::move(body));
  return index;
}

bool World::is_breakable(const Polygon& outline) const {
  switch (scene_.fracture.mode) {
    case FractureMode::kOff: return false;
    case FractureMode::kOn: return true;
    case FractureMode::kAuto: {
      // floes smaller than the characteristic length stay rigid (paper: 0.3 m < l_c)
      double size = 0;
      for (const Eigen::Vector2d& a : outline)
        for (const Eigen::Vector2d& b : outline) size = std::max(size, (a - b).norm() / std::sqrt(2.0));
      return size >= scene_.fracture.characteristic_length;
    }
  }
  return false;
}

double World::initial_height(const Floe& floe) const {
  const double h = scene_.ice.thickness;
  const double draft = h * scene_.ice.density / scene_.water.density;  // Archimedes, flat prism
  return h / 2 - draft + floe.layer * (h + scene_.layout.min_gap);
}

void World::add_floe(const Floe& floe) {
  const int floe_id = next_floe_id_++;
  if (is_breakable(floe.shape)) {
    add_breakable_floe(floe, floe_id);
    return;
  }
  const FloeShape& shape = shape_for(floe.shape);
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(btVector3(floe.centre.x(), initial_height(floe), floe.centre.y()));
  pose.setRotation(btQuaternion(btVector3(0, 1, 0), floe.yaw + shape.principal_yaw));
  add_body(shape, pose, floe_id);
}

void World::add_breakable_floe(const Floe& floe, int floe_id) {
  // the lattice in the floe's principal frame (elements are squares in that frame)
  const double yaw0 = principal_yaw(floe.shape);
  Polygon outline;
  for (const Eigen::Vector2d& v : floe.shape) outline.push_back(rotate(v, -yaw0));
  const double Le = scene_.fracture.element_size;
  const ElementLattice lattice = make_element_lattice(outline, Le);
  const FloeShape& element = shape_for(square(Le));

  const double y = initial_height(floe);
  const double yaw = floe.yaw + yaw0;
  const btQuaternion rotation(btVector3(0, 1, 0), yaw);

  // far from the structure the floe is one rigid body: its elements wait outside the world
  const bool dormant = scene_.fracture.lattice_radius > 0;
  btTransform stand_in_pose;
  if (dormant) {
    const FloeShape& whole = shape_for(floe.shape);
    stand_in_pose.setIdentity();
    stand_in_pose.setOrigin(btVector3(floe.centre.x(), y, floe.centre.y()));
    stand_in_pose.setRotation(btQuaternion(btVector3(0, 1, 0), floe.yaw + whole.principal_yaw));
    DormantLattice d;
    d.stand_in = add_body(whole, stand_in_pose, floe_id);
    floes_[d.stand_in].stand_in = true;
    floes_[d.stand_in].lattice = static_cast<int>(lattices_.size());
    d.first_element = static_cast<int>(floes_.size());
    d.elements = static_cast<int>(lattice.centres.size());
    d.first_joint = static_cast<int>(joints_.size());
    d.joints = static_cast<int>(lattice.joints.size());
    d.radius = 0;
    for (const Eigen::Vector2d& v : whole.outline) d.radius = std::max(d.radius, v.norm());
    lattices_.push_back(std::move(d));
  }

  const int first = static_cast<int>(floes_.size());
  for (const Eigen::Vector2d& c : lattice.centres) {
    const Eigen::Vector2d at = floe.centre + rotate(c, yaw);
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(btVector3(at.x(), y, at.y()));
    pose.setRotation(rotation);
    // one piece: its elements do not collide with each other (fragment 0)
    const int index = add_body(element, pose, floe_id, 0, !dormant);
    if (dormant) {
      DormantLattice& d = lattices_.back();
      floes_[index].lattice = static_cast<int>(lattices_.size()) - 1;
      d.offsets.push_back(stand_in_pose.inverse() * pose);
    }
  }

  // fixed joints at the middle of each shared face; softness set on all six axes
  // (axis -1, Bullet's default for setParam, is silently ignored: bullet-notes.md)
  int index = 0;
  for (const LatticeJoint& j : lattice.joints) {
    IceJoint joint;
    joint.floe = floe_id;
    joint.index = index++;
    joint.body_a = first + j.a;
    joint.body_b = first + j.b;
    const Eigen::Vector2d mid_a = j.midpoint - lattice.centres[j.a];
    const Eigen::Vector2d mid_b = j.midpoint - lattice.centres[j.b];
    joint.midpoint_a = Eigen::Vector3d(mid_a.x(), 0, mid_a.y());
    joint.axis_a = Eigen::Vector3d(j.axis.x(), 0, j.axis.y());
    btTransform frame_a, frame_b;
    frame_a.setIdentity();
    frame_b.setIdentity();
    frame_a.setOrigin(btVector3(mid_a.x(), 0, mid_a.y()));
    frame_b.setOrigin(btVector3(mid_b.x(), 0, mid_b.y()));
    joint.constraint = std::make_unique<btFixedConstraint>(*floes_[joint.body_a].body, *floes_[joint.body_b].body,
                                                           frame_a, frame_b);
    for (int axis = 0; axis < 6; ++axis) {
      joint.constraint->setParam(BT_CONSTRAINT_STOP_CFM, scene_.fracture.cfm, axis);
      joint.constraint->setParam(BT_CONSTRAINT_STOP_ERP, scene_.fracture.erp, axis);
    }
    // more iterations for the joints than for contacts where asked: Bullet solves a
    // constraint's rows for max(its override, solver.iterations) sweeps, contacts
    // only for solver.iterations (btSequentialImpulseConstraintSolver)
    if (scene_.fracture.joint_iterations > 0)
      joint.constraint->setOverrideNumSolverIterations(scene_.fracture.joint_iterations);
    joint.feedback = std::make_unique<btJointFeedback>();
    joint.constraint->setJointFeedback(joint.feedback.get());
    // the fragment filter handles collisions; a dormant lattice's joints wait for wake_lattice
    if (!dormant) dynamics_->addConstraint(joint.constraint.get(), false);
    joints_.push_back(std::move(joint));
  }
}

void World::wake_lattice(DormantLattice& lattice) {
  if (lattice.replaced) return;
  FloeBody& whole = floes_[lattice.stand_in];
  if (whole.frozen) unfreeze(whole);
  btRigidBody& w = *whole.body;
  const btTransform T = w.getCenterOfMassTransform();
  const btVector3 v = w.getLinearVelocity(), omega = w.getAngularVelocity();
  dynamics_->removeRigidBody(&w);
  w.forceActivationState(DISABLE_SIMULATION);
  for (int i = 0; i < lattice.elements; ++i) {
    btRigidBody& e = *floes_[lattice.first_element + i].body;
    const btTransform pose = T * lattice.offsets[i];
    e.setCenterOfMassTransform(pose);  // also the interpolation pose
    e.getMotionState()->setWorldTransform(pose);
    // rigid-body motion of the stand-in at the element's place
    e.setLinearVelocity(v + omega.cross(pose.getOrigin() - T.getOrigin()));
    e.setAngularVelocity(omega);
    dynamics_->addRigidBody(&e);
    // awake: the structure is near (the sleep clock starts again)
    e.forceActivationState(scene_.activation.sleeping ? ACTIVE_TAG : DISABLE_DEACTIVATION);
    e.setDeactivationTime(0);
  }
  for (int j = 0; j < lattice.joints; ++j) {
    btTypedConstraint* c = joints_[lattice.first_joint + j].constraint.get();
    if (c) dynamics_->addConstraint(c, false);
  }
  lattice.replaced = true;
}

bool World::output_awake(const FloeBody& floe) const {
  if (floe.lattice >= 0 && !floe.stand_in && !lattices_[floe.lattice].replaced)
    return floes_[lattices_[floe.lattice].stand_in].body->isActive();
  return floe.body->isActive();
}

bool World::make_dormant(DormantLattice& lattice) {
  if (!lattice.replaced || lattice.broken) return false;
  for (int i = 0; i < lattice.elements; ++i)
    if (floes_[lattice.first_element + i].frozen) return false;
  // the floe's motion: centre of mass and mean velocities of its (equal) elements,
  // orientation from the first element through its offset
  btVector3 v(0, 0, 0), omega(0, 0, 0);
  bool awake = false;
  for (int i = 0; i < lattice.elements; ++i) {
    const btRigidBody& e = *floes_[lattice.first_element + i].body;
    v += e.getLinearVelocity();
    omega += e.getAngularVelocity();
    awake = awake || e.isActive();
  }
  const double n = lattice.elements;
  btTransform T = floes_[lattice.first_element].body->getCenterOfMassTransform() * lattice.offsets[0].inverse();
  T.setOrigin(lattice_centre(lattice));

  for (int j = 0; j < lattice.joints; ++j) dynamics_->removeConstraint(joints_[lattice.first_joint + j].constraint.get());
  for (int i = 0; i < lattice.elements; ++i) {
    btRigidBody& e = *floes_[lattice.first_element + i].body;
    dynamics_->removeRigidBody(&e);
    e.forceActivationState(DISABLE_SIMULATION);
  }
  btRigidBody& w = *floes_[lattice.stand_in].body;
  w.setCenterOfMassTransform(T);
  w.getMotionState()->setWorldTransform(T);
  w.setLinearVelocity(v / n);
  w.setAngularVelocity(omega / n);
  dynamics_->addRigidBody(&w);
  w.forceActivationState(!scene_.activation.sleeping ? DISABLE_DEACTIVATION : awake ? ACTIVE_TAG : ISLAND_SLEEPING);
  w.setDeactivationTime(0);
  lattice.replaced = false;
  return true;
}

btVector3 World::lattice_centre(const DormantLattice& lattice) const {
  if (!lattice.replaced) return floes_[lattice.stand_in].body->getCenterOfMassPosition();
  btVector3 centre(0, 0, 0);
  for (int i = 0; i < lattice.elements; ++i) centre += floes_[lattice.first_element + i].body->getCenterOfMassPosition();
  return centre / lattice.elements;
}

Eigen::Isometry3d World::output_pose(const FloeBody& floe) const {
  if (floe.lattice >= 0 && !floe.stand_in) {
    const DormantLattice& d = lattices_[floe.lattice];
    if (!d.replaced) {
      const int i = floe.body->getUserIndex2() - d.first_element;
      return to_eigen(floes_[d.stand_in].body->getCenterOfMassTransform() * d.offsets[i]);
    }
  }
  return body_pose(*floe.body);
}

void World::break_joint(IceJoint& joint) {
  if (!joint.constraint) return;
  const int lattice = floes_[joint.body_a].lattice;
  if (lattice >= 0) lattices_[lattice].broken = true;
  dynamics_->removeConstraint(joint.constraint.get());
  joint.constraint.reset();
  update_fragments(joint.floe);
}

void World::update_fragments(int floe_id) {
  // fragments: connected components of the floe's elements over intact joints
  std::vector<int> bodies;
  for (int b = 0; b < static_cast<int>(floes_.size()); ++b)
    if (floes_[b].floe_id == floe_id && floes_[b].fragment >= 0) bodies.push_back(b);
  std::map<int, int> parent;
  for (int b : bodies) parent[b] = b;
  std::function<int(int)> root = [&](int x) { return parent[x] == x ? x : parent[x] = root(parent[x]); };
  for (const IceJoint& j : joints_)
    if (j.floe == floe_id && j.constraint) parent[root(j.body_a)] = root(j.body_b);
  for (int b : bodies) {
    const int fragment = root(b);
    if (floes_[b].fragment != fragment) {
      floes_[b].fragment = fragment;
    }
  }
  // new broadphase pairs between pieces that came apart: re-create their proxies
  for (int b : bodies) {
    floes_[b].body->activate(true);
    dynamics_->refreshBroadphaseProxy(floes_[b].body);
  }
}

void World::add_floes(const std::vector<Floe>& floes) {
  floes_.reserve(floes_.size() + floes.size());
  for (const Floe& f : floes) add_floe(f);
}

void World::set_structure_target(const Eigen::Vector3d& position) {
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(position));
  structure_->getMotionState()->setWorldTransform(pose);
}

int World::awake_floes() const {
  int n = 0;
  for (const FloeBody& f : floes_) n += f.body->isActive() ? 1 : 0;
  return n;
}

void World::freeze(FloeBody& floe) {
  btRigidBody& b = *floe.body;
  b.setLinearVelocity(btVector3(0, 0, 0));
  b.setAngularVelocity(btVector3(0, 0, 0));
  b.setMassProps(0, btVector3(0, 0, 0));  // also flags it static: the solver treats it as fixed
  b.updateInertiaTensor();
  b.forceActivationState(ISLAND_SLEEPING);
  floe.frozen = true;
}

void World::unfreeze(FloeBody& floe) {
  btRigidBody& b = *floe.body;
  b.setMassProps(floe.shape->mass, to_bt(floe.shape->inertia));  // clears the static flag
  b.updateInertiaTensor();
  b.setLinearVelocity(btVector3(0, 0, 0));
  b.setAngularVelocity(btVector3(0, 0, 0));
  b.forceActivationState(ACTIVE_TAG);
  b.setDeactivationTime(0);
  floe.frozen = false;
}

FloeBody* World::frozen_floe(const btCollisionObject* object) {
  if (object->getUserIndex() != kIce) return nullptr;
  FloeBody& f = floes_[object->getUserIndex2()];
  return f.frozen ? &f : nullptr;
}

int World::contact_points() const {
  int n = 0;
  for (int i = 0; i < dispatcher_->getNumManifolds(); ++i)
    n += dispatcher_->getManifoldByIndexInternal(i)->getNumContacts();
  return n;
}

WaterParams water_params(const WaterSettings& w) {
  return WaterParams{w.density, w.gravity, w.drag_coefficient, w.skin_friction_coefficient,
                     w.heave_damping_ratio, w.roll_pitch_damping_ratio};
}

std::unique_ptr<World> build_world(const Scene& scene, const std::vector<Floe>& floes) {
  auto world = std::make_unique<World>(scene);
  world->add_profile_structure();
  world->add_boundaries();
  world->add_floes(floes);
  return world;
}

}  // namespace icedem
