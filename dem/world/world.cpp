#include "dem/world/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/world/dbvt_fill.hpp"

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

}  // namespace

Liveness liveness(const btRigidBody& body) {
  // out of the world: a floe nothing has reached yet is at rest, asleep (World::add_resting_floe)
  if (!body.isInWorld()) return body.getActivationState() == ISLAND_SLEEPING ? Liveness::kAsleep : Liveness::kOutside;
  return body.isActive() ? Liveness::kAwake : Liveness::kAsleep;
}

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

World::World(const WorldSettings& settings)
    : settings_(settings), shapes_(settings.ice_thickness, settings.ice_density, settings.water) {
  const SolverSettings& solver = settings.solver;
  collision_config_ = std::make_unique<btDefaultCollisionConfiguration>();
  dispatcher_ = std::make_unique<btCollisionDispatcher>(collision_config_.get());
  if (solver.broadphase == Broadphase::kSweepAndPrune) {
    broadphase_ = std::make_unique<bt32BitAxisSweep3>(to_bt(settings.bounds.min()), to_bt(settings.bounds.max()),
                                                      kSweepAndPruneBodies + 1);
  } else {
    auto dbvt = std::make_unique<btDbvtBroadphase>();
    dbvt_ = dbvt.get();
    broadphase_ = std::move(dbvt);
  }
  solver_ = std::make_unique<ContactSolver>(solver, settings.contact_law);
  dynamics_ = std::make_unique<DynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                              collision_config_.get());
  dynamics_->setGravity(btVector3(0, -settings.gravity, 0));
  // sleeping and frozen bodies do not move: only update the bounding boxes of awake ones
  dynamics_->setForceUpdateAllAabbs(false);

  fragment_filter_ = std::make_unique<FragmentFilter>(floes_);
  broadphase_->getOverlappingPairCache()->setOverlapFilterCallback(fragment_filter_.get());

  // sleeping islands from touching contacts (see contact_islands.hpp for why)
  if (settings.activation.islands == IslandMode::kContact) {
    island_manager_ = std::make_unique<ContactIslandManager>();
    dynamics_->replace_island_manager(island_manager_.get());
  }
  // Bullet hands every manifold of an awake body to the solver, empty ones too, and
  // the solver gives both bodies of a manifold a solver body. A body whose empty
  // manifold lands in another island's solve is then solved twice, and each solve
  // adds its applied forces again: a floe near (not touching) floes of other islands
  // got its water forces and weight several times per step, and one went unstable
  // in the paper grid (docs/model/stability.md). With this flag Bullet skips
  // manifolds without contact points when it builds islands (and sorts pairs so
  // that the order is reproducible, which it already was here).
  dynamics_->getDispatchInfo().m_deterministicOverlappingPairs = true;

  btContactSolverInfo& info = dynamics_->getSolverInfo();
  info.m_numIterations = solver.iterations;
  info.m_warmstartingFactor = solver.warm_start;
  info.m_sor = solver.sor;
  // with a tolerance, one solve per island instead of Bullet's batches of islands
  // (about 128 rows each), so that each island stops sweeping when it has converged;
  // without one, Bullet's batches, which the paper profile's results were made with
  // (the batching changes round-off, and so a chaotic run's path)
  if (solver.tolerance > 0) info.m_minimumSolverBatchSize = 1;
  info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  info.m_restitution = 0;
  info.m_splitImpulse = solver.split_impulse;
  // Bullet only splits penetrations deeper than 4 cm by default, i.e. never for
  // 33 mm ice; a zero threshold splits every penetrating contact
  info.m_splitImpulsePenetrationThreshold = 0;
  // Bullet 3 uses m_erp2 for every contact (split or not); m_erp is for joints
  info.m_erp2 = solver.contact_erp;

  gCalculateCombinedFrictionCallback = &combined_friction;
  gCalculateCombinedRestitutionCallback = &combined_restitution;
  // a body sleeps after this long below its thresholds (a process-wide Bullet global)
  gDeactivationTime = settings.activation.time;
}

