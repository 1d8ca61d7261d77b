// The analytic fracture stage (fracture.mode = "analytic"): rigid floes that split in two when
// the structure's load reaches the load that breaks them in bending, the fracture model of the
// managed-ice simulators that keep floes rigid (docs/model/breakage.md, "Rigid floes that split").
//
// After each Bullet step, for every awake rigid floe the structure touches: the structure's
// contact force on it, F (N, the step's impulses over its length), and where it acts, the
// impulse-weighted mean of the contact points. The floe is a beam on the water
// (dem/fracture/fracture_analytic.hpp) along the horizontal direction d from that point to its centroid,
// in the floe's plane: as long as the outline's extent along d, as wide as its area over that
// length. It breaks when the force normal to its plane, |F . n|, reaches the beam's breaking
// edge load, along the crack that load predicts: the line across d at the section of the
// largest moment. The two pieces move on with the floe's rigid-body motion. A floe does not
// split if a piece would be shorter along d, or narrower anywhere (a sliver cut off a corner),
// than kMinPieceThicknesses ice thicknesses: a block that small fails by crushing or shear,
// not by bending, and beam theory no longer holds for it.
#pragma once

#include <Eigen/Core>

#include "dem/fracture/fracture_state.hpp"
#include "dem/input/scene.hpp"
#include "dem/layout/polygon.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// Pieces shorter than this many ice thicknesses along the load are not split off.
constexpr double kMinPieceThicknesses = 3.0;

/// Where and at what load a rigid floe cracks when the structure loads it at one point.
struct CrackPlan {
  double breaking_load = 0;  // N, normal to the floe's plane, at the loaded edge
  double length = 0;         // m, the beam's: the outline's extent along `direction`
  double width = 0;          // m, the beam's: the outline's area / length
  double crack_distance = 0; // m, from the loaded edge along `direction`
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit, body frame (x, z): into the floe
  Eigen::Vector2d point = Eigen::Vector2d::Zero();       // m, body frame: the crack's point nearest
                                                         // the centroid (the crack runs across direction)
  bool splits = false;       // both pieces are at least kMinPieceThicknesses ice thicknesses long
                             // along `direction` and wide (min_width)
};

/// The crack of a floe of `outline` (body frame, centred on its centroid) loaded by the structure
/// at `contact` (body frame x, z), for the scene's ice and water.
CrackPlan plan_crack(const Scene& scene, const Polygon& outline, const Eigen::Vector2d& contact);

/// Check every awake rigid floe the structure touches after a Bullet step of `h` seconds that
/// ended at `time`, the structure's reference point at `structure`; split those whose load
/// reaches their breaking load (World::split_floe) and add their breaks to `fracture` (joint -1,
/// mode bending).
void check_splits(const Scene& scene, World& world, double time, const Eigen::Vector3d& structure, double h,
                  FractureState& fracture);

}  // namespace icedem
