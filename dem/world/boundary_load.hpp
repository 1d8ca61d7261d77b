// The load the fixed boundaries take off the structure: a pack locked against a wall.
//
// A pack of rigid floes pushed by the structure against a fixed body (the channel's end
// wall, the tank's side walls, mother ice, a frozen floe) carries the structure's push
// into that body: the load the structure then measures is set by the confinement, not
// by the ice (docs/model/contact_problems.md, "Locked packs"). After each Bullet step,
// the contact impulses that fixed bodies give ice bodies of the islands touching the
// structure are summed along the structure's travel: the boundary load, positive when
// it resists the push as the structure's surge load does. A step is locked when the
// boundaries carry at least kLockedShare of the structure's surge load.
#pragma once

class btDispatcher;
class btRigidBody;

namespace icedem {

/// Share of the structure's surge load the fixed boundaries must carry for a step to
/// count as locked: more than half of the push goes into the boundary, so the load is
/// more the boundary's than the ice's.
inline constexpr double kLockedShare = 0.5;

/// Accumulates the boundary load over the substeps of one step.
class BoundaryLoad {
 public:
  /// Add the Bullet step just taken: `travel` is the sign of the structure's surge
  /// velocity (+1 or -1).
  void accumulate(const btDispatcher& dispatcher, const btRigidBody* structure, double travel);

  /// The mean boundary load over a step of length dt (s), N; resets.
  double finish(double dt);

 private:
  double impulse_ = 0;  // N s, along the structure's travel, resisting it
};

/// Whether a step with this boundary load and surge load (N) is locked.
inline bool locked(double boundary_load, double surge_load) {
  return surge_load > 0 && boundary_load >= kLockedShare * surge_load;
}

}  // namespace icedem
