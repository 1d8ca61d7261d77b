// The Bullet world of one run: solver set-up, the kinematic structure, the
// fixed boundaries (mother ice, tank) and the floating floes.
//
// Every Bullet choice the physics depends on is made here, once, with its reason
// (see also ../shared/reference/bullet-notes.md):
//  - double precision (BT_USE_DOUBLE_PRECISION, set by CMake);
//  - friction combined per material pair, not Bullet's product rule;
//  - two friction directions per contact (SOLVER_USE_2_FRICTION_DIRECTIONS);
//  - restitution 0 everywhere (paper, Table 3);
//  - collision margins of a millimetre (Bullet's 0.04 m exceeds the ice thickness);
//  - sleeping thresholds for a 0.07 m/s tow, and islands built from touching
//    contacts rather than bounding-box overlap (dem/contact_islands.hpp);
//  - Bullet's PGS solver with its sweep loop replaced (dem/contact_solver.hpp):
//    convergence measured per island, an early stop, friction warm starting;
//  - split-impulse penetration recovery, so contact impulses measured by the
//    load cell hold no position-correction push (solver.split_impulse).
#pragma once

#include <map>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <btBulletDynamicsCommon.h>

#include "dem/bullet_eigen.hpp"
#include "dem/contact_islands.hpp"
#include "dem/contact_solver.hpp"
#include "dem/floe_layout.hpp"
#include "dem/hydrostatics.hpp"
#include "dem/scene.hpp"
#include "dem/water_forces.hpp"

