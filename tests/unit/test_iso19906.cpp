// The ISO 19906 (Croasdale and Cammaert) load of level ice on a sloping structure
// (dem/iso19906.hpp), on the paper's cone and ice.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/errors.hpp"
#include "dem/iso19906.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;

namespace {

// The paper's cone (Table 2) and ice (Table 3), from the default scenario.
ConeLoadInputs paper_cone(double friction) {
  ConeLoadInputs in = cone_load_inputs(icedem::testing::scene_from(""));
  in.friction = friction;
  return in;
}

}  // namespace

TEST(Iso19906, TheScenariosConeIsTheTable2Cone) {
  const ConeLoadInputs in = paper_cone(0.2);
  EXPECT_NEAR(in.waterline_diameter, 1.228, 1e-9);
  EXPECT_NEAR(in.slope, M_PI / 4, 1e-9);  // 0.443 m down over 0.443 m of radius
  EXPECT_TRUE(in.downward);               // the radius shrinks below the waterline
  EXPECT_NEAR(in.ride_height, 0.443, 1e-9);
}

TEST(Iso19906, IntermediateValuesByHand) {
  // L_c = (60e6 x 0.033^3 / (12 x 1000 x 9.81 x (1 - 0.33^2)))^(1/4) = (2156.2 / 104904)^(1/4)
  // = 0.3787 m; w = 1.228 + pi^2 x 0.3787 / 4 = 2.1623 m; xi at 45 degrees and mu 0.2 =
  // (1 + 0.2) / (1 - 0.2) = 1.5; H_T = 1.5 x 1.228 x 0.033^2 x 70 x 9.81 cos45 / (sin45 x 0.8)
  // = 1.5 x 1.228 x 0.001089 x 686.7 x 1.25 = 1.722 N.
  const ConeLoad r = iso19906_cone_load(paper_cone(0.2));
  EXPECT_NEAR(r.characteristic_length, 0.3787, 1e-4);
  EXPECT_NEAR(r.crack_width, 2.1623, 1e-4);
  EXPECT_NEAR(r.slope_factor, 1.5, 1e-12);
  EXPECT_NEAR(r.turning, 1.722, 1e-3);
}

TEST(Iso19906, MatchesTheValidationTargetsTable) {
  // docs/model/validation_targets.md section 4a: the same equations as OpenFAST's IceFloe
  // module implements them (IceFlexISO.f90: breaking, ride and block-turning terms, no rubble
  // pile), evaluated by hand for this cone's waterline diameter and ice, the ride height the
  // cone's full depth (0.443 m), at three slopes: the total and, in brackets, breaking alone,
  // rounded to 1 N (hence the 0.6 N tolerance).
  struct Row {
    double degrees, mu, total, breaking;
  };
  const Row rows[] = {{30, 0.1, 84, 63},   {30, 0.2, 103, 77},  {30, 0.3, 126, 94},
                      {45, 0.1, 132, 108}, {45, 0.2, 164, 134}, {45, 0.3, 205, 168},
                      {60, 0.1, 238, 203}, {60, 0.2, 326, 279}, {60, 0.3, 489, 418}};
  for (const Row& row : rows) {
    ConeLoadInputs in = paper_cone(row.mu);
    in.slope = row.degrees * M_PI / 180.0;
    const ConeLoad r = iso19906_cone_load(in);
    EXPECT_NEAR(r.total, row.total, 0.6) << row.degrees << " degrees, mu " << row.mu;
    EXPECT_NEAR(r.breaking_only, row.breaking, 0.6) << row.degrees << " degrees, mu " << row.mu;
  }
}

TEST(Iso19906, AnUpwardSlopeLiftsTheIceItsWeightNotItsBuoyancy) {
  // The ride and turning terms scale with the density that resists the ride: rho_i when the
  // ice is lifted, rho_w - rho_i when it is pushed under: 930 / 70 times larger upward.
  ConeLoadInputs down = paper_cone(0.2), up = down;
  up.downward = false;
  const ConeLoad d = iso19906_cone_load(down), u = iso19906_cone_load(up);
  EXPECT_NEAR(u.ride / d.ride, 930.0 / 70.0, 1e-9);
  EXPECT_NEAR(u.turning / d.turning, 930.0 / 70.0, 1e-9);
  EXPECT_DOUBLE_EQ(u.breaking, d.breaking);  // breaking the sheet does not depend on the side
}

TEST(Iso19906, FrictionThatLocksTheIceOnTheSlopeIsAnInputError) {
  // at 45 degrees the method needs mu < 1: the terms' denominators vanish at mu = 1
  try {
    iso19906_cone_load(paper_cone(1.0));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("friction 1"), std::string::npos) << e.what();
  }
}
