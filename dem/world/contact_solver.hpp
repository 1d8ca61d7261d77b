// The contact solver: Bullet's projected Gauss-Seidel (sequential impulse)
// solver, with the sweep loop rewritten for a jammed ice pack.
//
// Why: in a pack pressed against the structure the load at the structure is
// carried by long chains of floes. Projected Gauss-Seidel moves an impulse
// about one contact along such a chain per sweep, so at a fixed small number
// of sweeps the chain is not solved, the penetration it should have resisted
// is removed by the split impulse instead, and the peak load at the structure
// is a property of the sweep count (docs/model/convergence.md). This solver:
//  - measures every island's convergence after each sweep and stops the sweeps
//    of that island once the residual is below solver.tolerance (quiet islands
//    stop after a sweep or two, the jammed one runs up to the cap);
//  - warm-starts friction as well as normal impulses (Bullet 3.24 starts
//    friction from zero each step, and recomputes its directions): the
//    friction impulse of the previous step, a vector in the tangent plane, is
//    projected onto the new friction directions;
//  - optionally orders the contact rows by distance from the structure,
//    alternating outward and inward sweeps (symmetric Gauss-Seidel along the
//    load path);
//  - optionally gives a contact that is not slipping its static friction coefficient
//    (dem/world/static_friction.hpp);
//  - optionally limits the normal force of each contact to the ice's crushing
//    force (ice.contact_crushing): a pair of floes, or a floe and the structure,
//    cannot press on each other harder than the ice can bear;
//  - optionally gives the ice's contacts the crushing law (contact.model =
//    "crushing", dem/contact/crushing.hpp): each contact row of ice carries at
//    most the force its overlap bears (dem/world/crushing_contact.hpp), and the
//    overlap it reached while crushing, the crushed ice, is not pushed out by the
//    position pass (only the overlap beyond it is);
//  - optionally bounds the normal impulses of rows a stage owns (dem/world/contact_bound.hpp: the
//    analytic level sheet's edge bears at most its breaking load);
//  - reports per step the sweeps used, the final residual and whether the cap
//    stopped an island before it converged.
// With warm_start 0.85 (Bullet's), no friction warm start, Bullet's row order
// and tolerance 0 it computes exactly what btSequentialImpulseConstraintSolver
// computes (tests/physics/test_contact_solver.cpp checks it bit for bit).
// With another method (solver.method, dem/contact/registry.hpp) an island with
// contacts is not swept: its problem is read off the rows Bullet set up
// (capture_problem), solved whole, joints included, by the island solve
// (dem/contact/island_solve.hpp), and the impulses written back to the rows
// (apply_impulses); Bullet then integrates as after the sweeps. The
// split-impulse position pass stays Bullet's sweeps either way.
//
// Residual after sweep k (dimensionless), per solve group (island): the relative
// change of the sweep,
//   c_k = max( |P_k - P_{k-1}| / max(|P_k|, p0),  max_b |dJ_b| / max(max_j ln_j, p0) ),
// divided by 1 - rho with rho = c_k / c_{k-1} (at most 0.99): an estimate of the
// relative error still left, since Gauss-Seidel converges linearly. P is the
// impulse vector of the island's contacts on the structure over the step (normal
// and friction), dJ_b the net impulse the sweep added to body b, measured as
// m_b (|dv_b| + r_b |dw_b|) (velocity change at its bounding radius r_b; single
// contact impulses are not used: on a face with several contact points they
// shift between the points without changing anything), ln_j the normal impulses
// and p0 = 1e-6 N s (below it an impulse is noise: a 0.3 m floe's weight over a
// step is 0.5 N s). Joints are
// swept their own count (fracture.joint_iterations), as in Bullet; the residual
// covers the contacts.
#pragma once

#include <algorithm>
#include <tuple>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>

#include "dem/contact/crushing.hpp"
#include "dem/contact/island_solve.hpp"
#include "dem/contact/problem.hpp"
#include "dem/contact/solver_settings.hpp"
#include "dem/world/contact_bound.hpp"
#include "dem/world/crushing_contact.hpp"
#include "dem/world/static_friction.hpp"