World::~World() {
  // joints out of the world before the world goes
  for (IceJoint& j : joints_)
    if (j.constraint) dynamics_->removeConstraint(j.constraint.get());
  // Then the pairs, all in one pass, and Bullet's world, which frees the boxes of the bodies
  // in it. Removing the bodies one by one cleaned each one's pairs by a pass over all pairs
  // and found it in Bullet's arrays by a linear search: minutes for a 96,000-floe field.
  btOverlappingPairCache& pairs = *broadphase_->getOverlappingPairCache();
  btBroadphasePairArray& all = pairs.getOverlappingPairArray();
  while (all.size() > 0) {
    btBroadphaseProxy* a = all[all.size() - 1].m_pProxy0;
    btBroadphaseProxy* b = all[all.size() - 1].m_pProxy1;
    pairs.removeOverlappingPair(a, b, dispatcher_.get());
  }
  pairs.setOverlapFilterCallback(nullptr);
  dynamics_.reset();  // before the bodies, which are declared after it and so would go first
}

void World::add_structure(std::unique_ptr<btCollisionShape> shape, const Eigen::Vector3d& position,
                          double friction, std::vector<std::unique_ptr<btCollisionShape>> parts) {
  for (auto& part : parts) static_shapes_.push_back(std::move(part));
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(position));
  auto motion = std::make_unique<btDefaultMotionState>(pose);
  btRigidBody::btRigidBodyConstructionInfo ci(0.0, motion.get(), shape.get());
  auto body = std::make_unique<btRigidBody>(ci);
  // kinematic: moved by us, infinite mass for the solver, never asleep
  body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  body->setActivationState(DISABLE_DEACTIVATION);
  body->setFriction(friction);
  body->setRestitution(0);
  body->setUserIndex(kStructure);
  body->setUserIndex2(-1);  // its place in the solver's canonical order (ContactSolver)
  body->setUserIndex3(static_cast<int>(bodies_.size()));  // its index in bodies() (enter_world)
  enter_world(*body);
  structure_ = body.get();
  solver_->set_structure(structure_);
  static_shapes_.push_back(std::move(shape));
  motion_states_.push_back(std::move(motion));
  bodies_.push_back(std::move(body));
}

btRigidBody* World::add_static_box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half, Material material,
                                   double friction) {
  auto shape = std::make_unique<btBoxShape>(to_bt(half));
  shape->setMargin(kDefaultCollisionMargin);
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(centre));
  btRigidBody::btRigidBodyConstructionInfo ci(0.0, nullptr, shape.get());
  ci.m_startWorldTransform = pose;
  auto body = std::make_unique<btRigidBody>(ci);
  body->setFriction(friction);
  body->setRestitution(0);
  body->setUserIndex(material);
  // fixed bodies are numbered -2, -3, ... in the order they are made (ice bodies 0, 1, ...):
  // every body's place in the solver's canonical order (ContactSolver)
  body->setUserIndex2(-2 - fixed_boxes_++);
  body->setUserIndex3(static_cast<int>(bodies_.size()));  // its index in bodies() (enter_world)
  enter_world(*body);
  btRigidBody* raw = body.get();
  static_shapes_.push_back(std::move(shape));
  bodies_.push_back(std::move(body));
  return raw;
}

int World::add_static_prism(const Polygon& outline, double bottom, double thickness, double friction) {
  auto shape = std::make_unique<btConvexHullShape>();
  for (const Eigen::Vector2d& v : outline)
    for (double y : {bottom, bottom + thickness}) shape->addPoint(btVector3(v.x(), y, v.y()), false);
  shape->recalcLocalAabb();
  shape->setMargin(kDefaultCollisionMargin);
  btRigidBody::btRigidBodyConstructionInfo ci(0.0, nullptr, shape.get());
  auto body = std::make_unique<btRigidBody>(ci);
  body->setFriction(friction);
  body->setRestitution(0);
  body->setUserIndex(kHeldIce);
  body->setUserIndex2(-2 - fixed_boxes_++);  // in the canonical order of fixed bodies (add_static_box)
  const int index = static_cast<int>(bodies_.size());
  body->setUserIndex3(index);
  enter_world(*body);
  static_shapes_.push_back(std::move(shape));
  bodies_.push_back(std::move(body));
  return index;
}

void World::remove_static(int index) {
  btRigidBody& body = *bodies_.at(index);
  if (!body.isStaticObject()) throw std::invalid_argument(fmt::format("remove_static: body {} is not fixed", index));
  dynamics_->removeRigidBody(&body);
  body.forceActivationState(DISABLE_SIMULATION);
}

