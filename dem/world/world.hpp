// The Bullet world of one run and the registry of what is in it: the solver
// set-up, the kinematic structure, fixed boxes, the floating ice bodies and
// their joints. It knows nothing of scenarios: dem/step/world_builder.hpp turns a
// Scene into a World, dem/fracture/ice_lattice.hpp adds and breaks the lattices of
// breakable floes.
//
// Every Bullet choice the physics depends on is made here, once, with its reason:
//  - double precision (BT_USE_DOUBLE_PRECISION, set by CMake);
//  - friction combined per material pair, not Bullet's product rule;
//  - two friction directions per contact (SOLVER_USE_2_FRICTION_DIRECTIONS);
//  - restitution 0 everywhere (paper, Table 3);
//  - collision margins of a millimetre (Bullet's 0.04 m exceeds the ice thickness);
//  - sleeping thresholds for a 0.07 m/s tow, and islands built from touching
//    contacts rather than bounding-box overlap (dem/world/contact_islands.hpp);
//  - Bullet's PGS solver with its sweep loop replaced (dem/world/contact_solver.hpp):
//    convergence measured per island, an early stop, friction warm starting;
//  - split-impulse penetration recovery, so contact impulses measured by the
//    load cell hold no position-correction push (solver.split_impulse).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <btBulletDynamicsCommon.h>

#include "dem/input/scene.hpp"
#include "dem/water/added_mass.hpp"
#include "dem/world/bullet_eigen.hpp"
#include "dem/world/static_friction.hpp"
#include "dem/world/contact_islands.hpp"
#include "dem/world/contact_solver.hpp"
#include "dem/world/dynamics_world.hpp"
#include "dem/world/floe_shape.hpp"
#include "dem/world/unreached_floes.hpp"

