#include "dem/activation/reach.hpp"

#include <cmath>

#include <btBulletDynamicsCommon.h>


namespace icedem {
namespace {

// how far a body's box can travel in `time`: its speed, and its spin times the half diagonal
double box_travel(const btRigidBody& body, double time) {
  const btBroadphaseProxy& p = *body.getBroadphaseHandle();
  const double half_diagonal = 0.5 * (p.m_aabbMax - p.m_aabbMin).length();
  return (body.getLinearVelocity().length() + body.getAngularVelocity().length() * half_diagonal) * time;
}

// the floes within `pad` of a body's broadphase box
void near_box(World& world, const btCollisionObject& object, double pad, std::vector<int>& out) {
  const btBroadphaseProxy& p = *object.getBroadphaseHandle();
  const btVector3 d(pad, pad, pad);
  world.unreached().overlapping(p.m_aabbMin - d, p.m_aabbMax + d, out);
}

}  // namespace

void enter_reached_floes(const Scene& scene, World& world) {
  if (world.unreached().size() == 0) return;
  const double dt = scene.time.dt;
  std::vector<int> reached;

  // the structure moves by its speed; Bullet's box of it already spans its last step
  near_box(world, *world.structure(), kReachMargin + 2 * std::abs(scene.structure.speed) * dt, reached);
  // every awake body (sleeping and fixed ones do not move)
  for (int i : world.awake_floe_indices()) {
    const btRigidBody& body = *world.floes()[static_cast<std::size_t>(i)].body;
    near_box(world, body, kReachMargin + box_travel(body, 2 * dt), reached);
  }
  for (int index : reached) world.enter_reached(index);  // a floe met twice enters once
}

}  // namespace icedem
