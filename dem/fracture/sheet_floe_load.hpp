// The loads the floes put on the analytic level sheet's edge (ice.cover = "level", fracture.mode = "analytic":
// docs/model/breakage.md, "Level ice cut by closed forms").
//
// The hull is not the only thing that bends the sheet: the pieces it broke off lie between it and the sheet's
// edge, and it pushes them against that edge, down its face and under it. The lattice's sheet breaks under any
// load on its elements; a held sheet that broke only where the hull touched it would let the rubble lock the
// cone against it (the first tows: 89 % of the surge load carried by the held sheet, 96 % of the steps locked).
// So each Bullet step the contact impulses the floes gave the sheet's prisms are read, and each floe's pressing
// on the edge is a load patch like a crushed zone's:
//   - its points within kEdgeReach thicknesses of the outline load the edge; farther in, a load is an interior
//     load of the plate, whose breaking load (Westergaard's) is several times the edge's: left out, and summed
//     apart so that a run says how much of the floes' load that was;
//   - its centre is the force-weighted mean of its points, taken to the nearest point of the outline;
//   - the wedge's axis (direction) is the sheet's inward normal there (at a corner, the mean of its two sides');
//   - its half-width is half its points' spread along the edge, but at least kLeastPatch thicknesses wide: a piece
//     touching at a corner (one point, no spread) is a point load, under which Nevel's wedge fails at the load
//     (its crack a few millimetres out), the cut breaks off nothing and the sheet stands while the piece, locked
//     between it and the cone, bears the cone without bound (the crushing tows' kilonewton steps); a load on a
//     plate's edge spreads over about the plate's thickness (Saint-Venant: plate theory holds a thickness away from
//     the load, as kEdgeReach says), and two ice edges touch over theirs;
//   - its bending force is the magnitude of the vertical force it puts on the sheet (the closed forms are those
//     of a linear plate on a linear foundation: up or down, the same load breaks it);
// and it breaks the sheet as a crushed zone does (sheet_breaking.hpp), with nothing crushed.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dem/fracture/sheet_contact.hpp"
#include "dem/layout/polygon.hpp"

class btCollisionObject;
class btDispatcher;
class btPersistentManifold;

namespace icedem {

/// Loads nearer the outline than this many ice thicknesses are edge loads: plate theory cannot tell a load a
/// thickness from the edge from one at it.
constexpr double kEdgeReach = 1.0;

/// A floe's load patch on the edge is at least this many ice thicknesses wide (its half-width at least half that).
constexpr double kLeastPatch = 1.0;

/// Whether a load at `at` (m, (x, z)) is on the edge of the sheet `sheet` (m, ccw) of ice `thickness` (m): within
/// kEdgeReach thicknesses of its outline.
bool at_edge(const Polygon& sheet, const Eigen::Vector2d& at, double thickness);

/// One contact point's force on the sheet.
struct SheetLoadPoint {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();     // m, (x, z) of the point on the sheet
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // N, on the sheet, over the step
  int floe = -1;                                     // the ice body that pushes (its place in World::floes())
};

/// A manifold between an ice body and one of the sheet's prisms: the floe (its place in World::floes()) and whether
/// the prism is the manifold's body 0; floe -1 for any other manifold (two prisms, a prism and another fixed body,
/// no prism, no points).
struct PrismContact {
  int floe = -1;
  bool prism_first = false;
};
PrismContact prism_contact(const btPersistentManifold& manifold, const std::vector<const btCollisionObject*>& prisms);

/// The forces the ice bodies gave the fixed bodies `prisms` (sorted) over the Bullet step of `h` (s) just
/// solved, in the solver's canonical order of manifolds.
std::vector<SheetLoadPoint> floe_loads_on_prisms(const btDispatcher& dispatcher,
                                                 const std::vector<const btCollisionObject*>& prisms, double h);

/// The floes' edge loads on the sheet `sheet` (m, ccw) of ice `thickness` (m): one patch per floe, as above
/// (zone empty; the forces are those on the sheet: horizontal_force its push into the sheet along `direction`).
struct FloePatches {
  std::vector<SheetContact> patches;
  std::vector<int> floes;        // the floe of each patch
  double interior_vertical = 0;  // N, the magnitude of the vertical force of points farther in, summed
};
FloePatches floe_patches(const Polygon& sheet, const std::vector<SheetLoadPoint>& points, double thickness);

}  // namespace icedem