namespace icedem {

/// The bodies the sweep-and-prune broadphase (solver.broadphase = "sap") can hold: Bullet
/// sizes it when the world is made (each handle costs about 150 bytes up front).
inline constexpr int kSweepAndPruneBodies = 65535;

/// Throws InputError, naming solver.broadphase, if `bodies` exceed kSweepAndPruneBodies.
void require_sweep_and_prune_room(std::size_t bodies);

/// What a collision object is made of; stored in btCollisionObject::userIndex
/// and read by the friction rule and the crushing law (crushing_contact.hpp). kHeldIce: a fixed body of ice
/// (the analytic level sheet's prisms), a boundary to the floes whose edge crushes where
/// contact.crushing_contacts says so.
enum Material : int { kIce = 1, kStructure = 2, kBoundary = 3, kHeldIce = 4 };

/// One floating rigid body: a whole rigid floe, or one element of a breakable floe.
struct FloeBody {
  btRigidBody* body;       // owned by World
  int floe_id;             // index of its floe in the layout
  const FloeShape* shape;  // owned by World
  bool frozen = false;     // a fixed obstacle for now (dem/activation/activation.hpp), or an element of
                           // level ice held where it lies (dem/fracture/level_ice.hpp)
  int fragment = -1;       // breakable floes: elements of one fragment do not collide; -1: rigid floe
  bool stand_in = false;   // the whole floe standing in for its dormant lattice (not an output body)
  int lattice = -1;        // index into World::lattices() for a floe with a lattice region, else -1
  int parent = -1;         // a piece of a split floe: the index of the floe it was split from, else -1
  bool gone = false;       // split into pieces: out of the run for good
  bool left = false;       // left behind the structure (activation.leave_behind): out of the run for good, where it lay
};

/// A rigid floe split in two along a straight crack (fracture.mode = "analytic",
/// dem/fracture/fracture_split.hpp), kept in the order of the splits so that a checkpoint's world makes
/// the same pieces again.
struct FloeSplit {
  int body;           // index into World::floes() of the floe that split
  double point[2];    // m, a point of the crack line in the floe's body frame (x, z)
  double normal[2];   // the crack line's normal, body frame (x, z): the far piece lies along it
};

/// Whether a body takes part in the dynamics now. Every stage that skips bodies
/// asks this, so the rule is in one place.
enum class Liveness {
  kOutside,  // not in the Bullet world: an element of a dormant lattice, or a replaced stand-in
  kAsleep,   // at rest (sleeping, frozen, or not yet reached and out of the world): not integrated
  kAwake,    // being solved and integrated
};
Liveness liveness(const btRigidBody& body);

/// A fixed joint between two elements of a breakable floe (seed paper, Fig. 5).
struct IceJoint {
  std::unique_ptr<btGeneric6DofSpring2Constraint> constraint;  // null once broken
  std::unique_ptr<btJointFeedback> feedback;  // force and torque on body A, written by the solver
  int floe;                    // floe index in the layout
  int index;                   // joint index within its floe
  int body_a, body_b;          // indices into World::floes()
  Eigen::Vector3d midpoint_a;  // m, joint midpoint in A's body frame
  Eigen::Vector3d axis_a;      // unit, from A's centre to B's, in A's body frame
  double face_length = 0;      // m, the face the two elements share; 0: fracture.element_size (a square's side)
};

/// A breakable floe simulated as one rigid body (its stand-in) while it is
/// farther than fracture.lattice_radius from the structure (dem/fracture/ice_lattice.hpp).
struct DormantLattice {
  int stand_in;                       // index into World::floes()
  int first_element, elements;        // World::floes()[first_element, first_element + elements)
  int first_joint, joints;            // World::joints()[first_joint, first_joint + joints)
  std::vector<btTransform> offsets;   // element poses in the stand-in's body frame
  double radius;                      // m, farthest outline vertex from the floe's centroid
  bool replaced = false;              // the lattice is in the world, the stand-in is not
  bool broken = false;                // a joint has broken: it stays a lattice
  bool equal_elements = true;         // its elements are equal squares (else their motion is weighed by mass)
};

/// Level ice (dem/fracture/level_ice.hpp): one breakable sheet whose elements are held where they
/// lie (frozen) far from the structure and move near it; a joint is in the solver while it is
/// intact and one of its elements moves.
struct LevelSheet {
  int floe_id = -1;                              // its floe index in the layout
  int first_element = 0, elements = 0;           // World::floes()[first_element, first_element + elements)
  int first_joint = 0, joints = 0;               // World::joints()[first_joint, first_joint + joints)
  std::vector<char> edge;                        // per element: along the sheet's sides or far end
  std::vector<char> joint_in_world;              // per joint: its constraint is in the solver
};

/// What a World is made with (from the Scene: world_settings() in dem/step/world_builder.hpp).
struct WorldSettings {
  SolverSettings solver;
  ActivationSettings activation;
  double gravity;              // m/s^2
  Eigen::AlignedBox3d bounds;  // m, where bodies can be (the sweep-and-prune broadphase needs it)
  double ice_thickness;        // m, of every floe shape
  double ice_density;          // kg/m^3
  WaterParams water;           // for the shapes' damping
  bool added_mass = false;     // ice bodies respond with the water's added mass (dem/water/added_mass.hpp)
  ContactLaw contact_law;      // the contacts' crushing and static friction (dem/world/contact_solver.hpp)
};

/// The Bullet world and everything in it. Not copyable; one per run.
class World {
 public:
  explicit World(const WorldSettings& settings);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Add the kinematic structure with `shape` (and the `parts` a compound shape refers to),
  /// its reference point (axis at the waterline) at `position`, with `friction` against ice.
  void add_structure(std::unique_ptr<btCollisionShape> shape, const Eigen::Vector3d& position, double friction,
                     std::vector<std::unique_ptr<btCollisionShape>> parts = {});

  /// Add a fixed box (mother ice, tank walls) with `friction` against ice.
  btRigidBody* add_static_box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half_extents,
                              Material material, double friction);

  /// Add a fixed prism of ice (kHeldIce): the convex `outline` (x, z; m, tank frame) from
  /// height `bottom` up by `thickness`, with `friction` against ice; a convex part of the analytic level sheet
  /// (dem/fracture/analytic_sheet.hpp). Returns its index in bodies().
  int add_static_prism(const Polygon& outline, double bottom, double thickness, double friction);

  /// Take the fixed body bodies()[index] out of the world for good (its index stays taken).
  void remove_static(int index);

  /// Add an ice body of `shape` at `pose`, with `friction` against ice; `fragment` >= 0 for an
  /// element of a breakable floe; out of the world (not simulated) unless `in_world`. At rest,
  /// asleep if sleeping is on. With the water's added mass on (WorldSettings::added_mass) it
  /// responds with `added`, by default its own outline's (plate_added_mass). Returns its index in
  /// floes().
  int add_body(const FloeShape& shape, const btTransform& pose, int floe_id, double friction, int fragment = -1,
               bool in_world = true, const std::optional<AddedMass>& added = std::nullopt);