int World::add_body(const FloeShape& shape, const btTransform& pose, int floe_id, double friction, int fragment,
                    bool in_world, const std::optional<AddedMass>& added) {
  auto motion = std::make_unique<btDefaultMotionState>(pose);
  btRigidBody::btRigidBodyConstructionInfo ci(shape.mass, motion.get(), shape.collision.get(),
                                              to_bt(shape.inertia));
  auto body = std::make_unique<btRigidBody>(ci);
  body->setFriction(friction);
  body->setRestitution(0);
  body->setUserIndex(kIce);
  body->setUserIndex2(static_cast<int>(floes_.size()));  // body index, for frozen_floe() and the filter
  body->setUserIndex3(static_cast<int>(bodies_.size()));  // its index in bodies() (enter_world)
  const ActivationSettings& a = settings_.activation;
  body->setSleepingThresholds(a.linear_threshold, a.angular_threshold);
  if (settings_.added_mass) {
    // heave, roll and pitch with the water's added mass (dem/water/added_mass.hpp), in the world's
    // axes: a floe stays nearly flat, so its body y stays the vertical
    const AddedMass water = added ? *added : plate_added_mass(area(shape.outline), settings_.water.water_density);
    const MotionFactors f = added_mass_factors(shape.mass, 0.5 * (shape.inertia.x() + shape.inertia.z()), water);
    body->setLinearFactor(btVector3(1, f.vertical, 1));
    body->setAngularFactor(btVector3(f.roll_pitch, 1, f.roll_pitch));
  }

  // registered before it enters the broadphase, which asks the fragment filter at once
  const int index = static_cast<int>(floes_.size());
  floes_.push_back(FloeBody{body.get(), floe_id, &shape, false, fragment});
  if (in_world) {
    enter_world(*body);
    // floes start at rest at their equilibrium draft: asleep until something touches them
    body->setActivationState(a.sleeping ? ISLAND_SLEEPING : DISABLE_DEACTIVATION);
  } else {
    // not simulated: liveness() is kOutside, so water forces, health checks and counts skip it
    body->forceActivationState(DISABLE_SIMULATION);
  }
  motion_states_.push_back(std::move(motion));
  bodies_.push_back(std::move(body));
  return index;
}

int World::add_joint(IceJoint joint, bool in_world) {
  // its index, for the solver's canonical order and the contact problems' joint rows
  joint.constraint->setUserConstraintId(static_cast<int>(joints_.size()));
  if (in_world) dynamics_->addConstraint(joint.constraint.get(), false);  // the fragment filter handles collisions
  joints_.push_back(std::move(joint));
  return static_cast<int>(joints_.size()) - 1;
}

void World::set_structure_target(const Eigen::Vector3d& position) {
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(to_bt(position));
  structure_->getMotionState()->setWorldTransform(pose);
}

void World::set_structure_target(const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation) {
  btTransform pose;
  pose.setBasis(btMatrix3x3(rotation(0, 0), rotation(0, 1), rotation(0, 2), rotation(1, 0), rotation(1, 1),
                            rotation(1, 2), rotation(2, 0), rotation(2, 1), rotation(2, 2)));
  pose.setOrigin(to_bt(position));
  structure_->getMotionState()->setWorldTransform(pose);
}

void World::update_boxes_shuffled(std::vector<btCollisionObject*> objects) {
  shuffle_fixed(objects);
  for (btCollisionObject* o : objects) dynamics_->updateSingleAabb(o);
}

void World::settle_broadphase() {
  if (!dbvt_) return;
  btDbvtBroadphase* dbvt = dbvt_;
  dbvt->m_sets[btDbvtBroadphase::DYNAMIC_SET].optimizeTopDown(kBottomUpLeaves);  // taking leaves out is then cheap
  std::vector<btDbvtProxy*> resting;
  for (int stage = 0; stage < btDbvtBroadphase::STAGECOUNT; ++stage) {
    for (btDbvtProxy* p = dbvt->m_stageRoots[stage]; p; p = p->links[1]) resting.push_back(p);
    dbvt->m_stageRoots[stage] = nullptr;
  }
  for (btDbvtProxy* p : resting) dbvt->m_sets[btDbvtBroadphase::DYNAMIC_SET].remove(p->leaf);
  shuffle_fixed(resting);  // into the fixed tree in no spatial order, then rebuilt top-down
  btDbvtProxy*& fixed = dbvt->m_stageRoots[btDbvtBroadphase::STAGECOUNT];
  for (btDbvtProxy* p : resting) {
    p->leaf = dbvt->m_sets[btDbvtBroadphase::FIXED_SET].insert(btDbvtVolume::FromMM(p->m_aabbMin, p->m_aabbMax), p);
    p->stage = btDbvtBroadphase::STAGECOUNT;
    p->links[0] = nullptr;
    p->links[1] = fixed;
    if (fixed) fixed->links[0] = p;
    fixed = p;
  }
  dbvt->m_sets[btDbvtBroadphase::FIXED_SET].optimizeTopDown(kBottomUpLeaves);
  dbvt->m_needcleanup = true;
}