namespace icedem {

/// Sees the contact problems of chosen Bullet steps (dem/output/problem_export.hpp
/// writes them to files).
class ProblemObserver {
 public:
  virtual ~ProblemObserver() = default;
  /// Called before each Bullet step's solve with the step's index, the time it ends at and its length.
  virtual void begin_step(long /*step*/, double /*t_end*/, double /*h*/) {}
  /// Whether to capture the islands of the Bullet step being solved.
  virtual bool wants_problems() const = 0;
  /// An island's problem as it stood before the sweeps, and what the sweeps made of it.
  virtual void solved(const ContactProblem& problem, const SolverAnswer& answer) = 0;
};


/// How contacts bear load beyond a rigid contact with Coulomb's kinetic friction (the scene's
/// contact, ice and friction keys).
struct ContactLaw {
  double crushing_force = 0.0;          // N, largest normal force of one contact pair (ice.contact_crushing); 0: none
  std::optional<CrushingLaw> crushing;  // contact.model = "crushing" (dem/contact/crushing.hpp); none: rigid
  // which contacts the crushing law acts on (contact.crushing_contacts), the others rigid
  CrushingScope crushing_scope = CrushingScope::kStructure;
  StaticFriction static_friction;       // static coefficients of sticking contacts (none by default)
};

class ContactSolver : public btSequentialImpulseConstraintSolver {
 public:
  /// Impulse below which an impulse counts as zero in the residual, N s.
  static constexpr double kImpulseFloor = 1e-6;
  /// How close to its cap a row's normal impulse is at its cap (relative): the merit's tolerance.
  static constexpr double kAtBound = 1e-3;
  /// Largest convergence rate per sweep the residual assumes (contact_solver.cpp).
  static constexpr double kMaxRate = 0.99;

  /// The error left after a sweep that changed the impulses by `change` (relative)
  /// following one that changed them by `previous_change`: change / (1 - rate).
  static double remaining_error(double change, double previous_change, int sweeps);

  /// `settings`: the scenario's solver keys; `law`: how the contacts bear load (rigid, with
  /// Coulomb's kinetic friction, by default). Throws std::invalid_argument for a crushing law
  /// with the sweeps (solver.method = "pgs"), which do not take it.
  explicit ContactSolver(const SolverSettings& settings, const ContactLaw& law = {});

  /// The structure whose load the residual follows (null: none).
  void set_structure(const btCollisionObject* structure) { structure_ = structure; }

  /// What decides whether an island is solved again to breaking_merit_tolerance (empty: never;
  /// dem/contact/island_solve.hpp).
  void set_joint_ratio(IslandSolve::JointRatio ratio) { island_.set_joint_ratio(std::move(ratio)); }

  /// Let `bound` (not owned; null: none) bound the normal impulses of the rows it holds. Throws
  /// std::invalid_argument for a contact method that takes no bound (the registry's takes_crushing: not the sweeps,
  /// nor the interior-point method).
  void set_contact_bound(ContactBound* bound);

  /// Let `observer` (not owned; null: none) see the problems of the steps it wants.
  void set_observer(ProblemObserver* observer) { observer_ = observer; }

  /// Tells the observer, if any, of the Bullet step about to be solved (ProblemObserver::begin_step).
  void begin_step(long step, double t_end, double h) {
    if (observer_) observer_->begin_step(step, t_end, h);
  }

  /// The friction impulse on body A the solver remembers for `point` from the last step
  /// (solver.friction_warm_start), or null if it remembers none.
  const btVector3* remembered_friction(const btManifoldPoint* point) const;

  /// Remember `impulse` for `point` as if the last step had ended with it (a world rebuilt
  /// from a checkpoint).
  void remember_friction(const btManifoldPoint* point, const btVector3& impulse);

  /// The crushed depth of each crushing manifold (contact.model = "crushing"), carried from step to step.
  CrushedIce& crushed_ice() { return crushed_; }
  const CrushedIce& crushed_ice() const { return crushed_; }

  /// A manifold's place in the canonical order (SweepOrder::kCanonical): the bodies it joins,
  /// then the child shapes its first point names. Sums over manifolds in this order do not
  /// depend on the order of Bullet's arrays (the load cell's, in a world rebuilt from a checkpoint).
  static std::tuple<int, int, int, int> canonical(const btPersistentManifold* m);
  /// The same for the points of a manifold joining `a` and `b`, the first of them `first`.
  static std::tuple<int, int, int, int> canonical(const btCollisionObject* a, const btCollisionObject* b,
                                                  const btManifoldPoint& first);

  /// Accumulated over the solves since the last clear (the owner clears it every step).
  SolverReport& report() { return report_; }
  const SolverReport& report() const { return report_; }

  // Bullet's per-step hook: the friction impulses of the last step become the
  // ones to warm-start from, and its crushed ice the one this step starts from
  void prepareSolve(int numBodies, int numManifolds) override;

  // One island's solve, its bodies first put in the canonical order (their user index 2, as
  // manifolds and joints are): Bullet lists an island's bodies in the order of its world's
  // arrays, which bodies entering the world as they are reached change (dem/activation/reach.hpp), and
  // the solve's sums over bodies would follow that order in their round-off
  btScalar solveGroup(btCollisionObject** bodies, int numBodies, btPersistentManifold** manifolds, int numManifolds,
                      btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info,
                      btIDebugDraw* debug, btDispatcher* dispatcher) override;

