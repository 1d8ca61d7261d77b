#include "dem/output/world_state.hpp"

#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <fmt/format.h>

#include "dem/core/errors.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/level_ice.hpp"

namespace icedem {
namespace {

// Bullet's own serialised layout of its types in this (double) precision: a btTransform's
// basis rows and origin, 4 doubles each; a btVector3, 4 doubles. Bit-exact both ways
static_assert(sizeof(btTransformData) == 16 * sizeof(double), "BodyState keeps a btTransform as 16 doubles");
static_assert(sizeof(btVector3Data) == 4 * sizeof(double), "BodyState keeps a btVector3 as 4 doubles");

void put(double* to, const btTransform& t) { t.serialize(*reinterpret_cast<btTransformData*>(to)); }
void put(double* to, const btVector3& v) { v.serialize(*reinterpret_cast<btVector3Data*>(to)); }
btTransform transform(const double* from) {
  btTransform t;
  t.deSerialize(*reinterpret_cast<const btTransformData*>(from));
  return t;
}
btVector3 vector(const double* from) {
  btVector3 v;
  v.deSerialize(*reinterpret_cast<const btVector3Data*>(from));
  return v;
}

// index of every collision object of the world in World::bodies()
std::unordered_map<const btCollisionObject*, int> body_indices(const World& world) {
  std::unordered_map<const btCollisionObject*, int> index;
  for (std::size_t i = 0; i < world.bodies().size(); ++i) index[world.bodies()[i].get()] = static_cast<int>(i);
  return index;
}

// the collision objects in the dynamics world
std::unordered_set<const btCollisionObject*> members(const World& world) {
  std::unordered_set<const btCollisionObject*> member;
  const btCollisionObjectArray& objects = world.dynamics().getCollisionObjectArray();
  for (int i = 0; i < objects.size(); ++i) member.insert(objects[i]);
  return member;
}

// the point as Bullet would hold it had body0 and body1 been the other way round
btManifoldPoint swapped(const btManifoldPoint& p) {
  btManifoldPoint q = p;
  std::swap(q.m_localPointA, q.m_localPointB);
  std::swap(q.m_positionWorldOnA, q.m_positionWorldOnB);
  std::swap(q.m_partId0, q.m_partId1);
  std::swap(q.m_index0, q.m_index1);
  q.m_normalWorldOnB = -p.m_normalWorldOnB;
  // the friction impulses act on body A along these directions: on the other body they
  // are the same impulses along the opposite directions
  q.m_lateralFrictionDir1 = -p.m_lateralFrictionDir1;
  q.m_lateralFrictionDir2 = -p.m_lateralFrictionDir2;
  return q;
}

}  // namespace

WorldState capture_world(const World& world) {
  WorldState s;
  const auto member = members(world);

  for (const auto& body : world.bodies()) {
    BodyState b{};
    put(b.transform, body->getWorldTransform());
    put(b.interpolation_transform, body->getInterpolationWorldTransform());
    put(b.linear, body->getLinearVelocity());
    put(b.angular, body->getAngularVelocity());
    put(b.interpolation_linear, body->getInterpolationLinearVelocity());
    put(b.interpolation_angular, body->getInterpolationAngularVelocity());
    b.deactivation_time = body->getDeactivationTime();
    b.activation = body->getActivationState();
    b.in_world = member.count(body.get()) ? 1 : 0;
    const FloeBody* f = world.ice_body(body.get());
    b.frozen = f && f->frozen ? 1 : 0;
    b.fragment = f ? f->fragment : -1;
    s.bodies.push_back(b);
  }
  for (const DormantLattice& l : world.lattices()) s.lattice_replaced.push_back(l.replaced ? 1 : 0);
  s.splits = world.splits();
  s.left = world.left_floes();
  for (const IceJoint& j : world.joints()) s.joint_broken.push_back(j.constraint ? 0 : 1);

  const auto index = body_indices(world);
  // Bullet has no const access to its manifolds
  btDispatcher& dispatcher = *const_cast<btDispatcher*>(world.dynamics().getDispatcher());
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    if (manifold.getNumContacts() == 0) continue;
    ManifoldState ms;
    ms.body0 = index.at(manifold.getBody0());
    ms.body1 = index.at(manifold.getBody1());
    for (int k = 0; k < manifold.getNumContacts(); ++k) {
      btManifoldPoint p = manifold.getContactPoint(k);
      p.m_userPersistentData = nullptr;
      const btVector3* memory = world.contact_solver().remembered_friction(&manifold.getContactPoint(k));
      ms.points.push_back(p);
      ms.has_friction_memory.push_back(memory ? 1 : 0);
      ms.friction_memory.push_back(memory ? *memory : btVector3(0, 0, 0));
    }
    if (const CrushedIce::Memory* crushed = world.contact_solver().crushed_ice().remembered(&manifold)) {
      ms.crushed = crushed->crushing ? 2 : 1;
      ms.crushed_depth = crushed->depth;
    }
    s.manifolds.push_back(std::move(ms));
  }
  return s;
}

