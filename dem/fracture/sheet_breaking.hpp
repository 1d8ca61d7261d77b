// When and how the analytic level sheet breaks under a contact zone's load (docs/model/breakage.md, "Level ice
// cut by closed forms").
//
// The sheet's edge at a zone is a wedge of ice whose opening angle theta is measured from the outline: the
// angle the sheet fills about the zone's centre within the crack's distance, 2 |sheet ∩ disc(c, x*)| / x*^2
// (pi at a straight edge, less at a corner left by earlier pieces; more, in a notch, is taken as pi).
//   - An edge wider than a right angle cracks radially under the load first: the semi-infinite plate's
//     radial crack needs P_r = sigma_b h^2 / (6 m_y(a / l)), a fifth or less of what its wedges need
//     (plate_edge_load.hpp: 8.9 N against 2 x 16.6 N for the paper's ice over a = 0.1 l). The crack runs
//     through the centre along the load, and the two wedges of theta / 2 it leaves share the load: they
//     break together at 2 P_f(theta / 2).
//   - A wedge of a right angle or less breaks as Nevel's narrow wedge at P_f(theta) (wedge_bending.hpp),
//     whose radial cracking the beam idealisation cannot tell.
//   - A load wider than the wedges can take breaks the edge along one crack across its patch, the semi-infinite
//     plate's circumferential crack: P_c = sigma_b h^2 / (6 m_x(a / l)) at x_c(a / l) (plate_edge_load.hpp), taken
//     wherever it needs less than the wedges (past a / l of about 0.5 at a straight edge). The wedge's beam puts
//     the load along its axis, over its first a; a patch is spread across the axis, and past a ~ l / 2 the beam's
//     load (S -> 0) and crack (x* up to 3 l) run far above the plate's, which tend to Hetenyi's strip of width 2a
//     (0.73 sigma_b h^2 a / l at 1.11 l; a rubble floe pressed along the edge loads it so). The intact plate's
//     P_c stands for any edge: a corner narrower than pi would need less, which no closed form gives.
// The load is spread over the zone's half-width a, the wedge's patch; each wedge breaks across its axis at
// x*(a / l) from the centre, along a straight crack (the wedge's chord there): the beam's section of the largest
// moment is the arc of radius x*, but a rigid piece can only hinge about a straight crack, and one bounded by an
// arc would be locked against the sheet as it turns down (the hinge of a piece broken by bending is the crack's
// far face). What breaks off is each wedge's ice short of its chord (within 2 x* of the centre, in the part that
// holds it); across a patch, the ice short of the crack at x_c along the load, which spans the patch and whose ends
// run back to the edge at 45 degrees, as the two wedges' chords do at a straight edge (within x_c behind the
// centre); what is left of the sheet is its largest part, and any other part it falls into leaves with the pieces.
// What is left loses its parts narrower than the ice is thick (polygon_set.hpp's opening): a tongue of the sheet
// left between two cuts that nearly meet, a tenth of a degree wide, is crushed ice, not sheet (one such, its tip
// the next load's centre, held no ice within the next crack, and stopped the paper's tow at 43 s); a part joined
// to the sheet by a neck that narrow leaves with the pieces.
#pragma once

#include <array>
#include <cstdint>

#include <Eigen/Core>
#include <vector>

#include "dem/fracture/sheet_contact.hpp"
#include "dem/layout/polygon.hpp"

namespace icedem {

/// The ice and water the closed forms need.
struct SheetIce {
  double thickness = 0;         // m
  double elastic_modulus = 0;   // Pa
  double poisson_ratio = 0;     // -
  double bending_strength = 0;  // Pa
  double water_density = 0;     // kg/m^3
  double gravity = 0;           // m/s^2
};

/// An edge wider than this (rad) cracks radially first.
constexpr double kRadialCrackAngle = M_PI / 2;
/// Segments of the circle that bounds a break (2 x* about the centre), over a full turn.
constexpr int kCrackSegments = 16;

/// How the edge breaks at a zone (the output's /sheet/breaks crack).
enum class SheetCrack : int32_t {
  kWedge = 0,         // a corner of a right angle or less: one wedge, across its axis at x*
  kRadialWedges = 1,  // a wider edge cracks radially under the load; its two wedges of theta / 2 break together
  kAcrossPatch = 2,   // a load wider than the wedges can take: one crack across its patch at the plate's x_c
};

/// Where and at what load the sheet breaks at a zone.
struct SheetBreakPlan {
  double opening_angle = 0;              // rad, theta, in (0, pi]
  SheetCrack crack = SheetCrack::kWedge;
  double breaking_load = 0;              // N, normal to the sheet
  double crack_distance = 0;             // m, x* (x_c across a patch) from the zone's centre
};

/// The plan for the zone `contact` of the sheet `sheet` (m, ccw).
SheetBreakPlan plan_sheet_break(const Polygon& sheet, const SheetContact& contact, const SheetIce& ice);

/// Where the ice around holds the sheet (m): the edges of its outline at the start that other ice or the tank's
/// walls hold (a level sheet's sides and far end; not the edge the structure comes in from).
using HeldEdges = std::vector<std::array<Eigen::Vector2d, 2>>;

/// The sheet after a break and what broke off it.
struct SheetCut {
  Polygon sheet;                // m, what is left: the part the ice around holds (else the largest)
  std::vector<Polygon> pieces;  // m, each one piece of ice (convex or not), ccw
  double slivers = 0;           // m^2, what was left narrower than the thickness: crushed
};

/// Cut the sheet of ice `thickness` (m) at `contact` by `plan`. No pieces (the sheet as it was) where the load is
/// at a point of the outline that holds no ice within the crack, where the cut would leave a hole in the sheet, or
/// where Boost.Geometry's difference does not take the broken ice from the sheet to round-off. Of what is left, a
/// part that reaches one of the `held` edges stays held: only parts that reach none leave as pieces (without held
/// edges, all but the largest leave). A cut that would leave two or more held parts is not made (the sheet holds
/// that step): the sheet is one polygon, and making the far parts of a held sheet floes broke off tens of square
/// metres at a time.
SheetCut cut_sheet(const Polygon& sheet, const SheetContact& contact, const SheetBreakPlan& plan, double thickness,
                   const HeldEdges& held = {});

}  // namespace icedem
