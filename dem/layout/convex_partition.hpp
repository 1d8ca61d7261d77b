// A simple polygon split into convex parts, by CGAL's partitioning: a piece of level ice that is not convex
// becomes as many rigid floes as its fewest convex parts (a floe's collision shape and its exact
// hydrostatics are those of a convex prism: dem/world/floe_shape.hpp).
//
// The fewest parts (Greene's dynamic programme, O(n^4)) for outlines of up to kOptimalPartitionVertices
// vertices, the pieces' size; the Hertel-Mehlhorn partition (at most four times the fewest, O(n) after a
// triangulation) above it, the sheet's outline near the structure. Each diagonal of either runs between two
// vertices of the outline and starts at a reflex one, where a notch in the ice concentrates its stress.
#pragma once

#include <vector>

#include "dem/layout/polygon.hpp"

namespace icedem {

/// Outlines of more vertices than this are partitioned by Hertel-Mehlhorn, not optimally.
constexpr std::size_t kOptimalPartitionVertices = 48;

/// The convex parts of the simple polygon `outline` (either orientation), each ccw; the outline itself if it
/// is convex. Their areas sum to the outline's to round-off.
std::vector<Polygon> convex_parts(const Polygon& outline);

}  // namespace icedem
