// Convex partitions by CGAL; see convex_partition.hpp.
#include "dem/layout/convex_partition.hpp"

#include <iterator>
#include <list>
#include <stdexcept>
#include <string>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>

namespace icedem {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Partition_traits_2<Kernel>;
using CgalPolygon = Traits::Polygon_2;

}  // namespace

std::vector<Polygon> convex_parts(const Polygon& outline) {
  const Polygon simple = without_degenerate_vertices(outline);  // CGAL wants none
  if (simple.size() < 3) return {};
  if (is_convex(simple)) return {make_ccw(simple)};
  // CGAL wants its own counter-clockwise: in a plot of (x, z) with z up, clockwise seen from above
  Polygon ordered = make_ccw(simple);
  CgalPolygon polygon;
  for (auto it = ordered.rbegin(); it != ordered.rend(); ++it) polygon.push_back(Traits::Point_2(it->x(), it->y()));
  if (!polygon.is_simple())  // CGAL's partition asserts it
    throw std::invalid_argument("convex_parts: the outline of " + std::to_string(polygon.size()) +
                                " vertices is not simple");
  std::list<CgalPolygon> parts;
  if (polygon.size() <= kOptimalPartitionVertices)
    CGAL::optimal_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(), std::back_inserter(parts));
  else
    CGAL::approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(), std::back_inserter(parts));
  std::vector<Polygon> out;
  for (const CgalPolygon& part : parts) {
    Polygon p;
    for (auto v = part.vertices_begin(); v != part.vertices_end(); ++v) p.emplace_back(v->x(), v->y());
    out.push_back(make_ccw(std::move(p)));
  }
  return out;
}

}  // namespace icedem