void replay_splits(World& world, const std::vector<FloeSplit>& splits, std::size_t until) {
  if (world.splits().size() > until || until > splits.size())
    throw std::runtime_error("replay_splits: the world has more split floes than asked, or the state fewer");
  for (std::size_t i = world.splits().size(); i < until; ++i) {
    const FloeSplit& split = splits[i];
    if (split.body < 0 || split.body >= static_cast<int>(world.floes().size()))
      throw InputError(fmt::format("the checkpoint splits body {}, the scene builds {} ice bodies: it is not "
                                   "this scene's",
                                   split.body, world.floes().size()));
    world.split_floe(split);
  }
}

void restore_world(World& world, const WorldState& s) {
  // the split floes' pieces first, in the order they were made: they are bodies of the state (those made
  // already, among the analytic sheet's breaks, the state's first splits)
  replay_splits(world, s.splits, s.splits.size());
  // the floes that had left the run, out of it again (pieces made above, or floes of the layout)
  for (int i : s.left) {
    if (i < 0 || i >= static_cast<int>(world.floes().size()))
      throw InputError(fmt::format("the checkpoint has body {} leave the run, the scene builds {} ice bodies: it is "
                                   "not this scene's", i, world.floes().size()));
    try {
      world.leave_run(i);
    } catch (const std::invalid_argument& e) {
      throw InputError(fmt::format("the checkpoint's body {} left the run, but in the rebuilt world {}: it is not "
                                   "this scene's checkpoint", i, e.what()));
    }
  }
  const auto& bodies = world.bodies();
  if (s.bodies.size() != bodies.size() || s.lattice_replaced.size() != world.lattices().size() ||
      s.joint_broken.size() != world.joints().size())
    throw InputError(fmt::format(
        "the checkpoint holds {} bodies, {} lattices and {} joints, the scene builds {}, {} and {}: it is not this "
        "scene's",
        s.bodies.size(), s.lattice_replaced.size(), s.joint_broken.size(), bodies.size(), world.lattices().size(),
        world.joints().size()));
  // the floes the run had reached, in the world (asleep where they lay, as the run found them)
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (s.bodies[i].in_world && world.ice_body(bodies[i].get())) world.enter_reached(bodies[i]->getUserIndex2());
  // the lattices in the world and the broken joints, as the run left them
  for (std::size_t l = 0; l < world.lattices().size(); ++l)
    if (s.lattice_replaced[l]) wake_lattice(world, world.lattices()[l]);
  for (std::size_t j = 0; j < world.joints().size(); ++j)
    if (s.joint_broken[j]) break_joint(world, world.joints()[j]);
  // level ice: the build holds every element of the sheet; those the run had released move again
  // (before the collision pass below, which makes their contacts) with their joints in the solver
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    FloeBody* f = world.ice_body(bodies[i].get());
    if (f && f->frozen && !s.bodies[i].frozen) world.unfreeze(*f);
  }
  sync_level_sheet_joints(world);

  // every body where it was. The bodies of the checkpoint's manifolds are awake for the
  // collision pass below, which makes a manifold for each of their pairs (Bullet skips pairs of
  // two sleeping bodies); every other body keeps the state the build gave it, so a field's
  // untouched floes stay in the broadphase's tree of resting boxes and cost nothing here
  const auto index = body_indices(world);
  const auto member = members(world);
  std::vector<char> touching(bodies.size(), 0);
  for (const ManifoldState& ms : s.manifolds) {
    if (ms.body0 < 0 || ms.body1 < 0 || ms.body0 >= static_cast<int>(bodies.size()) ||
        ms.body1 >= static_cast<int>(bodies.size()))
      throw InputError(fmt::format("the checkpoint has a contact between bodies {} and {}, the scene builds {}: it is "
                                   "not this scene's", ms.body0, ms.body1, bodies.size()));
    touching[ms.body0] = touching[ms.body1] = 1;
  }
  std::vector<btCollisionObject*> moved;  // since the build: their broadphase boxes are stale
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    btRigidBody& body = *bodies[i];
    const BodyState& b = s.bodies[i];
    const FloeBody* f = world.ice_body(&body);
    if (f && f->fragment != b.fragment)
      throw InputError(fmt::format("body {}: fragment {} in the checkpoint, {} rebuilt from its broken joints: it "
                                   "is not this scene's checkpoint", i, b.fragment, f->fragment));
    if ((member.count(&body) > 0) != (b.in_world != 0))
      throw InputError(fmt::format("body {}: {} the world in the checkpoint, not in the rebuilt one: it is not this "
                                   "scene's checkpoint", i, b.in_world ? "in" : "out of"));
    const btTransform pose = transform(b.transform), interpolation = transform(b.interpolation_transform);
    if (b.in_world && !(pose == body.getWorldTransform() && interpolation == body.getInterpolationWorldTransform()))
      moved.push_back(&body);
    body.setWorldTransform(pose);
    body.setInterpolationWorldTransform(interpolation);
    if (body.getMotionState()) body.getMotionState()->setWorldTransform(pose);
    body.updateInertiaTensor();
    if (b.in_world && touching[i] && !body.isStaticObject()) body.forceActivationState(ACTIVE_TAG);
  }
  world.update_boxes_shuffled(moved);  // before Bullet's pass updates the awake ones in the order they were made
  world.dynamics().performDiscreteCollisionDetection();

  // the contact points of every pair as they were, in the manifold Bullet's algorithm for the
  // pair now holds (the collision pass made one for every pair whose boxes overlap); the
  // structure is a compound of hull pieces, with one manifold per piece touching a floe, told
  // apart by the pieces their points name (the solver's canonical key, which is the same
  // whichever way round Bullet holds the pair). Every other manifold is emptied
  btDispatcher& dispatcher = *world.dynamics().getDispatcher();
  using Key = std::tuple<int, int, int, int>;
  std::unordered_map<const btPersistentManifold*, Key> made;  // by the pass's first point of each
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    if (manifold.getNumContacts() > 0) made[&manifold] = ContactSolver::canonical(&manifold);
    manifold.clearManifold();
  }
  btOverlappingPairCache& pairs = *world.dynamics().getBroadphase()->getOverlappingPairCache();
  for (const ManifoldState& ms : s.manifolds) {
    btBroadphasePair* pair =
        pairs.findPair(bodies[ms.body0]->getBroadphaseHandle(), bodies[ms.body1]->getBroadphaseHandle());
    if (!pair || !pair->m_algorithm) continue;  // cannot happen for bodies in touch: dropped
    btManifoldArray candidates;
    pair->m_algorithm->getAllContactManifolds(candidates);
    btPersistentManifold* target = candidates.size() == 1 ? candidates[0] : nullptr;
    const Key k = ContactSolver::canonical(bodies[ms.body0].get(), bodies[ms.body1].get(), ms.points.front());
    for (int c = 0; !target && c < candidates.size(); ++c) {
      const auto it = made.find(candidates[c]);
      if (it != made.end() && it->second == k) target = candidates[c];
    }
    if (!target || target->getNumContacts() > 0) continue;  // a piece no longer touching: dropped
    const bool swap = index.at(target->getBody0()) != ms.body0;
    for (std::size_t p = 0; p < ms.points.size(); ++p) {
      const int at = target->addManifoldPoint(swap ? swapped(ms.points[p]) : ms.points[p]);
      if (ms.has_friction_memory[p])
        world.contact_solver().remember_friction(&target->getContactPoint(at),
                                                 swap ? -ms.friction_memory[p] : ms.friction_memory[p]);
    }
    if (ms.crushed)
      world.contact_solver().crushed_ice().remember(
          target, CrushedIce::Memory{target->getBody0(), target->getBody1(), ms.crushed_depth, ms.crushed == 2});
  }

  // velocities, frozen floes and sleep as they were
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    btRigidBody& body = *bodies[i];
    const BodyState& b = s.bodies[i];
    FloeBody* f = world.ice_body(&body);
    if (f && b.frozen && !f->frozen) world.freeze(*f);
    body.setLinearVelocity(vector(b.linear));
    body.setAngularVelocity(vector(b.angular));
    body.setInterpolationLinearVelocity(vector(b.interpolation_linear));
    body.setInterpolationAngularVelocity(vector(b.interpolation_angular));
    body.forceActivationState(b.activation);
    body.setDeactivationTime(b.deactivation_time);
  }
}

}  // namespace icedem