namespace icedem {

/// What a collision object is made of; stored in btCollisionObject::userIndex
/// and read by the friction rule.
enum Material : int { kIce = 1, kStructure = 2, kBoundary = 3 };

/// Geometry shared by every floe with the same outline and thickness.
struct FloeShape {
  Polygon outline;           // local (x, z), m, centroid at origin, principal axes along x and z
  double principal_yaw;      // rad, yaw of the principal frame relative to the input outline
  ConvexPolyhedron prism;    // body frame, for hydrostatics
  double mass;               // kg
  Eigen::Vector3d inertia;   // kg m^2, principal moments about body x, y, z
  DampingCoefficients damping;
  std::unique_ptr<btCollisionShape> collision;
};

/// One floating rigid body: a whole rigid floe, or one element of a breakable floe.
struct FloeBody {
  btRigidBody* body;       // owned by World
  int floe_id;             // index of its floe in the layout
  const FloeShape* shape;  // owned by World
  bool frozen = false;     // a fixed obstacle for now (dem/activation.hpp)
  int fragment = -1;       // breakable floes: elements of one fragment do not collide; -1: rigid floe
  bool stand_in = false;   // the whole floe standing in for its dormant lattice (not an output body)
  int lattice = -1;        // index into World::lattices() for a floe with a lattice region, else -1
};

/// A breakable floe simulated as one rigid body (its stand-in) while it is
/// farther than fracture.lattice_radius from the structure; nearer, its
/// elements and joints replace the stand-in. An intact lattice that has left
/// the region becomes the stand-in again; a broken one stays a lattice. A
/// dormant lattice's elements and joints exist but are not in the Bullet world.
struct DormantLattice {
  int stand_in;                       // index into World::floes()
  int first_element, elements;        // World::floes()[first_element, first_element + elements)
  int first_joint, joints;            // World::joints()[first_joint, first_joint + joints)
  std::vector<btTransform> offsets;   // element poses in the stand-in's body frame
  double radius;                      // m, farthest outline vertex from the floe's centroid
  bool replaced = false;              // the lattice is in the world, the stand-in is not
  bool broken = false;                // a joint has broken: it stays a lattice
};

/// A fixed joint between two elements of a breakable floe (seed paper, Fig. 5).
struct IceJoint {
  std::unique_ptr<btGeneric6DofSpring2Constraint> constraint;  // null once broken
  std::unique_ptr<btJointFeedback> feedback;  // force and torque on body A, written by the solver
  int floe;                    // floe index in the layout
  int index;                   // joint index within its floe
  int body_a, body_b;          // indices into World::floes()
  Eigen::Vector3d midpoint_a;  // m, joint midpoint in A's body frame
  Eigen::Vector3d axis_a;      // unit, from A's centre to B's, in A's body frame
};

/// The Bullet world and everything in it. Not copyable; one per run.
class World {
 public:
  /// An empty world with the scene's solver, friction and activation settings.
  explicit World(const Scene& scene);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Add the kinematic structure with `shape`, its reference point (axis at the
  /// waterline) at `position`. Friction against ice: friction.ice_structure.
  void add_structure(std::unique_ptr<btCollisionShape> shape, const Eigen::Vector3d& position);

  /// Add the scene's hull (structure.profile) at the structure's start position.
  void add_profile_structure();

  /// Add the mother ice along the channel sides and end, the tank walls and floor.
  void add_boundaries();

  /// Inside of the tank (x, y, z), m: between its end walls and side walls, from
  /// the floor up to the walls' top; ice outside it has escaped.
  Eigen::AlignedBox3d tank_box() const;

  /// Add one floe floating at its equilibrium draft, at rest: a rigid body, or a
  /// lattice of elements and joints if the scene makes it breakable.
  void add_floe(const Floe& floe);

  /// Height of a floe's centre at t = 0, m: at its equilibrium draft, or
  /// resting on the layers below it (rafted ice, layout.layers).
  double initial_height(const Floe& floe) const;

  /// Add every floe of a layout.
  void add_floes(const std::vector<Floe>& floes);

  /// Move the kinematic structure so that it reaches `position` at the end of
  /// the next Bullet step; Bullet derives its velocity from the motion.
  void set_structure_target(const Eigen::Vector3d& position);

  /// What the contact solver did since the report was last cleared.
  SolverReport& solver_report() { return solver_->report(); }

  DynamicsWorld& dynamics() { return *dynamics_; }
  const DynamicsWorld& dynamics() const { return *dynamics_; }
  btRigidBody* structure() const { return structure_; }
  std::vector<FloeBody>& floes() { return floes_; }
  const std::vector<FloeBody>& floes() const { return floes_; }
  const Scene& scene() const { return scene_; }

  /// Number of floes currently awake (simulated).
  int awake_floes() const;

  /// Make a floe a fixed obstacle at rest (zero inverse mass, asleep).
  void freeze(FloeBody& floe);

  /// Make a frozen floe dynamic again, at rest and awake.
  void unfreeze(FloeBody& floe);

  /// The floe of a collision object if it is a frozen floe, else nullptr.
  FloeBody* frozen_floe(const btCollisionObject* object);

  /// Joints of breakable floes (broken ones have no constraint).
  std::vector<IceJoint>& joints() { return joints_; }
  const std::vector<IceJoint>& joints() const { return joints_; }

  /// Remove a joint from the solver and recompute its floe's fragments, so that
  /// pieces that came apart collide with each other.
  void break_joint(IceJoint& joint);

  /// Breakable floes that start as one rigid body (fracture.lattice_radius > 0).
  std::vector<DormantLattice>& lattices() { return lattices_; }
  const std::vector<DormantLattice>& lattices() const { return lattices_; }

  /// Put a dormant lattice in the world in place of its stand-in: every element
  /// takes the rigid-body motion of the stand-in at its place, the joints are
  /// added intact, and the stand-in leaves the world.
  void wake_lattice(DormantLattice& lattice);

  /// The reverse, for a lattice with every joint intact and no frozen element:
  /// the stand-in returns at the elements' centre of mass with their mean motion,
  /// and the elements and joints leave the world. Returns false (and does
  /// nothing) if the lattice is broken or frozen.
  bool make_dormant(DormantLattice& lattice);

  /// Centre of mass of a breakable floe with a lattice region: its stand-in's while
  /// dormant, else the mean of its (equal) elements' centres.
  btVector3 lattice_centre(const DormantLattice& lattice) const;

  /// Pose of an output body (a rigid floe or an element): an element of a
  /// dormant lattice follows its stand-in.
  Eigen::Isometry3d output_pose(const FloeBody& floe) const;

  /// Whether an output body is being simulated (awake), through its stand-in while dormant.
  bool output_awake(const FloeBody& floe) const;

  /// Whether a floe of this outline is made of breakable elements (fracture.mode).
  bool is_breakable(const Polygon& outline) const;

  /// Number of contact points in all manifolds (what the solver works on).
  int contact_points() const;

 private:
  const FloeShape& shape_for(const Polygon& outline);
  int add_body(const FloeShape& shape, const btTransform& pose, int floe_id, int fragment = -1,
               bool in_world = true);
  void add_breakable_floe(const Floe& floe, int floe_id);
  void update_fragments(int floe_id);
  btRigidBody* add_static_box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents,
                              Material material);

  const Scene& scene_;
  std::unique_ptr<btDefaultCollisionConfiguration> collision_config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<ContactSolver> solver_;
  std::unique_ptr<btSimulationIslandManager> island_manager_;  // must outlive dynamics_
  std::unique_ptr<DynamicsWorld> dynamics_;

  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btMotionState>> motion_states_;
  std::vector<std::unique_ptr<FloeShape>> floe_shapes_;
  std::map<std::vector<double>, FloeShape*> shape_cache_;
  std::vector<FloeBody> floes_;
  std::vector<IceJoint> joints_;
  std::vector<DormantLattice> lattices_;
  std::unique_ptr<btOverlapFilterCallback> fragment_filter_;
  int next_floe_id_ = 0;
  btRigidBody* structure_ = nullptr;
};

/// Water properties and hydrodynamic coefficients of the scene.
WaterParams water_params(const WaterSettings& water);

/// The scene's full world: structure, boundaries and the given floes.
std::unique_ptr<World> build_world(const Scene& scene, const std::vector<Floe>& floes);

}  // namespace icedem
