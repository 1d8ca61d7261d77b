// The load cell: the ice load on the kinematic structure, from contact impulses.
//
// After each Bullet step, every contact manifold that involves the structure is
// read. A contact point's total impulse is the normal impulse along its normal
// plus both friction impulses along their directions; Bullet applies it to
// body 0 and its opposite to body 1, so the sign flips when the structure is
// body 1 (docs/model/bullet.md). Summed over points and divided by the step length it
// is the force of the ice on the structure; the moment is taken about the
// structure's reference point (its axis at the waterline), like the paper's
// six-component load cell.
//
// With split impulse on (solver.split_impulse), penetration is corrected by a
// separate pseudo-impulse that does not enter these impulses, so the load holds
// no position-correction push.
#pragma once

#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

class btDispatcher;
class btRigidBody;
class btPersistentManifold;

namespace icedem {

/// The ice load over one step, tank frame.
struct LoadReading {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   // N, by the ice on the structure
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // N m, about the reference point
  int contacts = 0;                                  // contact points on the structure (last substep)
};

/// Calls `visit(name, field)` for every field of a LoadReading (a checkpoint writes it so, as the
/// State's values: dem/step/state.hpp).
template <typename Load, typename Visit>  // Load: LoadReading or const LoadReading
std::enable_if_t<std::is_same_v<std::remove_const_t<Load>, LoadReading>> visit_fields(Load& l, Visit&& visit) {
  visit("force", l.force);
  visit("moment", l.moment);
  visit("contacts", l.contacts);
}

/// The contact manifolds that involve `structure`, into `out` (cleared first), in the contact
/// solver's canonical order: sums over them then do not depend on the order of Bullet's arrays,
/// which a world rebuilt from a checkpoint does not share.
void structure_manifolds(const btDispatcher& dispatcher, const btRigidBody* structure,
                         std::vector<const btPersistentManifold*>& out);

/// Accumulates contact impulses over the substeps of one step.
class LoadCell {
 public:
  /// Add the impulses of the Bullet step just taken (moment about `reference`, m); returns them
  /// (N s and N m s), which drive a moored structure in the next (dem/mooring/structure_motion.hpp).
  std::pair<Eigen::Vector3d, Eigen::Vector3d> accumulate(const btDispatcher& dispatcher, const btRigidBody* structure,
                                                         const Eigen::Vector3d& reference);

  /// Add an impulse on the structure that no Bullet contact carries (N s, and its moment about the reference
  /// point, N m s): the analytic level sheet's crushing load (dem/fracture/analytic_sheet.hpp).
  void add(const Eigen::Vector3d& impulse, const Eigen::Vector3d& angular_impulse) {
    impulse_ += impulse;
    angular_impulse_ += angular_impulse;
  }

  /// The mean force and moment over a step of length dt (s); resets the cell.
  LoadReading finish(double dt);

 private:
  Eigen::Vector3d impulse_ = Eigen::Vector3d::Zero();         // N s
  Eigen::Vector3d angular_impulse_ = Eigen::Vector3d::Zero(); // N m s
  int contacts_ = 0;
  std::vector<const btPersistentManifold*> touching_;  // scratch: the structure's manifolds
};

}  // namespace icedem
