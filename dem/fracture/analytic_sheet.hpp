// The analytic level sheet (ice.cover = "level" with fracture.mode = "analytic"): level ice as one held sheet
// whose outline the structure cuts, piece by piece, by closed-form bending failure, in place of the lattice
// of elements (docs/model/breakage.md, "Level ice cut by closed forms").
//
// The sheet is held where it lies, as the lattice's sheet is beyond its radius: an obstacle for the floes in
// Bullet, as fixed convex prisms (kHeldIce, world.hpp): the sheet within each square cell of
// kTileSize, as its fewest convex parts. Each Bullet step, after the load cell has read the contacts:
//   1. the hull's crushed zones at the sheet's edge and their loads (sheet_contact.hpp); the crushing force
//      is an impulse on the structure that no Bullet contact carries, added to the load cell;
//   2. the floes' loads on the sheet's edge over the step, each floe's a patch (sheet_floe_load.hpp): the rubble
//      the hull pushes against the sheet bends it too. Each point of a floe's push was bounded inside the solve by
//      its patch's breaking load (sheet_edge_bound.hpp), so that a piece cannot lock between the hull and the sheet;
//   3. a zone or patch whose load normal to the sheet reaches its breaking load (sheet_breaking.hpp), or a floe's
//      patch one of whose points the bound held, cuts the sheet:
//      the broken ice, less the crushed ice under a zone (all short of the line across the load that touches the hull's
//      larger section: the hull's overlap and the slivers beside it), leaves as rigid floes at
//      rest at the sheet's draft, a non-convex piece as its convex parts (convex_partition.hpp), a piece
//      smaller than kSmallestPiece thickness squared or narrower than the thickness counted as crushed; each cell the
//      cut reached is partitioned again, from its square's sheet: its prisms are not cut again and again, which
//      left fans of slivers along the broken channel's sides (a piece of 0.13 m under the sheet touched some 30 of
//      them, and the sheet's contacts were most of the solve's rows). The pieces can split again as rigid floes do
//      (fracture_split.hpp). The zones and patches are found again after a cut, until none breaks; a patch
//      that broke the sheet is spent (its floe's push left with the piece).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dem/fracture/fracture_state.hpp"
#include "dem/fracture/sheet_break_record.hpp"
#include "dem/fracture/sheet_breaking.hpp"
#include "dem/fracture/sheet_contact.hpp"
#include "dem/fracture/sheet_edge_bound.hpp"
#include "dem/fracture/sheet_floe_load.hpp"
#include "dem/input/scene.hpp"
#include "dem/layout/polygon.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// Side of the square cells the sheet's prisms are made in, m: a cut partitions again the few it reaches.
constexpr double kTileSize = 1.0;
/// Pieces smaller than this many ice thicknesses squared, or narrower anywhere than the ice is thick, are crushed
/// ice, not floes: a block no wider than the ice is thick is rubble of crushing, and a body that small or thin is
/// the stiffest in the contact solve (a sliver 0.11 m x 0.029 m of the paper's 0.033 m ice, squeezed between the
/// cone and the held sheet, blew up at 54 m/s 52 s into the tow).
constexpr double kSmallestPiece = 1.0;

class AnalyticSheet {
 public:
  /// The sheet of `outline` (m, tank frame (x, z)) as fixed prisms in `world`; its pieces' floe ids start at
  /// `first_floe_id`. Bounds the floes' pushes on its edge in `world`'s contact solve (sheet_edge_bound.hpp): the
  /// world's solver holds this object, which must outlive its steps and not move.
  AnalyticSheet(const Scene& scene, World& world, const Polygon& outline, int first_floe_id);
  AnalyticSheet(const AnalyticSheet&) = delete;
  AnalyticSheet& operator=(const AnalyticSheet&) = delete;

  /// The Bullet step of `h` that ended at `time` with the structure's reference point at `structure` (its
  /// axis at the waterline): the crushing impulse on the structure (N s) and its moment about `structure`
  /// (N m s), and the breaks, into `fracture` (mode bending, floe -1, joint -1).
  std::pair<Eigen::Vector3d, Eigen::Vector3d> step(const Scene& scene, World& world, const Eigen::Vector3d& structure,
                                                  double time, double h, FractureState& fracture);

  /// Cut the sheet again as `record` says it was cut (its pieces made as floes at rest): a checkpoint's replay of
  /// the run's breaks, in order, into the world built from the scene. Throws InputError if the cut does not
  /// make the pieces the record counts (another scene, or another build).
  void replay(World& world, const SheetBreakRecord& record);

  const Polygon& outline() const { return outline_; }
  /// The fixed prisms' outlines (m, tank frame): the sheet's convex parts.
  std::vector<Polygon> prisms() const;
  const std::vector<SheetBreakRecord>& breaks() const { return breaks_; }
  /// The sheet's outline after breaks()[i].
  const Polygon& outline_after(std::size_t i) const { return outlines_after_.at(i); }

  /// The vertical impulses the floes gave the sheet so far, N s: at its edge (patches) and farther in (left out).
  struct FloeLoadTotals {
    double edge = 0;
    double interior = 0;
  };
  const FloeLoadTotals& floe_load_totals() const { return floe_totals_; }
  /// The zones and patches at or over their breaking load that the last step() did not cut: the cut would have
  /// parted the held sheet or left a hole in it, no ice lay within the crack, or Boost.Geometry's difference did not
  /// take the broken ice (cut_sheet's refusals). The sheet holds them that step.
  int holds() const { return holds_; }
  void set_floe_load_totals(const FloeLoadTotals& totals) { floe_totals_ = totals; }

 private:
  struct Tile {
    Polygon outline;
    int body = -1;  // in World::bodies()
    int cell = -1;  // in cells_
  };
  // cut the sheet as `record` says (its load, plan and, for a hull's zone, the hull, whose crushed ice does not
  // become floes), make the pieces floes and keep the record with what broke off; false where no ice lay within
  // the crack (nothing done)
  bool cut(World& world, SheetBreakRecord record);
  // the cell's prisms: `sheet_in_cell` (the sheet within its square) as convex parts
  void tile_cell(World& world, int cell, const std::vector<Polygon>& sheet_in_cell);
  // the prisms' bodies, sorted (what floe_loads_on_prisms reads)
  std::vector<const btCollisionObject*> prism_bodies(const World& world) const;

  Polygon outline_;
  HeldEdges held_;              // the start outline's edges the ice around holds: all but the structure's way in
  std::vector<Polygon> cells_;  // the squares of kTileSize over the sheet at the start
  std::vector<Tile> tiles_;
  std::vector<SheetBreakRecord> breaks_;
  std::vector<Polygon> outlines_after_;  // per break, for the output
  FloeLoadTotals floe_totals_;
  int holds_ = 0;  // in the last step()
  double bottom_ = 0;     // m, the ice's bottom face
  double thickness_ = 0;  // m
  double friction_ = 0;   // ice against ice
  int next_floe_id_ = 0;
  bool sleeping_ = false;  // activation.sleeping: the pieces are made awake either way
  SheetEdgeBound edge_bound_;  // the floes' pushes on the edge, bounded in the solve; installed in the world's solver
};

/// The hull where the sheet meets it, for the structure's reference point at `structure`.
HullInIce hull_in_ice(const Scene& scene, const Eigen::Vector3d& structure);

/// The closed forms' ice and water, from the scene.
SheetIce sheet_ice(const Scene& scene);

}  // namespace icedem