 protected:
  void convertContacts(btPersistentManifold** manifolds, int numManifolds, const btContactSolverInfo& info) override;
  // Bullet's joint rows, then the rows of spring joints (dem/world/joint_springs.hpp) rewritten
  // from their stiffness and the step
  void convertJoints(btTypedConstraint** constraints, int numConstraints, const btContactSolverInfo& info) override;
  void solveGroupCacheFriendlySplitImpulseIterations(btCollisionObject** bodies, int numBodies,
                                                     btPersistentManifold** manifolds, int numManifolds,
                                                     btTypedConstraint** constraints, int numConstraints,
                                                     const btContactSolverInfo& info, btIDebugDraw* debug) override;
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                             btPersistentManifold** manifolds, int numManifolds,
                                             btTypedConstraint** constraints, int numConstraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debug) override;
  // Bullet's solver bodies carry a body's linear and angular factors twice (in their inverse mass
  // and angular components, and again when an impulse is applied): a factor of 1/6 would scale the
  // contacts' response by 1/36 while forces get 1/6. Each is applied once (convert_bodies)
  void convertBodies(btCollisionObject** bodies, int numBodies, const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int numBodies,
                                         const btContactSolverInfo& info) override;

 private:
  // a contact row on the structure: its index and which side the structure is on
  struct StructureRow {
    int row;
    double sign;  // +1: the structure is body A of the row, -1: body B
  };
  // the friction impulse a contact point ended a step with
  struct FrictionMemory {
    btScalar normal_impulse;  // identifies the point: Bullet keeps it when it refreshes the point
    btVector3 tangent;        // friction impulse on body A, world frame, N s
  };

  // a crushing manifold's rows in the group's pool
  struct CrushingRows {
    const btPersistentManifold* manifold;
    int first, end;
  };

  // per solver body of the group: its mass and radius, and its velocity change so far
  struct BodyScale {
    double mass = 0;    // kg; 0 for fixed and kinematic bodies
    double radius = 0;  // m, bounding sphere
    btVector3 linear, angular;
  };
  void measure_bodies();
  void remember_velocities();
  double largest_body_impulse_change() const;
  void warm_start_friction(int first_row, const btContactSolverInfo& info);
  void stick_or_slip(const btPersistentManifold& manifold, int first_row, bool on_structure);
  void build_order(bool from_structure);
  // limit a crushing row's position correction to the overlap beyond the crushed depth `crushed` (m)
  static void push_beyond(btSolverConstraint& row, double crushed, const btContactSolverInfo& info);
  // one sweep over the joint rows (those with sweeps left) and, if `contacts`, the contact rows
  // in the given direction of the order; returns the largest change of a contact impulse, N s
  double sweep(int iteration, bool contacts, bool reverse);
  btVector3 structure_impulse() const;
  // the problem of the island whose rows are set up (dem/world/contact_capture.cpp)
  ContactProblem capture_problem(const btContactSolverInfo& info) const;
  // the impulses the rows hold now
  SolverAnswer row_impulses() const;
  // the island solved by the island solve (settings_.method) instead of the sweeps; its
  // impulses written to the rows
  void solve_with_method(const btContactSolverInfo& info);
  // the manifold point of a contact row of the group
  const btManifoldPoint* bound_point(int row) const;
  // the rows a ContactBound holds: each one's point and its impulses now
  std::vector<BoundedImpulse> bounded_impulses() const;
  // contact row r's impulse on body 0 of its manifold now: its normal's and its friction rows' together, N s
  btVector3 row_impulse(int r) const;
  btVector3 friction_impulse(int r) const;  // its friction rows' alone
  // most solves of an island under a ContactBound's sums (contact_bound.hpp): a sum of normal impulses alone is within
  // its bound after the second; one the friction makes nears it by about half its excess a pass (a face's points
  // partly sticking: their friction takes up what the lowered ones shed), 2.35 times to 1.009 in eight
  static constexpr int kBoundPasses = 8;
  // set the rows' impulses to `answer`'s (rows in capture_problem's order), the bodies'
  // velocity changes with them
  void apply_impulses(const SolverAnswer& answer);

  SolverSettings settings_;
  ContactLaw law_;
  const btCollisionObject* structure_ = nullptr;
  IslandSolve island_;              // solves an island's problem with a method other than the sweeps
  ProblemObserver* observer_ = nullptr;
  ContactBound* bound_ = nullptr;
  SolverReport report_;
  std::vector<StructureRow> structure_rows_;  // of the current group
  bool two_directions_ = false;               // two friction rows per contact (else one), set per group
  std::vector<int> order_;                    // contact rows of the current group, sweep order
  std::vector<double> normal_caps_;           // each contact row's largest normal impulse (law_.crushing, bound_), N s
  std::vector<int> bound_rows_;               // of the current group, the contact rows bound_ holds
  std::vector<CrushingRows> crushing_manifolds_;  // of the current group
  CrushedIce crushed_;
  std::vector<BodyScale> bodies_;             // solver bodies of the current group
  // the group's manifolds and joints in the order their rows are made: Bullet's (SweepOrder::kBullet),
  // else canonical (sorted by the bodies and joints they act on)
  std::vector<btPersistentManifold*> sorted_manifolds_;
  std::vector<btTypedConstraint*> sorted_joints_;
  std::unordered_map<const btManifoldPoint*, FrictionMemory> friction_previous_, friction_current_;
};

}  // namespace icedem
