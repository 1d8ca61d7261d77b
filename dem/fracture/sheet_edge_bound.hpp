// The analytic level sheet's edge bears at most its breaking load, inside the contact solve (ice.cover = "level",
// fracture.mode = "analytic": docs/model/breakage.md, "Level ice cut by closed forms").
//
// The floes' pushes on the sheet's edge break it when a floe's patch bears its breaking load (sheet_floe_load.hpp,
// sheet_breaking.hpp), but that is read after the step: within the step the held sheet is rigid. A piece the structure
// presses down on the edge is then locked between them and bears whatever the structure's contact can put on it: the
// crushing tows' largest loads (1.0 to 1.3 kN on the cone at single steps, against a mean of 32 N) were such steps,
// the piece pushing the edge at 380 to 830 N against a breaking load of 26 to 28 N. Ice does not bear more than it
// breaks at, so before each island's solve, each floe's points on the edge (within kEdgeReach thicknesses of the
// outline) make its patch as they will after the step (one patch per floe, its width their spread), the plan gives
// its breaking load P, and each point's normal impulse is bounded so that the patch's push normal to the sheet is at
// most P over the step:
//   |sum over the floe's points of J_y| <= h P    (J a point's impulse on the sheet, normal and friction; y up)
// The solve takes a bound per row, not on a sum of rows, so each point is first bounded by the whole on its normal's
// part, r_N |n_y| <= h P (none where n_y = 0: a point pressing the edge's face sideways bends nothing by its normal,
// and the held sheet takes an in-plane push rigidly); where the solve's answer puts more than h P on a floe's patch
// (a floe pressing along the edge at many points: a single step of 414 N on the cone, a patch at 5.7 times its
// breaking load; with the normals alone bounded, a step of 501 N on the cone at a patch 2.9 times its breaking load,
// the friction's part of its push not held), each of its points' normal impulses is bounded by its share of h P (its
// impulse times h P over the sum, tighten), which bounds its friction too, and the island is solved again from that
// answer (dem/world/contact_bound.hpp). A floe whose patch's push reached its bound breaks the sheet at its patch after
// the step (floes_at_bound: its sum at h P, to kPatchAtBound where tighten held it; not a floe one of whose points is
// at a cap while the patch's sum is below), even where the patch the forces make (its centre their resultant's) plans
// a higher load than the one the points made before the solve (at a corner, whose opening angle depends on the
// centre): the edge gave way, so it broke.
#pragma once

#include <unordered_map>
#include <vector>

#include "dem/fracture/sheet_breaking.hpp"
#include "dem/layout/polygon.hpp"
#include "dem/world/contact_bound.hpp"

class btCollisionObject;

namespace icedem {

/// How near its bound (relative) the push of a floe's patch that tighten held must be to have given way (one it did not
/// hold: ContactSolver::kAtBound, the solve's own): the passes that hold a patch leave its sum within about 1 % of the
/// bound (each cuts the excess about by half where the face's points partly stick and take up what the others shed:
/// 0.9 % above after the solver's eight solves, tests/physics/test_sheet_edge_bound.cpp).
constexpr double kPatchAtBound = 0.02;

class SheetEdgeBound : public ContactBound {
 public:
  explicit SheetEdgeBound(const SheetIce& ice) : ice_(ice) {}

  /// The sheet as it stands: its outline (m, ccw) and its prisms' bodies (sorted by address).
  void set_sheet(const Polygon& outline, std::vector<const btCollisionObject*> prisms);

  void begin_step() override { caps_.clear(); }
  void prepare(btPersistentManifold* const* manifolds, int count, double h) override;
  std::optional<double> cap(const btManifoldPoint& point) const override;
  bool tighten(const std::vector<BoundedImpulse>& impulses) override;

  /// The floes (their place in World::floes()) whose patch's push on the edge reached its bound in the step just
  /// solved (its |sum of J_y| at h P; to kPatchAtBound where tighten held it), in increasing order. Call before the
  /// world changes (a cut removes prisms, and their contact points).
  std::vector<int> floes_at_bound() const;

 private:
  struct Bound {
    double cap = kUnbounded;  // N s, on the point's normal impulse
    int floe = -1;
    double patch_bound = 0;   // N s, h P of its floe's patch: on |the sum over the patch of J_y|
    double sign = 1;          // +1 where the sheet's prism is body 0 of the point's manifold, -1 where body 1
    bool lowered = false;     // its cap lowered to its share of the patch's bound (tighten)
  };
  SheetIce ice_;
  Polygon outline_;
  std::vector<const btCollisionObject*> prisms_;
  std::unordered_map<const btManifoldPoint*, Bound> caps_;  // this step's bounded points
};

}  // namespace icedem