void require_sweep_and_prune_room(std::size_t bodies) {
  if (bodies <= static_cast<std::size_t>(kSweepAndPruneBodies)) return;
  throw InputError(fmt::format("solver.broadphase = \"sap\" holds at most {} bodies in the world, and this scene "
                               "needs at least {} (floes, lattice elements, boundaries, structure): use "
                               "solver.broadphase = \"dbvt\", the default, which has no limit",
                               kSweepAndPruneBodies, bodies));
}

void World::enter_world(btRigidBody& body) {
  // Bullet's sweep and prune has a fixed number of handles and writes past them (a crash)
  if (settings_.solver.broadphase == Broadphase::kSweepAndPrune)
    require_sweep_and_prune_room(static_cast<std::size_t>(dynamics_->getNumCollisionObjects()) + 1);
  // Bullet orders the two bodies of a pair, and so the sides its collision detection works
  // from, by their broadphase ids, which its dbvt hands out in the order bodies enter. A floe
  // that enters when it is reached (dem/activation/reach.hpp) would then meet its neighbours from the other
  // side than had it been in the world from the start, and their contact points would differ
  // in round-off: the id is the body's index in bodies() instead, its order of making
  make_proxy(body, true);
  if (!dbvt_) return;
  // Each box enters the dbvt's tree of moving boxes next to the box nearest it, and a field
  // made row by row, each floe nearest the one before, grows a chain: 96,000 floes took 5 s
  // to enter. Rebuilt balanced every 4 sqrt(N) entries, the chain stays that short, and the
  // entries and rebuilds cost about N^1.5 together.
  btDbvt& moving = dbvt_->m_sets[btDbvtBroadphase::DYNAMIC_SET];
  if (++entered_since_rebuild_ >= std::max(256.0, 4.0 * std::sqrt(static_cast<double>(moving.m_leaves)))) {
    moving.optimizeTopDown(kBottomUpLeaves);
    entered_since_rebuild_ = 0;
  }
}

void World::refresh_proxy(btRigidBody& body) { make_proxy(body, false); }

void World::make_proxy(btRigidBody& body, bool add) {
  const auto bullet = [&] { add ? dynamics_->addRigidBody(&body) : dynamics_->refreshBroadphaseProxy(&body); };
  if (!dbvt_) {
    bullet();
    return;
  }
  const int next_id = dbvt_->m_gid;
  dbvt_->m_gid = body.getUserIndex3();  // the broadphase gives the body m_gid + 1
  bullet();
  dbvt_->m_gid = std::max(next_id, body.getUserIndex3() + 1);
}

std::vector<int> World::awake_floe_indices() const {
  std::vector<int> awake;
  const btAlignedObjectArray<btRigidBody*>& bodies = dynamics_->getNonStaticRigidBodies();
  for (int i = 0; i < bodies.size(); ++i)
    if (bodies[i]->getUserIndex() == kIce && liveness(*bodies[i]) == Liveness::kAwake)
      awake.push_back(bodies[i]->getUserIndex2());
  std::sort(awake.begin(), awake.end());  // the floes' order: sums over them as before
  return awake;
}

bool World::keeps_unreached() const {
  const ActivationSettings& a = settings_.activation;
  return a.unreached_out_of_world && a.sleeping && a.skip_asleep && a.islands == IslandMode::kContact &&
         !a.freeze_outside_region;
}

int World::add_resting_floe(const FloeShape& shape, const btTransform& pose, int floe_id, double friction) {
  const bool unreached = keeps_unreached();
  const int index = add_body(shape, pose, floe_id, friction, -1, !unreached);
  if (!unreached) return index;
  btRigidBody& body = *floes_[static_cast<std::size_t>(index)].body;
  btVector3 lo, hi;
  body.getCollisionShape()->getAabb(body.getWorldTransform(), lo, hi);
  unreached_.add(index, lo, hi);
  body.forceActivationState(ISLAND_SLEEPING);  // asleep, out of the world (liveness)
  return index;
}

void World::enter_reached(int index) {
  if (!unreached_.contains(index)) return;
  unreached_.remove(index);
  btRigidBody& body = *floes_[static_cast<std::size_t>(index)].body;
  enter_world(body);
  body.forceActivationState(ISLAND_SLEEPING);  // as add_body leaves a floe made in the world
}

