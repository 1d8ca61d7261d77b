// Breakable floes as lattices of elements glued by fixed joints (seed paper,
// Fig. 5): building a floe's lattice, breaking its joints into fragments, and
// the lattice region, where a floe far from the structure is one rigid body
// (its stand-in) and becomes its lattice as the structure comes near.
//
// An intact lattice that has left the region becomes the stand-in again; a
// broken one stays a lattice. A dormant lattice's elements and joints exist but
// are not in the Bullet world.
#pragma once

#include <Eigen/Geometry>

#include "dem/fracture/element_lattice.hpp"
#include "dem/fracture/outline_lattice.hpp"
#include "dem/input/scene.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// A floe's element lattice in its principal frame (elements are squares there), and the
/// yaw of that frame relative to the floe's outline. Throws InputError naming
/// fracture.element_size if the outline cannot be cut into elements (not a rectangle,
/// or not a whole number of elements across).
ElementLattice floe_lattice(const Polygon& outline, double element_size, double& principal_yaw_out);

/// Whether a floe is cut into the paper's lattice (floe_lattice): square elements along its
/// principal axes (fracture.lattice_angle 0), and an outline that is a rectangle a whole
/// number of them across in its principal frame. Every other breakable floe is an outline
/// lattice (floe_outline_lattice).
bool paper_lattice(const Polygon& outline, const FractureSettings& fracture);

/// A floe's outline lattice (dem/fracture/outline_lattice.hpp) in the grid's frame (the floe's
/// principal frame turned by fracture.lattice_angle), and the yaw of that frame relative to the
/// floe's outline.
OutlineLattice floe_outline_lattice(const Polygon& outline, const FractureSettings& fracture,
                                    double& principal_yaw_out);

/// Add a breakable floe: its elements (squares of fracture.element_size in the
/// floe's principal frame, or the outline lattice's elements) at height `y`, joined at the
/// middle of each shared face with the fracture settings' softness (elastic joints: springs
/// of `ice`);
/// with fracture.lattice_radius > 0 a stand-in in the world and the lattice
/// dormant. `friction`: ice against ice. `held`: level ice (dem/fracture/level_ice.hpp), its
/// elements in the world held where they lie (frozen) and its joints out of the solver, whatever
/// the radius.
void add_lattice_floe(World& world, const Floe& floe, int floe_id, double y, const FractureSettings& fracture,
                      const IceSettings& ice, double friction, bool held = false);

/// Put a dormant lattice in the world in place of its stand-in: every element
/// takes the rigid-body motion of the stand-in at its place, the joints are
/// added intact, and the stand-in leaves the world.
void wake_lattice(World& world, DormantLattice& lattice);

/// The reverse, for a lattice with every joint intact and no frozen element:
/// the stand-in returns at the elements' centre of mass with the rigid motion of
/// their momentum (their mean motion for equal squares), and the elements and
/// joints leave the world. Returns false (and does nothing) if the lattice is
/// broken or frozen.
bool make_dormant(World& world, DormantLattice& lattice);

/// Centre of mass of a breakable floe with a lattice region: its stand-in's while
/// dormant, else the mean of its (equal) elements' centres, or for unequal elements
/// the mean of the stand-in centres their poses imply.
btVector3 lattice_centre(const World& world, const DormantLattice& lattice);

/// Remove a joint from the solver and recompute its floe's fragments, so that
/// pieces that came apart collide with each other.
void break_joint(World& world, IceJoint& joint);

/// Pose of an output body (a rigid floe or an element): an element of a
/// dormant lattice follows its stand-in.
Eigen::Isometry3d output_pose(const World& world, const FloeBody& floe);

/// Whether an output body is being simulated (awake), through its stand-in while dormant.
bool output_awake(const World& world, const FloeBody& floe);

}  // namespace icedem
