// Joint loads and the paper's failure criteria (eq. 1-3): the decomposition
// against hand statics, the element lattice, and each criterion alone.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/core/errors.hpp"
#include "dem/fracture/element_lattice.hpp"
#include "dem/fracture/joint_loads.hpp"

using namespace icedem;

namespace {
// paper ice: L_e 0.15 m, T_e 0.033 m, sigma_c 145.6 kPa, sigma_s 72.8 kPa, sigma_b 36.4 kPa
const JointCapacity kPaper = paper_joint_capacity(0.15, 0.033, 145.6e3, 72.8e3, 36.4e3);
}  // namespace

TEST(JointCapacity, MatchesThePaperThresholds) {
  // docs/model/validation_targets.md §3: compression 720.7 N, shear 360.4 N, bending 0.991 N m (L_e 0.15)
  EXPECT_NEAR(kPaper.compression, 720.7, 0.05);
  EXPECT_NEAR(kPaper.shear, 360.4, 0.05);
  EXPECT_NEAR(kPaper.bending, 0.991, 0.0005);
  EXPECT_LE(kPaper.tension, 0.0);  // off in paper mode
}

TEST(JointCapacity, AFacesCapacitiesFollowItsLength) {
  // eqs. 1-3 for a face of half the length: half of each capacity (a cut element's face)
  const JointCapacity half = scaled(kPaper, 0.5);
  const JointCapacity paper_half = paper_joint_capacity(0.075, 0.033, 145.6e3, 72.8e3, 36.4e3);
  EXPECT_NEAR(half.compression, paper_half.compression, 1e-9);
  EXPECT_NEAR(half.shear, paper_half.shear, 1e-9);
  EXPECT_NEAR(half.bending, paper_half.bending, 1e-12);
  EXPECT_LE(half.tension, 0.0);  // off stays off
}

TEST(JointLoads, WrenchMovesToTheJointMidpoint) {
  // element A centred at the origin, B along +x; the joint at x = 0.075.
  // a vertical force F on A at its centre, no torque: at the midpoint it is a
  // vertical shear F and a moment (c - p) x F about the joint line
  const Eigen::Vector3d F(0, -2.0, 0), centre(0, 0, 0), mid(0.075, 0, 0);
  const JointLoads l = decompose_joint_load(F, Eigen::Vector3d::Zero(), centre, mid, {1, 0, 0}, {0, 1, 0});
  EXPECT_NEAR(l.axial, 0.0, 1e-12);
  EXPECT_NEAR(l.shear_vertical, -2.0, 1e-12);
  EXPECT_NEAR(l.shear_in_plane, 0.0, 1e-12);
  // (c - p) x F = (-0.075, 0, 0) x (0, -2, 0) = (0, 0, 0.15); t = v x n = (0,1,0) x (1,0,0) = (0,0,-1)
  EXPECT_NEAR(l.bending_out_of_plane, -0.15, 1e-12);
  EXPECT_NEAR(l.bending_in_plane, 0.0, 1e-12);
  EXPECT_NEAR(l.torsion, 0.0, 1e-12);
}

TEST(JointLoads, CantileverRootCarriesTheWeightOutboard) {
  // hand statics: a root joint holding three 0.15 m elements of mass m out along +x;
  // the joint acts on the root element A with the weight of the outboard part
  const double m = 0.691, g = 9.81, Le = 0.15;  // 0.15 x 0.15 x 0.033 m of ice
  const double W = 3 * m * g;
  // on A (at x = 0): force -W (it holds the beam up, so the beam pulls A down) and the
  // moment of the outboard weights about A's centre
  const Eigen::Vector3d F(0, -W, 0);
  const double arm_about_centre = (1 + 2 + 3) * Le;  // outboard centres at 1, 2, 3 L_e
  const Eigen::Vector3d T(0, 0, -m * g * arm_about_centre);
  const JointLoads l = decompose_joint_load(F, T, {0, 0, 0}, {Le / 2, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_NEAR(std::abs(l.shear_vertical), W, 1e-12);
  // about the midpoint the arms are 0.5, 1.5, 2.5 L_e: M = m g Le (0.5 + 1.5 + 2.5)
  EXPECT_NEAR(std::abs(l.bending_out_of_plane), m * g * Le * 4.5, 1e-12);
}

TEST(FailureCriteria, EachFiresAloneAboveItsThreshold) {
  double r = 0;
  JointLoads c{-1.01 * kPaper.compression, 0, 0, 0, 0, 0};
  EXPECT_EQ(failure_mode(c, kPaper, r), FailureMode::kCompression);
  EXPECT_NEAR(r, 1.01, 1e-12);
  JointLoads s{0, 0.8 * kPaper.shear, 0.8 * kPaper.shear, 0, 0, 0};  // resultant 1.13
  EXPECT_EQ(failure_mode(s, kPaper, r), FailureMode::kShear);
  JointLoads b{0, 0, 0, -1.2 * kPaper.bending, 0, 0};
  EXPECT_EQ(failure_mode(b, kPaper, r), FailureMode::kBending);
  EXPECT_NEAR(r, 1.2, 1e-12);
}

TEST(FailureCriteria, NothingFailsBelowTheThresholds) {
  double r = 0;
  JointLoads l{-0.99 * kPaper.compression, 0.5 * kPaper.shear, 0.5 * kPaper.shear, 0.99 * kPaper.bending, 0, 0};
  EXPECT_EQ(failure_mode(l, kPaper, r), FailureMode::kNone);
  EXPECT_NEAR(r, 0.99, 1e-12);
  // tension and in-plane bending are off in paper mode, however large
  JointLoads t{1e6, 0, 0, 0, 1e6, 0};
  EXPECT_EQ(failure_mode(t, kPaper, r), FailureMode::kNone);
}

TEST(ElementLattice, SplitsASquareFloeIntoElementsAndJoints) {
  const Polygon floe{{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}};
  const ElementLattice l = make_element_lattice(floe, 0.15);
  EXPECT_EQ(l.centres.size(), 16u);
  EXPECT_EQ(l.joints.size(), 24u);  // 2 n (n - 1) for n = 4
  for (const LatticeJoint& j : l.joints) {
    // the midpoint lies halfway between the centres, one half element from each
    EXPECT_NEAR((l.centres[j.a] + l.centres[j.b]).x() / 2, j.midpoint.x(), 1e-12);
    EXPECT_NEAR((l.centres[j.b] - l.centres[j.a]).norm(), 0.15, 1e-12);
  }
  EXPECT_EQ(make_element_lattice(floe, 0.2).centres.size(), 9u);
}

TEST(ElementLattice, ElementSizeThatDoesNotDivideTheFloeIsAnError) {
  const Polygon floe{{-0.15, -0.15}, {0.15, -0.15}, {0.15, 0.15}, {-0.15, 0.15}};
  try {
    make_element_lattice(floe, 0.2);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fracture.element_size"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ice.floe_size"), std::string::npos) << e.what();
  }
}
