// What a checkpoint keeps of the Bullet world, and how a world is rebuilt from it.
//
// A checkpoint does not copy Bullet's internals (its broadphase tree, the order of its pairs
// and manifolds, a collision algorithm's cached axis): it keeps what the physics depends on,
// and a run continues from a world rebuilt from the scene and that state. Every body's pose,
// velocities and sleeping state; which lattices are in the world and which joints are
// broken; and every contact point with the impulses the next step warm-starts from (and the
// friction impulse the solver remembers for it). The rebuilt world holds the same bodies,
// joints and contact points, in an order of its own: the order changes round-off, so a run
// that checkpoints rebuilds its world at every checkpoint too, which makes a resumed run
// continue exactly as the run that was killed would have (dem/output/checkpoint.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "dem/world/world.hpp"

namespace icedem {

/// One rigid body of World::bodies() (the structure, fixed boxes, ice bodies, in the order
/// they were made): Bullet's state of it, as raw doubles (bit-exact).
struct BodyState {
  double transform[16];                 // btTransform: basis rows (4 each, padded) and origin
  double interpolation_transform[16];   // Bullet's previous pose (the kinematic structure's velocity)
  double linear[4], angular[4];         // m/s, rad/s
  double interpolation_linear[4], interpolation_angular[4];
  double deactivation_time;             // s, Bullet's sleep clock
  int activation;                       // Bullet's activation state
  int in_world;                         // 1: in the dynamics world
  int frozen;                           // 1: a frozen floe (ice bodies only)
  int fragment;                         // ice bodies: FloeBody::fragment
};

/// The contact points of one pair of bodies, body0 as Bullet's manifold has it.
struct ManifoldState {
  int body0, body1;                       // indices into World::bodies()
  std::vector<btManifoldPoint> points;    // Bullet's points, as they are (user data cleared)
  std::vector<int> has_friction_memory;   // per point: 1 if the solver remembers its friction impulse
  std::vector<btVector3> friction_memory; // per point: that impulse on body0, N s, world frame
  int crushed = 0;                        // the crushed ice the solver remembers (dem/world/crushing_contact.hpp):
                                          // 0 none, 1 below its bound, 2 crushing at it
  double crushed_depth = 0.0;             // m
};

struct WorldState {
  std::vector<BodyState> bodies;        // World::bodies() order
  std::vector<uint8_t> lattice_replaced;  // per World::lattices(): its elements are in the world
  std::vector<uint8_t> joint_broken;      // per World::joints()
  std::vector<FloeSplit> splits;          // World::splits(): the rebuilt world makes the same pieces
  std::vector<int> left;                  // World::left_floes(): the floes that left the run, in order
  std::vector<ManifoldState> manifolds;
};

/// The world's state between two steps.
WorldState capture_world(const World& world);

/// Split the floes of `world` as `splits`, from the world's own splits so far up to `until` (the state's first
/// splits, in order). Throws InputError for a split of a body the world has not got (another scene's state).
void replay_splits(World& world, const std::vector<FloeSplit>& splits, std::size_t until);

/// Put `state` into `world`, a world just built from the scene the state was taken from:
/// lattices woken and joints broken as in the state, every body's pose, velocities and sleep,
/// and every contact point. Throws std::runtime_error if the world does not match the state
/// (another scene, or another build of icedem).
void restore_world(World& world, const WorldState& state);

}  // namespace icedem