  /// Add a joint; its constraint enters the solver if `in_world`. Returns its index in joints().
  int add_joint(IceJoint joint, bool in_world);

  /// Split rigid floe `split.body` along its crack into two rigid pieces that move with the floe's
  /// rigid-body velocity at their places (mass, momentum and angular momentum are kept), both
  /// awake; the floe leaves the world for good (Liveness::kOutside). Returns the pieces' indices
  /// in floes(): the one behind the crack line (against its normal), then the one ahead. Throws
  /// std::invalid_argument if the body is not a whole rigid floe in play or the line misses it.
  std::array<int, 2> split_floe(const FloeSplit& split);

  /// The splits so far, in order.
  const std::vector<FloeSplit>& splits() const { return splits_; }

  /// Rigid floe `index` leaves the run for good where it lies (dem/activation/left_behind.hpp): out of
  /// Bullet's world, its contacts gone with it, its pose kept. Throws std::invalid_argument if it is not a
  /// whole rigid floe or piece in the world.
  void leave_run(int index);

  /// The floes that left the run so far (leave_run), in order: a checkpoint's world takes them out again.
  const std::vector<int>& left_floes() const { return left_; }

  /// The shape of bodies with this outline (made once, owned by the world).
  const FloeShape& shape(const Polygon& outline) { return shapes_.get(outline); }

  /// Move the kinematic structure so that it reaches `position` at the end of
  /// the next Bullet step; Bullet derives its velocity from the motion.
  void set_structure_target(const Eigen::Vector3d& position);
  /// The same with the structure turned by `rotation` about its reference point (a moored structure).
  void set_structure_target(const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation);

  /// Let `observer` (not owned; null: none) see the contact problems of the steps it wants.
  void set_problem_observer(ProblemObserver* observer) { solver_->set_observer(observer); }

  /// What the contact solver did since the report was last cleared.
  SolverReport& solver_report() { return solver_->report(); }

  /// The contact solver (what it remembers between steps is part of a checkpoint).
  ContactSolver& contact_solver() { return *solver_; }
  const ContactSolver& contact_solver() const { return *solver_; }

  /// Every rigid body in the order it was made (the structure, fixed boxes, ice bodies):
  /// the index a checkpoint names a body by.
  const std::vector<std::unique_ptr<btRigidBody>>& bodies() const { return bodies_; }

  const WorldSettings& settings() const { return settings_; }
  DynamicsWorld& dynamics() { return *dynamics_; }
  const DynamicsWorld& dynamics() const { return *dynamics_; }
  btRigidBody* structure() const { return structure_; }
  std::vector<FloeBody>& floes() { return floes_; }
  const std::vector<FloeBody>& floes() const { return floes_; }

  /// Joints of breakable floes (broken ones have no constraint).
  std::vector<IceJoint>& joints() { return joints_; }
  const std::vector<IceJoint>& joints() const { return joints_; }

  /// Breakable floes that start as one rigid body (fracture.lattice_radius > 0).
  std::vector<DormantLattice>& lattices() { return lattices_; }
  const std::vector<DormantLattice>& lattices() const { return lattices_; }
  /// An element of a dormant lattice (its stand-in is in the world in its place): out of the
  /// world, so liveness() is kOutside, but known without reading the body. The per-step loops over
  /// every body or joint skip these first: on the 0.15 m hexagons' field (5,800 bodies, about
  /// 10,000 joints, most dormant) reading each body took 2.6 % of the run.
  bool in_dormant_lattice(const FloeBody& floe) const {
    return floe.lattice >= 0 && !floe.stand_in && !lattices_[floe.lattice].replaced;
  }

  /// The level sheet (ice.cover = "level"), if the scene has one.
  std::optional<LevelSheet>& level_sheet() { return level_sheet_; }
  const std::optional<LevelSheet>& level_sheet() const { return level_sheet_; }

  /// Move every body now in Bullet's world to its broadphase's tree of resting boxes, built
  /// balanced. Bullet's dbvt does that itself two steps after a body last moved, one
  /// insertion at a time, so a field made at once (the floes made row by row) became a deep
  /// chain: a 96,000-floe field's first steps took 22 s. Call once the world is built.
  void settle_broadphase();

  /// Update the broadphase boxes of `objects` (in the world), in a shuffled order: a body whose
  /// box Bullet updates leaves the tree of resting boxes for the tree of moving ones, one
  /// insertion at a time, and all of a field at once in the order it was made built a chain
  /// (restoring a 96,000-floe checkpoint took 100 s of CPU).
  void update_boxes_shuffled(std::vector<btCollisionObject*> objects);

