// One mooring line as an elastic catenary, quasi-static, with the part of it that lies on the seabed:
// the fairlead's tension for the fairlead's position relative to the anchor, and the line's stiffness
// there. The closed form of Irvine (1981, "Cable Structures") as FAST's and MAP++'s catenary routines
// write it (Jonkman 2007, eq. 2-38 for the laid length): with the fairlead at horizontal distance XF and
// height ZF above the anchor, a line of unstretched length L, submerged weight w per metre, axial
// stiffness EA and seabed friction coefficient CB has, where part of it lies on the seabed (VF < w L,
// laid length L_B = L - VF / w),
//   XF = L_B + (HF / w) asinh(VF / HF) + HF L / EA - (CB w / (2 EA)) (L_B^2 - x_B^2),
//   ZF = (HF / w) (sqrt(1 + (VF / HF)^2) - 1) + VF^2 / (2 EA w),
// x_B = max(L_B - HF / (CB w), 0) where the tension on the seabed falls to zero; and hanging whole
// (VF >= w L),
//   XF = (HF / w) (asinh(VF / HF) - asinh((VF - w L) / HF)) + HF L / EA,
//   ZF = (HF / w) (sqrt(1 + (VF / HF)^2) - sqrt(1 + ((VF - w L) / HF)^2)) + (VF L - w L^2 / 2) / EA.
// (HF, VF) is found by Newton's method on these two equations with their analytic derivatives, from
// Peyrot and Goulois's (1979) first guess; a line so slack that it hangs straight down from the
// fairlead to the seabed (HF = 0) is its own case.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace icedem {

/// A mooring line's properties (SI).
struct CatenaryLine {
  double length = 0;            // m, unstretched
  double weight = 0;            // N/m, submerged weight per metre (weight in air minus buoyancy)
  double axial_stiffness = 0;   // N, EA
  double seabed_friction = 0;   // -, CB: the seabed's friction on the laid part (0: none)
};

/// The line's state for one fairlead position.
struct CatenaryState {
  double horizontal = 0;        // N, HF: the fairlead's horizontal tension (towards the anchor)
  double vertical = 0;          // N, VF: its vertical tension (downwards on the fairlead)
  double laid_length = 0;       // m, the unstretched length lying on the seabed
  double anchor_horizontal = 0; // N, HA: the horizontal tension at the anchor (friction takes the rest)
  double anchor_vertical = 0;   // N, VA: the vertical tension at the anchor (0 with a laid part)
  int iterations = 0;           // Newton's
  /// d(HF, VF) / d(XF, ZF), N/m: the line's stiffness at the fairlead in the line's vertical plane
  /// (the inverse of the equations' Jacobian); the transverse stiffness is HF / XF.
  Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();
};

/// The line's state with its fairlead `xf` m from the anchor horizontally and `zf` m above it. Throws
/// std::invalid_argument naming the value for a line or position that has none (a length, weight or
/// stiffness not positive; zf not positive; a fairlead farther than the line stretched taut can
/// reach is solved: the line stretches), std::runtime_error if Newton's method does not converge.
CatenaryState solve_catenary(const CatenaryLine& line, double xf, double zf);

/// The shape of a line in the state `state` (of solve_catenary for a fairlead `xf` m from its anchor):
/// `points` (>= 2) points (horizontal distance from the anchor, height above it), m, at equal steps of
/// unstretched length from the anchor to the fairlead, and the point where the line leaves the seabed
/// among them where part of it lies there. The same closed form as the solve, evaluated along the line
/// (the seabed part stretched by its tension, which friction lowers towards the anchor); its last point
/// is the fairlead to the solve's tolerance. A line slack enough to hang straight down (HF = 0) lies on
/// the seabed from the anchor to below the fairlead, slack; its laid part is drawn straight.
std::vector<Eigen::Vector2d> catenary_profile(const CatenaryLine& line, const CatenaryState& state, double xf, int points);

}  // namespace icedem