std::array<int, 2> World::split_floe(const FloeSplit& split) {
  const int parent = split.body;
  if (parent < 0 || parent >= static_cast<int>(floes_.size()) || floes_[parent].fragment >= 0 ||
      floes_[parent].stand_in || liveness(*floes_[parent].body) == Liveness::kOutside)
    throw std::invalid_argument(fmt::format("split_floe: body {} is not a whole rigid floe in play", parent));
  const PolygonCut parts = cut(floes_[parent].shape->outline, {split.point[0], split.point[1]},
                               {split.normal[0], split.normal[1]});
  if (parts.behind.size() < 3 || parts.ahead.size() < 3)
    throw std::invalid_argument(fmt::format("split_floe: the crack line misses body {}", parent));
  enter_reached(parent);  // kept out of the world until reached: as if it had been in it
  if (floes_[parent].frozen) unfreeze(floes_[parent]);
  // what the pieces take from the floe, read before floes_ grows (its references then dangle)
  btRigidBody& whole = *floes_[parent].body;
  const int floe_id = floes_[parent].floe_id;
  const btTransform T = whole.getCenterOfMassTransform();
  const btVector3 v = whole.getLinearVelocity(), omega = whole.getAngularVelocity();
  const double friction = whole.getFriction();
  dynamics_->removeRigidBody(&whole);
  whole.forceActivationState(DISABLE_SIMULATION);
  floes_[parent].gone = true;

  std::array<int, 2> pieces{};
  int k = 0;
  for (const Polygon* part : {&parts.behind, &parts.ahead}) {
    // a piece's shape is centred on its centroid, its body axes along its principal axes
    const Eigen::Vector2d c = centroid(*part);
    Polygon local;
    for (const Eigen::Vector2d& p : *part) local.push_back(p - c);
    const FloeShape& shape = shapes_.get(local);
    btTransform offset;
    offset.setIdentity();
    offset.setOrigin(btVector3(c.x(), 0.0, c.y()));
    offset.setRotation(btQuaternion(btVector3(0, 1, 0), shape.principal_yaw));
    const btTransform pose = T * offset;
    const int index = add_body(shape, pose, floe_id, friction);
    floes_[index].parent = parent;
    btRigidBody& b = *floes_[index].body;
    // the floe's rigid-body motion at the piece's place: with the pieces' masses and
    // inertias summing to the floe's, momentum and angular momentum are the floe's
    b.setLinearVelocity(v + omega.cross(pose.getOrigin() - T.getOrigin()));
    b.setAngularVelocity(omega);
    b.forceActivationState(settings_.activation.sleeping ? ACTIVE_TAG : DISABLE_DEACTIVATION);
    b.setDeactivationTime(0);
    pieces[k++] = index;
  }
  splits_.push_back(split);
  return pieces;
}

void World::leave_run(int index) {
  if (index < 0 || index >= static_cast<int>(floes_.size()) || floes_[index].fragment >= 0 ||
      floes_[index].stand_in || floes_[index].lattice >= 0 || floes_[index].gone || floes_[index].left ||
      (!floes_[index].body->isInWorld() && !unreached_.contains(index)))
    throw std::invalid_argument(fmt::format("leave_run: body {} is not a rigid floe in play", index));
  FloeBody& floe = floes_[index];
  if (floe.frozen) unfreeze(floe);
  btRigidBody& body = *floe.body;
  body.setLinearVelocity(btVector3(0, 0, 0));
  body.setAngularVelocity(btVector3(0, 0, 0));
  // a checkpoint's rebuilt world may keep it out until reached, where the run had it in the world
  if (unreached_.contains(index)) unreached_.remove(index);
  else dynamics_->removeRigidBody(&body);  // its broadphase proxy, and with it its pairs and manifolds
  body.forceActivationState(DISABLE_SIMULATION);
  floe.left = true;
  left_.push_back(index);
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

FloeBody* World::ice_body(const btCollisionObject* object) {
  return object->getUserIndex() == kIce ? &floes_[object->getUserIndex2()] : nullptr;
}

const FloeBody* World::ice_body(const btCollisionObject* object) const {
  return object->getUserIndex() == kIce ? &floes_[object->getUserIndex2()] : nullptr;
}

FloeBody* World::frozen_floe(const btCollisionObject* object) {
  FloeBody* f = ice_body(object);
  return f && f->frozen ? f : nullptr;
}

int World::contact_points() const {
  int n = 0;
  for (int i = 0; i < dispatcher_->getNumManifolds(); ++i)
    n += dispatcher_->getManifoldByIndexInternal(i)->getNumContacts();
  return n;
}

}  // namespace icedem
