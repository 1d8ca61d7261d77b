// Level ice (ice.cover = "level"): one continuous breakable sheet over the channel, the case an
// ice engineer checks first and the one ISO 19906 gives a load for (icedem cone-load).
//
// The sheet is a lattice of elements and joints like a breakable floe's (dem/fracture/ice_lattice.hpp),
// of the whole channel: 20 m x 4.8 m of 0.15 m squares is 4,300 elements and 8,500 joints, far
// more than a solve can carry each step. Only the ice near the structure moves: an element within
// fracture.lattice_radius of the structure axis is free, and one farther off is held where it
// lies (frozen: a fixed obstacle), as the sheet far from the structure is held by the ice around
// it. A joint is in the solver while it is intact and one of its two elements is free, so a free
// element next to the held sheet is clamped to it, and the island the solver sees is the free
// part alone. As the structure comes, the elements ahead of it are released; the intact sheet it
// has passed (along the channel's sides) is held again once it lies kLatticeHysteresis beyond the
// radius. Pieces that have broken off the sheet (fragments with no element on the sheet's sides or
// far end, where the ice around it holds it) move as floes of their own until the structure has
// left them behind: a piece all of which lies more than the radius plus kLatticeHysteresis behind
// the axis, along the structure's travel, is held whole where it lies. The structure moves away
// from it, so nothing it does can reach the structure again; left free, the pieces the tow leaves
// in the channel stay in one island with the rubble at the structure and awake, and the solve grows
// with the length towed (700 awake bodies and 1,900 contact points after 120 s of a tow, more than
// half of them over 2 m behind the axis: docs/model/breakage.md, "Level ice"). Pieces beside the
// structure or ahead of it stay free however far they are, so no held piece is a wall the
// structure can push ice against.
//
// The approximation is the held edge: a floating sheet bends as exp(-x / (sqrt(2) l_c)) away
// from its load (l_c, the characteristic length), so a radius of a few l_c leaves the clamp's
// stiffening of the sheet the structure bends small (the scenario check asks for the hull's
// radius plus two elements at least). Its size is measured by rerunning with a larger radius
// (docs/model/breakage.md, "Level ice").
#pragma once

#include <Eigen/Core>

#include "dem/input/scene.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// The layout of level ice: one rectangular floe over the channel's length and its width less
/// layout.min_gap on each side (clear of the mother ice).
Floe level_sheet_floe(const Scene& scene);

/// Add the sheet `floe` as a lattice with every element held and no joint in the solver, and
/// record it in world.level_sheet().
void add_level_sheet(World& world, const Scene& scene, const Floe& floe, int floe_id, double y);

/// Release the held elements within fracture.lattice_radius of the structure axis at `structure`,
/// hold again the free elements of the attached sheet beyond the radius plus kLatticeHysteresis
/// and the broken-off pieces wholly that far behind it along the travel (scene.structure.speed's sign),
/// and put in the solver the joints that join a free element (out of it those between two held
/// ones). Does nothing without a sheet.
void update_level_sheet(const Scene& scene, const Eigen::Vector3d& structure, World& world);

/// Whether `joint` is one of the sheet's that joins a free element to a held one: the clamp the
/// held sheet stands in for the ice around. It does not break: a rigid clamp bends the free sheet at
/// it harder than the continuing ice would, so that a sheet free within 1.2 m of the cone's axis
/// broke 30 % of its joints there (docs/model/breakage.md, "Level ice"); its overloads are counted
/// (/diagnostics/held_edge_overloads) to show a radius too small. False without a sheet.
bool at_held_edge(const World& world, const IceJoint& joint);

/// Put the sheet's joints in the solver, or take them out, as its elements' held states ask
/// (after the build, or a checkpoint's restore, set those states). Does nothing without a sheet.
void sync_level_sheet_joints(World& world);

}  // namespace icedem
