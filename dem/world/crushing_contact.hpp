// The crushing law's bound (dem/contact/crushing.hpp) for Bullet's contact manifolds:
// the nominal contact area of a manifold from the shapes of its two bodies and the
// plane of the contact.
//
//  - Ice against a body that does not crush (the structure, a wall): the overlap seen
//    along the contact's normal (Daley's nominal area): the ice's section by the other
//    body's surface (the plane through Bullet's point on that body with the contact's
//    normal: the structure's facet there) where it lies over the other body's section by
//    the parallel plane through the ice's deepest point (on the faceted cone, the band of
//    the hull within the penetration; the structure's convex pieces summed).
//  - Ice against ice: the one of smaller section crushes (a corner pressed into a straight
//    edge); the larger of the areas the two pieces' sections share on the planes of the two
//    bodies' surfaces.
// The manifold's overlap is its deepest point's, and its force is shared by its points:
// each point's normal impulse is bounded by 1/n of the manifold's h F.
//
// The crushed ice (CrushedIce): the overlap a manifold reached while it crushed (its rows at
// their bound) is ice that has crushed, and stays; overlap beyond it is not. A contact below
// its bound is a rigid one, yet its overlap can still grow: the velocity rows hold the
// manifold's few points apart along their normals, and a piece sliding or turning on the hull
// brings other corners in (a 33 mm piece pressed up under the downward cone by the rubble
// went 4 cm into the hull at a hundredth of its bound in 4 s, and then through it, where its
// section was empty and the bound 0). The position pass pushes out what lies beyond the
// crushed depth, as it pushes out a rigid contact's whole overlap.
#pragma once

#include <optional>
#include <unordered_map>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "dem/contact/crushing.hpp"

namespace icedem {

/// A manifold's overlap: its deepest point's depth inside the other body, m (0 if none overlaps).
double manifold_overlap(const btPersistentManifold& manifold);

/// The crushed depth of each crushing manifold (m), carried from step to step.
class CrushedIce {
 public:
  /// What a manifold ended a step with.
  struct Memory {
    const btCollisionObject* a = nullptr;  // the manifold's bodies: a manifold Bullet made anew at the
    const btCollisionObject* b = nullptr;  // address of another is another
    double depth = 0.0;                    // m, the crushed depth
    bool crushing = false;                 // its rows ended the step at their bound
  };

  /// A new step: what the last one ended with is what this one starts from (Bullet's prepareSolve).
  void next_step();

  /// The crushed depth of `manifold` in this step, m: if it crushed in the last step, the larger
  /// of its crushed depth and its overlap now (the ice it crushed over the step); else the smaller
  /// (a contact below its bound crushes nothing, and one that opened has left its crushed ice);
  /// its overlap now if it was not in contact in the last step (it came into contact within it).
  double depth(const btPersistentManifold& manifold);

  /// Whether the manifold's rows ended this step at their bound (after depth).
  void set_crushing(const btPersistentManifold& manifold, bool crushing);

  /// What `manifold` ended the last step with (a checkpoint's), or null.
  const Memory* remembered(const btPersistentManifold* manifold) const;
  /// Remember `memory` for `manifold` as if the last step had ended with it (a world rebuilt from a checkpoint).
  void remember(const btPersistentManifold* manifold, const Memory& memory);

 private:
  std::unordered_map<const btPersistentManifold*, Memory> previous_, current_;
};

/// Which contacts of a floe crush (contact.crushing_contacts); the rest are rigid.
enum class CrushingScope {
  kStructure,             // with the structure ("structure")
  kStructureAndHeldIce,   // with the structure and the held level sheet's edge ("structure_and_sheet")
  kAllIce,                // every contact of ice, between floes too ("all")
};

/// The largest normal impulse (N s) of each of the manifold's points over the step `h` (s), or
/// none (a rigid contact) if neither body is a floe (world.hpp's Material kIce in the user index),
/// if the other body is not one `scope` crushes against, or if the manifold has no point.
std::optional<double> crushing_cap(const btPersistentManifold& manifold, const CrushingLaw& law, double h,
                                   CrushingScope scope);

}  // namespace icedem
