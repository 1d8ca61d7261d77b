// The mooring room (dem/mooring/): the elastic catenary of one line against its closed forms (the
// inextensible line's tension for a given span, an elastic line's tension and stiffness, the stiffness
// against the solver's own finite differences, a line hanging whole, a slack line, the seabed's
// friction, bad input refused), and a spread of lines on a body against the reference's solved offsets.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "dem/mooring/catenary.hpp"
#include "dem/mooring/spread.hpp"

namespace icedem {
namespace {

// the example line: 6 m, 2 N/m submerged, its fairlead 2 m above the anchor
constexpr double kLength = 6.0, kWeight = 2.0, kHeight = 2.0;

CatenaryLine line(double ea, double cb = 0) { return CatenaryLine{kLength, kWeight, ea, cb}; }

// An inextensible line partly on the seabed, in closed form from its horizontal tension: the hanging
// part's vertical tension VF = sqrt(w^2 ZF^2 + 2 w ZF HF), and its span XF = L - VF/w + (HF/w) asinh(VF/HF)
TEST(Catenary, AnInextensibleLineReturnsTheTensionItsSpanWasMadeFrom) {
  // the reference's round trip: (HF, XF) = (0.5, 4.48575), (1, 4.69673), (2, 4.93432), (4, 5.16981) N, m
  const double table[][2] = {{0.5, 4.48575}, {1.0, 4.69673}, {2.0, 4.93432}, {4.0, 5.16981}};
  for (const auto& [hf, xf_table] : table) {
    const double vf = std::sqrt(kWeight * kWeight * kHeight * kHeight + 2 * kWeight * kHeight * hf);
    const double xf = kLength - vf / kWeight + hf / kWeight * std::asinh(vf / hf);
    EXPECT_NEAR(xf, xf_table, 5e-6) << "the closed form reproduces the table's five digits";
    // EA 1e12 N: the stretch, HF L / EA, is 1e-11 m at most: the inextensible line to round-off
    const CatenaryState s = solve_catenary(line(1e12), xf, kHeight);
    EXPECT_NEAR(s.horizontal, hf, 1e-8 * hf) << "HF " << hf;
    EXPECT_NEAR(s.vertical, vf, 1e-8 * vf);
    EXPECT_NEAR(s.laid_length, kLength - vf / kWeight, 1e-8);
    EXPECT_DOUBLE_EQ(s.anchor_horizontal, s.horizontal) << "no seabed friction: the anchor takes all of HF";
    EXPECT_EQ(s.anchor_vertical, 0.0);
  }
}

// The reference's elastic example (EA 5e4 N), derived with the same equations: tensions, laid length and
// stiffness to the digits given
TEST(Catenary, AnElasticLinesTensionAndStiffness) {
  struct Row { double xf, hf, vf, laid, k[2][2]; };
  const Row rows[] = {{5.4, 8.658, 9.233, 1.384, {{32.51, 14.08}, {14.08, 8.84}}},
                      {5.5, 12.937, 10.930, 0.535, {{55.83, 20.42}, {20.42, 10.57}}}};
  for (const Row& r : rows) {
    const CatenaryState s = solve_catenary(line(5e4), r.xf, kHeight);
    EXPECT_NEAR(s.horizontal, r.hf, 6e-4) << r.xf;
    EXPECT_NEAR(s.vertical, r.vf, 6e-4);
    EXPECT_NEAR(s.laid_length, r.laid, 6e-4);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) EXPECT_NEAR(s.stiffness(i, j), r.k[i][j], 6e-3) << i << j;
    EXPECT_LT(s.iterations, 30);
  }
  // four such lines at 45, 135, 225 and 315 degrees: K11 = 2 (k_HH + HF / XF) = 68.2 N/m at 5.4 m
  const CatenaryState s = solve_catenary(line(5e4), 5.4, kHeight);
  EXPECT_NEAR(2 * (s.stiffness(0, 0) + s.horizontal / 5.4), 68.2, 0.05);
}

// The stiffness is the inverse of the equations' analytic Jacobian: it must be what solving again at a
// nearby position gives (central differences, 1e-6 m: their error is of order 1e-12 relative)
void expect_stiffness_is_the_solvers(const CatenaryLine& l, double xf, double zf) {
  const CatenaryState s = solve_catenary(l, xf, zf);
  const double d = 1e-6;
  for (int j = 0; j < 2; ++j) {
    const CatenaryState plus = solve_catenary(l, xf + (j == 0 ? d : 0), zf + (j == 1 ? d : 0));
    const CatenaryState minus = solve_catenary(l, xf - (j == 0 ? d : 0), zf - (j == 1 ? d : 0));
    const double dh = (plus.horizontal - minus.horizontal) / (2 * d), dv = (plus.vertical - minus.vertical) / (2 * d);
    const double scale = s.stiffness.cwiseAbs().maxCoeff();
    EXPECT_NEAR(s.stiffness(0, j), dh, 1e-6 * scale) << "d HF / d " << (j ? "ZF" : "XF") << " at " << xf;
    EXPECT_NEAR(s.stiffness(1, j), dv, 1e-6 * scale) << "d VF / d " << (j ? "ZF" : "XF") << " at " << xf;
  }
}

TEST(Catenary, TheStiffnessIsTheSolversOwnDerivative) {
  expect_stiffness_is_the_solvers(line(5e4), 5.4, kHeight);         // on the seabed
  expect_stiffness_is_the_solvers(line(5e4), 5.9, kHeight);         // hanging whole, stretched
  expect_stiffness_is_the_solvers(line(5e4, 0.5), 5.0, kHeight);    // friction, tension zero on the seabed
  expect_stiffness_is_the_solvers(line(5e4, 0.05), 5.45, kHeight);  // friction, tension all along
}

// Hanging whole, the line carries its own weight: VF - VA = w L; and a stretched span beyond the
// unstretched length is reached by the stretch
TEST(Catenary, ALineHangingWholeCarriesItsWeight) {
  const CatenaryState s = solve_catenary(line(5e4), 5.9, kHeight);  // sqrt(5.9^2 + 2^2) = 6.23 m > 6 m
  EXPECT_EQ(s.laid_length, 0.0);
  EXPECT_NEAR(s.vertical - s.anchor_vertical, kWeight * kLength, 1e-9);
  EXPECT_GT(s.horizontal, 100.0) << "pulled taut: the span is the stretch";
}

// So slack that it hangs straight down from the fairlead: no horizontal tension, the hanging part's weight
TEST(Catenary, ASlackLineHangsStraightDown) {
  const double ea = 5e4;
  const CatenaryState s = solve_catenary(line(ea), 2.0, kHeight);
  const double hanging = 2 * kHeight / (1 + std::sqrt(1 + 2 * kHeight * kWeight / ea));
  EXPECT_NEAR(hanging + kWeight * hanging * hanging / (2 * ea), kHeight, 1e-12) << "stretched by its own weight";
  EXPECT_EQ(s.horizontal, 0.0);
  EXPECT_NEAR(s.vertical, kWeight * hanging, 1e-12);
  EXPECT_NEAR(s.laid_length, kLength - hanging, 1e-12);
}

// Friction on the laid part takes some of the tension before the anchor: HA = max(HF - CB w L_B, 0), and
// the laid part stretches less, so the same span needs a little more tension than without it
TEST(Catenary, SeabedFrictionTakesTensionBeforeTheAnchor) {
  const CatenaryState free = solve_catenary(line(5e4), 5.4, kHeight);
  const CatenaryState held = solve_catenary(line(5e4, 1.0), 5.4, kHeight);
  EXPECT_NEAR(held.anchor_horizontal, std::max(held.horizontal - 1.0 * kWeight * held.laid_length, 0.0), 1e-12);
  EXPECT_LT(held.anchor_horizontal, held.horizontal);
  EXPECT_GT(held.horizontal, free.horizontal);
  EXPECT_LT(held.horizontal, 1.001 * free.horizontal) << "the stretch is small beside the span: a small effect";
}

// The drawn shape is the solve's closed form along the line: from the anchor (0, 0) to the fairlead
// (XF, ZF) to the solve's tolerance (1e-12 relative; 1e-9 m asked), on the seabed up to the touchdown
// point, rising after it with the slope VF / HF reached at the fairlead (the tension's direction), and
// as long as the line stretched: the chords no longer than the line under its largest tension, and short
// of the unstretched length by no more than the chords' sag (0.1 % at 41 points)
void expect_profile_closes(const CatenaryLine& l, double xf, double zf) {
  const CatenaryState s = solve_catenary(l, xf, zf);
  const int n = 41;
  const auto p = catenary_profile(l, s, xf, n);
  ASSERT_EQ(p.size(), static_cast<std::size_t>(n));
  EXPECT_NEAR(p.front().x(), 0.0, 1e-12) << xf;
  EXPECT_NEAR(p.front().y(), 0.0, 1e-12);
  EXPECT_NEAR(p.back().x(), xf, 1e-9) << "the shape ends at the fairlead, " << xf;
  EXPECT_NEAR(p.back().y(), zf, 1e-9);
  const double tension = std::hypot(s.horizontal, s.vertical);
  double drawn = 0;
  for (int i = 1; i < n; ++i) {
    drawn += (p[i] - p[i - 1]).norm();
    EXPECT_GE(p[i].x(), p[i - 1].x()) << "no line doubles back, " << i;
    EXPECT_GE(p[i].y(), p[i - 1].y() - 1e-12) << "nor sags below the seabed, " << i;
  }
  if (s.horizontal > 0) {  // chords of the stretched line: no longer than it, shorter by a chord's sag only
    EXPECT_LE(drawn, l.length * (1 + tension / l.axial_stiffness)) << xf;
    EXPECT_GE(drawn, 0.999 * l.length) << xf;
  }
  // the touchdown point among the points: on the seabed at the laid length, stretched by at most
  // HF / EA (below the fairlead for a slack line)
  const double touchdown = s.horizontal > 0 ? s.laid_length : xf;
  bool found = s.laid_length == 0;
  for (const auto& q : p)
    found = found || (q.y() == 0 && q.x() >= touchdown - 1e-12 && q.x() <= touchdown * (1 + tension / l.axial_stiffness));
  EXPECT_TRUE(found) << "the touchdown point is one of the points";
  if (s.horizontal > 0) {
    const Eigen::Vector2d last = p[n - 1] - p[n - 2];
    EXPECT_NEAR(last.y() / last.x(), s.vertical / s.horizontal, 0.05 * s.vertical / s.horizontal + 1e-3)
        << "the last segment points along the fairlead's tension (to a chord's error)";
  }
}

TEST(Catenary, TheDrawnShapeIsTheSolvedLine) {
  expect_profile_closes(line(5e4), 5.4, kHeight);         // on the seabed
  expect_profile_closes(line(5e4), 5.9, kHeight);         // hanging whole, stretched
  expect_profile_closes(line(5e4, 0.5), 5.0, kHeight);    // friction, tension zero on the seabed
  expect_profile_closes(line(5e4, 0.05), 5.45, kHeight);  // friction, tension all along
  expect_profile_closes(line(5e4), 2.0, kHeight);         // slack, hanging straight down
  EXPECT_THROW(catenary_profile(line(5e4), solve_catenary(line(5e4), 5.4, kHeight), 5.4, 1), std::invalid_argument);
}

TEST(Catenary, BadLinesAndPositionsAreRefused) {
  EXPECT_THROW(solve_catenary(CatenaryLine{0, 2, 5e4}, 5, 2), std::invalid_argument);
  EXPECT_THROW(solve_catenary(CatenaryLine{6, -2, 5e4}, 5, 2), std::invalid_argument);
  EXPECT_THROW(solve_catenary(CatenaryLine{6, 2, NAN}, 5, 2), std::invalid_argument);
  EXPECT_THROW(solve_catenary(CatenaryLine{6, 2, 5e4, -1}, 5, 2), std::invalid_argument);
  EXPECT_THROW(solve_catenary(line(5e4), 5, 0), std::invalid_argument) << "a fairlead on the seabed";
  EXPECT_THROW(solve_catenary(line(5e4), -1, 2), std::invalid_argument);
}

}  // namespace
}  // namespace icedem

