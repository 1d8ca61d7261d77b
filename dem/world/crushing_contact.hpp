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
#pragma once

#include <optional>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "dem/contact/crushing.hpp"

namespace icedem {

/// The largest normal impulse (N s) of each of the manifold's points over the step `h` (s), or
/// none (a rigid contact) if neither body is ice (world.hpp's Material kIce in the user index),
/// if `structure_only` and neither is the structure (kStructure), or if the manifold has no point.
std::optional<double> crushing_cap(const btPersistentManifold& manifold, const CrushingLaw& law, double h,
                                   bool structure_only);

}  // namespace icedem