  /// Make a body's broadphase proxy again (its pairs are found anew), under the same id it
  /// entered with (enter_world), so that its pairs keep their sides. Bullet's own refresh hands
  /// out the next free id, and a world rebuilt from a checkpoint, which refreshes in another
  /// order, then meets the pairs from other sides (round-off apart).
  void refresh_proxy(btRigidBody& body);

  /// Put a body made by the world into Bullet's world (every body enters through here).
  /// Throws InputError if the sweep-and-prune broadphase is full (kSweepAndPruneBodies).
  void enter_world(btRigidBody& body);

  /// Whether floes that nothing has reached are kept out of Bullet's world
  /// (activation.unreached_out_of_world, with sleeping on, forces on awake bodies only and
  /// contact islands: Bullet's own islands join boxes that merely overlap, so there a resting
  /// neighbour counts). Not with activation.freeze_outside_region: frozen floes entering when
  /// reached made a run that left the one with all floes in the world after 35 s (a 12 m short
  /// tow), for a reason not yet found.
  bool keeps_unreached() const;

  /// Add a floe resting where the layout put it (a rigid floe or a lattice's stand-in): in the
  /// world, asleep, or kept out of it until reached when keeps_unreached() (dem/world/unreached_floes.hpp).
  /// Returns its index in floes().
  int add_resting_floe(const FloeShape& shape, const btTransform& pose, int floe_id, double friction);

  /// Floe `index`, kept out of the world until reached, enters it asleep where it lies, as a
  /// floe in the world all along that nothing has touched is.
  void enter_reached(int index);

  /// The floes kept out of the world until reached.
  UnreachedFloes& unreached() { return unreached_; }
  const UnreachedFloes& unreached() const { return unreached_; }

  /// Number of ice bodies currently awake (simulated).
  int awake_floes() const { return static_cast<int>(awake_floe_indices().size()); }

  /// The ice bodies awake now, by index into floes(), ascending. Read from Bullet's list of the
  /// dynamic bodies in its world, so it costs what the world holds, not what the field does.
  std::vector<int> awake_floe_indices() const;

  /// Make a floe a fixed obstacle at rest (zero inverse mass, asleep).
  void freeze(FloeBody& floe);

  /// Make a frozen floe dynamic again, at rest and awake.
  void unfreeze(FloeBody& floe);

  /// The ice body (floe or element) of a collision object, else nullptr.
  FloeBody* ice_body(const btCollisionObject* object);
  const FloeBody* ice_body(const btCollisionObject* object) const;

  /// The floe of a collision object if it is a frozen floe, else nullptr.
  FloeBody* frozen_floe(const btCollisionObject* object);

  /// Number of contact points in all manifolds (what the solver works on).
  int contact_points() const;

 private:
  // Bullet's dbvt proxy of `body` made (add: the body enters Bullet's world; else its proxy is
  // made again) under the body's index in bodies() as its broadphase id (enter_world says why)
  void make_proxy(btRigidBody& body, bool add);

  WorldSettings settings_;
  std::unique_ptr<btDefaultCollisionConfiguration> collision_config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  btDbvtBroadphase* dbvt_ = nullptr;  // broadphase_ when it is the dbvt (the default), else null
  std::unique_ptr<ContactSolver> solver_;
  std::unique_ptr<btSimulationIslandManager> island_manager_;  // must outlive dynamics_
  std::unique_ptr<DynamicsWorld> dynamics_;

  FloeShapes shapes_;
  std::vector<std::unique_ptr<btCollisionShape>> static_shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  int entered_since_rebuild_ = 0;  // bodies entered since the broadphase's moving tree was rebuilt
  std::vector<std::unique_ptr<btMotionState>> motion_states_;
  std::vector<FloeBody> floes_;
  std::vector<IceJoint> joints_;
  std::vector<DormantLattice> lattices_;
  std::optional<LevelSheet> level_sheet_;
  std::vector<FloeSplit> splits_;
  std::vector<int> left_;
  UnreachedFloes unreached_;
  std::unique_ptr<btOverlapFilterCallback> fragment_filter_;
  btRigidBody* structure_ = nullptr;
  int fixed_boxes_ = 0;  // fixed boxes made so far
};

}  // namespace icedem