namespace icedem {
namespace {

// The reference's spread: four of the elastic example's lines at 45, 135, 225 and 315 degrees, each
// anchor 5.4 m from its fairlead horizontally and 2 m below it, the fairleads at the body's point
std::vector<MooringLine> four_lines() {
  std::vector<MooringLine> out;
  for (double deg : {45.0, 135.0, 225.0, 315.0}) {
    const double a = deg * M_PI / 180;
    out.push_back(MooringLine{Eigen::Vector3d(5.4 * std::cos(a), -2.0, 5.4 * std::sin(a)), Eigen::Vector3d::Zero(),
                              CatenaryLine{6.0, 2.0, 5e4, 0}});
  }
  return out;
}

TEST(MooringSpread, FourLinesHoldTheBodyInPlace) {
  const MooringLoad at_rest = mooring_load(four_lines(), Eigen::Vector3d::Zero());
  EXPECT_NEAR(at_rest.force.x(), 0, 1e-12);
  EXPECT_NEAR(at_rest.force.z(), 0, 1e-12);
  EXPECT_NEAR(at_rest.force.y(), -4 * at_rest.lines[0].vertical, 1e-12) << "the lines' pull down";
  EXPECT_NEAR(-at_rest.force.y(), 36.9, 0.05) << "the reference's 4 x 9.23 N";
}

// Offset in surge, every line solved again: the reference's restoring forces 0.683, 3.44 and 7.03 N at
// 0.01, 0.05 and 0.10 m (secant stiffness 68.3, 68.7, 70.3 N/m: the spread stiffens as it is pulled)
TEST(MooringSpread, AnOffsetIsRestoredAsTheReferenceSolvedIt) {
  const double offsets[] = {0.01, 0.05, 0.10}, forces[] = {0.683, 3.44, 7.03};
  for (int k = 0; k < 3; ++k) {
    const MooringLoad l = mooring_load(four_lines(), Eigen::Vector3d(offsets[k], 0, 0));
    EXPECT_NEAR(-l.force.x(), forces[k], 0.006 * forces[k] + 0.001) << offsets[k] << " m";
    EXPECT_NEAR(l.force.z(), 0, 1e-12) << "symmetric in sway";
  }
  // the linear stiffness of the spread, 2 (k_HH + HF / XF), is the small offset's secant
  const CatenaryState s = solve_catenary(CatenaryLine{6.0, 2.0, 5e4, 0}, 5.4, 2.0);
  const double k11 = 2 * (s.stiffness(0, 0) + s.horizontal / 5.4);
  const MooringLoad small = mooring_load(four_lines(), Eigen::Vector3d(1e-5, 0, 0));
  EXPECT_NEAR(-small.force.x() / 1e-5, k11, 1e-3 * k11);
}

// A fairlead off the reference point: its line's force acts there, so the body feels a moment
TEST(MooringSpread, AFairleadOffThePointGivesAMoment) {
  std::vector<MooringLine> one = {MooringLine{Eigen::Vector3d(5.4, -2.0, 0), Eigen::Vector3d(0, 0, 0.5),
                                              CatenaryLine{6.0, 2.0, 5e4, 0}}};
  one[0].anchor.z() = 0.5;  // the line in the x-y plane through the fairlead
  const MooringLoad l = mooring_load(one, Eigen::Vector3d::Zero());
  const Eigen::Vector3d expected = Eigen::Vector3d(0, 0, 0.5).cross(l.force);
  EXPECT_NEAR((l.moment - expected).norm(), 0, 1e-12);
  EXPECT_GT(l.moment.norm(), 1.0);
  EXPECT_THROW(mooring_load({MooringLine{Eigen::Vector3d(5, 1, 0), Eigen::Vector3d::Zero(), CatenaryLine{6, 2, 5e4}}},
                            Eigen::Vector3d::Zero()),
               std::invalid_argument)
      << "an anchor above its fairlead";
}

}  // namespace
}  // namespace icedem
