// The ice the structure has left behind: out of the run past activation.leave_behind.
//
// Behind a structure towed through level ice the broken channel grows with the tow, and nothing in it
// sleeps: the rubble passing the structure pushes the pieces behind it back as one column, which creeps
// (docs/model/breakage.md, "The jam"), and its cost grows with the tow. With activation.leave_behind = L > 0,
// a rigid floe (a whole floe or a piece of one; never a lattice's element or stand-in) whose every point lies
// more than L behind the structure's axis, against its travel, leaves the run for good: out of Bullet's world
// where it lies, recorded as left (/snapshots/rows/awake 3) and counted in the ice's mass. The approximation
// is that the column beyond L pushes nothing back: a floe nearer the structure meets open water there. A
// frozen column there instead (activation.freeze_outside_region) raised the level tow's peaks many times
// over; whether leaving it behind moves the loads is measured against L, not assumed.
#pragma once

#include <Eigen/Core>

#include "dem/input/scene.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// Take out of the run the rigid floes that lie wholly more than activation.leave_behind behind the
/// structure's reference point `structure`. Call after each step; does nothing when the key is 0.
/// Returns how many left in this call.
int leave_behind(const Scene& scene, const Eigen::Vector3d& structure, World& world);

}  // namespace icedem
