// What a breakable floe was doing when one of its joints broke, and how close
// the floes near the structure came to breaking.
//
// The seed paper (Fig. 18) explains its failures by what the floe was doing:
// at f_ii = 0.3 an approaching floe presses a submerged floe against the cone
// and breaks it; at f_ii = 0.7 floes break while sliding on the slope. Every
// break is therefore recorded with the contacts of its floe in the Bullet step
// of the break, the depth of the joint, its distance from the structure and the
// joint's load ratio under every criterion, and classified into a mechanism.
//
// The largest load ratio a floe's joints reach tells whether few breaks come
// from loads that stay low or from loads that do not reach the joints; it is
// kept per floe, with the floe's closest approach to the structure.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "dem/fracture/joint_loads.hpp"
#include "dem/input/scene.hpp"

class btCollisionObject;

namespace icedem {

class World;

enum class BreakMechanism : int {
  kOnSlope = 0,       // the floe touches the structure and is not pressed under by another floe
  kPressedUnder = 1,  // the floe touches the structure, is submerged and another floe presses it
  kInRubble = 2,      // the floe does not touch the structure but is submerged: on or under the ice
                      // riding down the slope between it and the structure
  kInPack = 3,        // the floe does not touch the structure and is afloat
};
constexpr int kBreakMechanisms = 4;

/// Names of the mechanisms, indexed by their integer value (HDF5 attribute, summary keys).
const char* break_mechanism_name(BreakMechanism mechanism);

/// Another floe "presses" the broken floe when its contact force on the floe's
/// elements, downward plus towards the structure axis, exceeds this: the weight
/// of a tenth of a 0.15 m element (0.67 N), well above the drag that holds a
/// drifting floe against its neighbours (about 0.01 N at 0.07 m/s) and well
/// below the 45 N edge load that breaks a 0.6 m floe (docs/model/breakage.md).
constexpr double kPressingForce = 0.67;  // N

/// Floes whose joints come this close to the structure (distance_from_structure)
/// count as "near the structure" for the load-ratio distribution: a 0.6 m floe
/// with its edge on the cone, plus the floe behind it that presses it.
constexpr double kNearStructureDistance = 1.0;  // m

/// The state of a broken floe in the Bullet step of the break.
struct BreakContext {
  bool touching_structure = false;  // an element of the floe has a contact with the structure
  double structure_force = 0;       // N, magnitude of the structure's contact force on the floe
  double press_down = 0;            // N, other floes' net contact force on it, downward component (0 if upward)
  double press_toward = 0;          // N, the same, horizontal component towards the structure axis (0 if away)
  double depth = 0;                 // m, depth of the joint midpoint below the waterline (+ down)
  double distance = 0;              // m, distance_from_structure() of the joint midpoint
  std::array<double, kFailureModes> ratios{};  // load / capacity per criterion (FailureMode order)
};

/// Gather the context of a break of a joint of layout floe `floe_id` whose
/// midpoint is at `midpoint` (tank frame), from the contact manifolds of the
/// Bullet step of `h` seconds just taken.
BreakContext break_context(const Scene& scene, const World& world, int floe_id, const Eigen::Vector3d& midpoint,
                           const Eigen::Vector3d& structure_position, double h);

/// The same for the floe made of the collision objects `is_floe` picks (one rigid body, say).
BreakContext break_context(const Scene& scene, const World& world,
                           const std::function<bool(const btCollisionObject*)>& is_floe,
                           const Eigen::Vector3d& midpoint, const Eigen::Vector3d& structure_position, double h);

/// Horizontal distance of a point from the structure's section at the point's
/// height (the round profile, not its facets), m; 0 at or inside it.
double distance_from_structure(const Scene& scene, const Eigen::Vector3d& structure_position,
                               const Eigen::Vector3d& point);

/// The mechanism of a break. A joint is submerged when it is at least one ice
/// thickness deep (the floe's top half a thickness under water; afloat the
/// midpoint is 0.43 h deep). Touching the structure: pressed under if submerged
/// and another floe presses it by more than kPressingForce, else on the slope.
/// Not touching: in the rubble if submerged, else in the pack.
BreakMechanism classify_break(const BreakContext& context, double thickness);

/// How close a floe's joints came to failing: the largest load ratio under any
/// criterion over the run, and its closest approach to the structure.
struct FloeFailureMargin {
  double max_ratio = 0;                                         // 1
  double min_distance = std::numeric_limits<double>::infinity();  // m
};

}  // namespace icedem
