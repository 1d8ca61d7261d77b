// Ralston's load of level ice on a cone (dem/validation/ralston.hpp), on the paper's cone and ice.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/core/errors.hpp"
#include "dem/validation/ralston.hpp"
#include "tests/support/paper_cone.hpp"

using namespace icedem;
using icedem::testing::paper_cone;

// The slope ends at the keel: D_T is the keel's diameter (Table 2: radius 0.171 m)
TEST(Ralston, TheSlopeEndsAtTheKeel) { EXPECT_NEAR(paper_cone(0.2).end_diameter, 0.342, 1e-9); }

TEST(Ralston, IntermediateValuesByHand) {
  // G = 1000 x 9.81 x 1.228^2 / (4 x 36400 x 0.033) = 14793 / 4804.8 = 3.0789
  const RalstonLoad r = ralston_cone_load(paper_cone(0.2));
  EXPECT_NEAR(r.weight_ratio, 3.0789, 1e-4);
  EXPECT_NEAR(r.total, r.breaking + r.ride, 1e-12);
}

// docs/model/validation_targets.md section 4a: 171, 214 and 267 N at mu 0.1, 0.2 and 0.3 for the
// paper's cone at 45 degrees, evaluated apart from this code (from IceFloe's IceFlexIEC.f90, with
// rho_w in G), rounded to 1 N (hence the 0.6 N tolerance)
TEST(Ralston, MatchesTheValidationTargetsTable) {
  const double mu[] = {0.1, 0.2, 0.3}, total[] = {171, 214, 267};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(ralston_cone_load(paper_cone(mu[k])).total, total[k], 0.6) << mu[k];
}

// More friction, more load; a friction that locks the ice on the slope is refused
TEST(Ralston, FrictionRaisesTheLoadUntilTheIceLocks) {
  EXPECT_LT(ralston_cone_load(paper_cone(0.1)).total, ralston_cone_load(paper_cone(0.3)).total);
  EXPECT_THROW(ralston_cone_load(paper_cone(2.0)), InputError);
}
