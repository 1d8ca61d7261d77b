// The analytic level sheet (ice.cover = "level" with fracture.mode = "analytic"): level ice as one held sheet
// whose outline the structure cuts, piece by piece, by closed-form bending failure, in place of the lattice
// of elements (docs/model/breakage.md, "Level ice cut by closed forms").
//
// The sheet is held where it lies, as the lattice's sheet is beyond its radius: an obstacle for the floes in
// Bullet, as fixed convex prisms (kBoundary, like the mother ice) that start as squares of kTileSize and are
// cut with it. Each Bullet step, after the load cell has read the contacts:
//   1. the hull's crushed zones at the sheet's edge and their loads (sheet_contact.hpp); the crushing force
//      is an impulse on the structure that no Bullet contact carries, added to the load cell;
//   2. a zone whose load normal to the sheet reaches its breaking load (sheet_breaking.hpp) cuts the sheet:
//      the broken ice, less the crushed ice (all short of the line across the load that touches the hull's
//      larger section: the hull's overlap and the slivers beside it), leaves as rigid floes at
//      rest at the sheet's draft, a non-convex piece as its convex parts (convex_partition.hpp), a piece
//      smaller than kSmallestPiece thickness squared or narrower than the thickness counted as crushed; the prisms the cut crossed are
//      replaced by their convex parts outside it. The pieces can split again as rigid floes do
//      (fracture_split.hpp). The zones are found again after a cut, until none breaks.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dem/fracture/fracture_state.hpp"
#include "dem/fracture/sheet_breaking.hpp"
#include "dem/fracture/sheet_contact.hpp"
#include "dem/input/scene.hpp"
#include "dem/layout/polygon.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// Side of the square prisms the sheet starts as, m: a cut replaces the few it crosses.
constexpr double kTileSize = 1.0;
/// Pieces smaller than this many ice thicknesses squared, or narrower anywhere than the ice is thick, are crushed
/// ice, not floes: a block no wider than the ice is thick is rubble of crushing, and a body that small or thin is
/// the stiffest in the contact solve (a sliver 0.11 m x 0.029 m of the paper's 0.033 m ice, squeezed between the
/// cone and the held sheet, blew up at 54 m/s 52 s into the tow).
constexpr double kSmallestPiece = 1.0;

/// One break of the sheet, in the order they happened.
struct SheetBreakRecord {
  double time = 0;                                   // s
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // m, the zone's centre (x, z)
  double load = 0;                                   // N, the load normal to the sheet at the break
  SheetBreakPlan plan;
  double broken_area = 0;   // m^2, ice that left the sheet
  double crushed_area = 0;  // m^2, of it, crushed (in the hull's section, or in pieces too small)
  int pieces = 0;           // floes made
};

class AnalyticSheet {
 public:
  /// The sheet of `outline` (m, tank frame (x, z)) as fixed prisms in `world`; its pieces' floe ids start at
  /// `first_floe_id`.
  AnalyticSheet(const Scene& scene, World& world, const Polygon& outline, int first_floe_id);

  /// The Bullet step of `h` that ended at `time` with the structure's reference point at `structure` (its
  /// axis at the waterline): the crushing impulse on the structure (N s) and its moment about `structure`
  /// (N m s), and the breaks, into `fracture` (mode bending, floe -1, joint -1).
  std::pair<Eigen::Vector3d, Eigen::Vector3d> step(const Scene& scene, World& world, const Eigen::Vector3d& structure,
                                                  double time, double h, FractureState& fracture);

  const Polygon& outline() const { return outline_; }
  /// The fixed prisms' outlines (m, tank frame): the sheet's convex parts.
  std::vector<Polygon> prisms() const;
  const std::vector<SheetBreakRecord>& breaks() const { return breaks_; }

 private:
  struct Tile {
    Polygon outline;
    int body = -1;  // in World::bodies()
  };
  void cut(const Scene& scene, World& world, const SheetContact& contact, const SheetBreakPlan& plan,
           const HullInIce& hull, double time);
  void add_tile(World& world, const Polygon& outline);

  Polygon outline_;
  std::vector<Tile> tiles_;
  std::vector<SheetBreakRecord> breaks_;
  double bottom_ = 0;     // m, the ice's bottom face
  double thickness_ = 0;  // m
  double friction_ = 0;   // ice against ice
  int next_floe_id_ = 0;
};

/// The hull where the sheet meets it, for the structure's reference point at `structure`.
HullInIce hull_in_ice(const Scene& scene, const Eigen::Vector3d& structure);

/// The closed forms' ice and water, from the scene.
SheetIce sheet_ice(const Scene& scene);

}  // namespace icedem
