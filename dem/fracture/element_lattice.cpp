#include "dem/fracture/element_lattice.hpp"

#include <cmath>

#include <fmt/format.h>

#include "dem/core/errors.hpp"

namespace icedem {

ElementLattice make_element_lattice(const Polygon& outline, double element_size) {
  // the outline must be an axis-aligned rectangle centred at the origin
  double hx = 0, hz = 0;
  for (const Eigen::Vector2d& v : outline) hx = std::max(hx, std::abs(v.x())), hz = std::max(hz, std::abs(v.y()));
  bool rectangle = outline.size() == 4;
  for (const Eigen::Vector2d& v : outline)
    rectangle = rectangle && std::abs(std::abs(v.x()) - hx) < 1e-9 && std::abs(std::abs(v.y()) - hz) < 1e-9;
  if (!rectangle)
    throw InputError(fmt::format("fracture.element_size: breakable floes must be rectangles (a floe has {} "
                                 "vertices); use fracture.mode = \"off\" for polygonal floes",
                                 outline.size()));

  // whole numbers of elements along both sides
  auto count = [&](double side, const char* which) {
    const double n = side / element_size;
    const long k = std::lround(n);
    if (k < 1 || std::abs(n - k) > 1e-6)
      throw InputError(fmt::format("fracture.element_size = {} m: the floe's {} side of {} m (ice.floe_size) is not a "
                                   "whole number of elements ({:.3f}); choose an element size that divides it",
                                   element_size, which, side, n));
    return static_cast<int>(k);
  };
  const int nx = count(2 * hx, "x"), nz = count(2 * hz, "z");

  ElementLattice lattice;
  lattice.element_size = element_size;
  auto index = [nz](int i, int j) { return i * nz + j; };
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < nz; ++j)
      lattice.centres.emplace_back(-hx + (i + 0.5) * element_size, -hz + (j + 0.5) * element_size);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < nz; ++j) {
      const Eigen::Vector2d& c = lattice.centres[index(i, j)];
      if (i + 1 < nx)
        lattice.joints.push_back({index(i, j), index(i + 1, j), c + Eigen::Vector2d(element_size / 2, 0), {1, 0}});
      if (j + 1 < nz)
        lattice.joints.push_back({index(i, j), index(i, j + 1), c + Eigen::Vector2d(0, element_size / 2), {0, 1}});
    }
  }
  return lattice;
}

}  // namespace icedem
