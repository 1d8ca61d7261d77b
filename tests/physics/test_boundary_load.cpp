// The boundary load (dem/world/boundary_load.hpp): what fixed bodies take off the structure's
// push through the ice it touches. The sliding row of 20 boxes (contact_scenes.hpp),
// pushed by the plate at constant speed over a fixed floor: by momentum balance the
// floor's friction carries the plate's whole push, n mu m g, and the row is "locked"
// in the sense of the diagnostic (the boundary carries at least half the surge load).
#include <gtest/gtest.h>

#include "tests/physics/contact_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

TEST(BoundaryLoad, TheFloorCarriesThePushOfTheSlidingRow) {
  const RowStep s = sliding_row_step("newton");
  const double push = s.plate_impulse / kDt;  // N, the plate's surge load (normal contacts, frictionless plate)
  const double expected = kRowBoxes * kRowMu * kBoxMass * kGravity;
  // Newton to a merit of 1e-9 (contact_scenes): the push is n mu m g to 1e-6, and
  // the boxes keep their speed, so the floor takes the same load to 1e-6
  ASSERT_NEAR(push, expected, 1e-6 * expected);
  EXPECT_NEAR(s.boundary_load, push, 1e-6 * push);
  EXPECT_TRUE(locked(s.boundary_load, push));
  // a boundary that carries less than half the push is not a lock
  EXPECT_FALSE(locked(0.49 * push, push));
  EXPECT_FALSE(locked(s.boundary_load, 0.0));  // no push, no lock
}
