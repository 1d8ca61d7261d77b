// Breakable floes as lattices of square ice elements (seed paper, Fig. 5).
//
// A rectangular floe of Lx x Lz is cut into nx x nz square elements of side
// L_e; each element is joined to its neighbours along x and z by a fixed joint
// at the middle of their shared face. Pure geometry, in the floe's local
// (principal) frame; dem/world/world.cpp turns it into Bullet bodies and joints.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "dem/layout/polygon.hpp"

namespace icedem {

/// One joint between two elements of a lattice.
struct LatticeJoint {
  int a, b;                  // element indices, b is the +x or +z neighbour of a
  Eigen::Vector2d midpoint;  // m, (x, z) in the floe frame: middle of the shared face
  Eigen::Vector2d axis;      // unit, from a's centre towards b's centre
};

/// The elements and joints of one floe.
struct ElementLattice {
  double element_size;                   // m
  std::vector<Eigen::Vector2d> centres;  // m, (x, z) of each element in the floe frame
  std::vector<LatticeJoint> joints;
};

/// Cut a rectangular outline (axis-aligned, centred at the origin) into square
/// elements of side `element_size`. Throws InputError, naming
/// fracture.element_size and ice.floe_size, if the outline is not such a
/// rectangle or its sides are not whole multiples of the element size.
ElementLattice make_element_lattice(const Polygon& outline, double element_size);

}  // namespace icedem
