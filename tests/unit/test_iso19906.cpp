// The ISO 19906 (Croasdale and Cammaert) load of level ice on a sloping structure
// (dem/validation/iso19906.hpp), on the paper's cone and ice.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/core/errors.hpp"
#include "dem/validation/iso19906.hpp"
#include "tests/support/paper_cone.hpp"

using namespace icedem;
using icedem::testing::paper_cone;

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

namespace {

// An upward-breaking Arctic cone with a rubble pile: every term in play.
ConeLoadInputs arctic_cone(double slope_deg, double h, double sigma_f, double E, double nu, double rho_i, double mu,
                           double mu_i, RubblePile pile) {
  ConeLoadInputs in{};
  in.waterline_diameter = 10.0;
  in.slope = slope_deg * M_PI / 180.0;
  in.downward = false;
  in.ride_height = 99.0;  // unused with a pile: the ice rides to the pile's top
  in.thickness = h;
  in.flexural_strength = sigma_f;
  in.elastic_modulus = E;
  in.poisson_ratio = nu;
  in.ice_density = rho_i;
  in.water_density = 1025.0;
  in.gravity = 9.80665;
  in.friction = mu;
  in.ice_friction = mu_i;
  in.rubble = pile;
  return in;
}

RubblePile pile(double height, double porosity, double angle_deg, double phi_deg, double cohesion) {
  return RubblePile{height, porosity, angle_deg * M_PI / 180.0, phi_deg * M_PI / 180.0, cohesion};
}

}  // namespace

TEST(Iso19906, EveryTermMatchesAnIndependentImplementation) {
  // The reference values are IceFloe's (OpenFAST's ice module, DNV KEMA 2014:
  // IceFlexISO.f90, functions H_b, H_p, H_r, H_l, H_t and the amplified sum, crack length
  // term on), compiled with gfortran 12 in double precision and run at these inputs on
  // 2026-11-26, with its gravity of 9.80665 m/s^2. It is a second transcription of the same
  // ISO equations, written independently of this one: a mistyped term in either shows here.
  // Relative tolerance 1e-7: IceFloe's literal 0.68 is single precision (1e-8 off).
  struct Case {
    ConeLoadInputs in;
    double H_B, H_P, H_R, H_L, H_T, H;
  };
  const Case cases[] = {
      {arctic_cone(45, 1.0, 7e5, 5e9, 0.3, 900, 0.1, 0.1, pile(5, 0.3, 35, 40, 5000)), 1.0087283760822359e6,
       9.9125610011017325e3, 8.1643044560788968e5, 2.8393978759860882e5, 1.4709975000000003e5, 2.3393204199865479e6},
      {arctic_cone(60, 0.8, 5e5, 4e9, 0.33, 910, 0.15, 0.05, pile(3, 0.25, 45, 50, 0)), 1.0153530550166566e6,
       2.6900914417185923e3, 6.4994166273089917e5, 2.9983028650674282e5, 5.4151797142121941e4, 2.1627742946052924e6},
      // the pile's face as steep as the slope: no wedge to push or lift (k = 0)
      {arctic_cone(45, 1.0, 7e5, 5e9, 0.3, 900, 0.1, 0.1, pile(5, 0.3, 45, 45, 5000)), 1.0087283760822359e6, 0.0,
       7.6277835872953595e5, 0.0, 1.4709975000000003e5, 1.9805894264278738e6}};
  for (const Case& c : cases) {
    const ConeLoad r = iso19906_cone_load(c.in);
    const auto near = [](double got, double want) { return std::abs(got - want) <= 1e-7 * std::abs(want) + 1e-6; };
    EXPECT_TRUE(near(r.breaking, c.H_B)) << r.breaking << " vs " << c.H_B;
    EXPECT_TRUE(near(r.pile_push, c.H_P)) << r.pile_push << " vs " << c.H_P;
    EXPECT_TRUE(near(r.ride, c.H_R)) << r.ride << " vs " << c.H_R;
    EXPECT_TRUE(near(r.pile_lift, c.H_L)) << r.pile_lift << " vs " << c.H_L;
    EXPECT_TRUE(near(r.turning, c.H_T)) << r.turning << " vs " << c.H_T;
    EXPECT_TRUE(near(r.total, c.H)) << r.total << " vs " << c.H;
  }
}

TEST(Iso19906, WithoutAPileTheRubbleTermsVanish) {
  const ConeLoad r = iso19906_cone_load(paper_cone(0.2));
  EXPECT_EQ(r.pile_push, 0.0);
  EXPECT_EQ(r.pile_lift, 0.0);
}

TEST(Iso19906, APileOutOfItsRangesIsAnInputError) {
  // each names the value and the range it needs
  const struct {
    RubblePile pile;
    const char* words;
  } bad[] = {{pile(-1, 0.3, 30, 40, 0), "height -1"},
             {pile(2, 1.0, 30, 40, 0), "porosity 1"},
             {pile(2, 0.3, 50, 40, 0), "angle 50.0 deg"},
             {pile(2, 0.3, 0, 40, 0), "angle 0.0 deg"},
             {pile(2, 0.3, 30, 90, 0), "friction angle 90.0"},
             {pile(2, 0.3, 30, 40, -5), "cohesion -5"}};
  for (const auto& b : bad) {
    ConeLoadInputs in = paper_cone(0.2);
    in.rubble = b.pile;
    try {
      iso19906_cone_load(in);
      ADD_FAILURE() << "expected an InputError for " << b.words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(b.words), std::string::npos) << e.what();
    }
  }
}
