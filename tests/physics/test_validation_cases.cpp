// The validation cases (dem/validation/): the plate against Hertz, the cantilevers against
// eq. 6, and the finite-plate table.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/fracture/break_context.hpp"
#include "dem/fracture/fracture.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/lattice_region.hpp"
#include "dem/input/scenario.hpp"
#include "dem/run/simulation.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/validation/calibration.hpp"
#include "dem/validation/case.hpp"
#include "dem/validation/plate_theory.hpp"
#include "tests/physics/breakable_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

TEST(Breakable, PlateDeflectionMatchesHertzWithinFivePercent) {
  // scenarios/validation/plate_deflection_27_015.toml: a 2.7 m plate of 0.15 m elements at
  // the calibrated CFM (0.0059 at 100 joint iterations), 10 N at the centre; reference
  // Hertz x finite-plate factor = 0.092 mm/N (docs/model/validation_targets.md §2).
  // 5 %: the tolerance docs/model/validation_targets.md accepts (E then within 10 %)
  const Scene scene =
      load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_deflection_27_015.toml");
  const RunSummary s = run_simulation(scene, test_run("plate.h5"));
  ASSERT_FALSE(s.validation.is_null());
  EXPECT_NEAR(s.validation["reference"].get<double>(), 0.0922, 0.0005);
  EXPECT_LT(std::abs(s.validation["rel_error"].get<double>()), 0.05) << s.validation.dump();
  EXPECT_TRUE(s.validation["passed"].get<bool>());
}

// Hexagonal elements (fracture.element_shape = "hexagon"): the same plates cut from a
// hexagonal lattice, each at its calibrated stiffness scale (0.751 at 0.15 m, the squares'
// own; 0.774 at 0.20 m, where the squares' 0.621 gives 49.7 MPa). The same 5 % as the
// squares'. Measured: -0.2 % and +0.0 %. A hexagonal lattice is isotropic in its elastic
// bending, so a point load at the centre measures its modulus in every direction.
class HexagonalPlate : public ::testing::TestWithParam<const char*> {};

TEST_P(HexagonalPlate, DeflectionMatchesHertzWithinFivePercent) {
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/" + GetParam());
  ASSERT_EQ(scene.fracture.element_shape, ElementShape::kHexagon);
  const RunSummary s = run_simulation(scene, test_run(std::string("hexagon_") + GetParam() + ".h5"));
  ASSERT_FALSE(s.validation.is_null());
  EXPECT_LT(std::abs(s.validation["rel_error"].get<double>()), 0.05) << s.validation.dump();
  EXPECT_TRUE(s.validation["passed"].get<bool>());
}

INSTANTIATE_TEST_SUITE_P(Validation, HexagonalPlate,
                         ::testing::Values("plate_deflection_27_015_hexagon.toml",
                                           "plate_deflection_28_020_hexagon.toml"));

TEST(Validation, FinitePlateFactorFollowsTheTable) {
  // docs/model/validation_targets.md §2: 2.70 at a/l_c = 1, 1.038 at 4, 1.000 at 8 and beyond
  EXPECT_DOUBLE_EQ(finite_plate_factor(1.0), 2.70);
  EXPECT_DOUBLE_EQ(finite_plate_factor(4.0), 1.038);
  EXPECT_DOUBLE_EQ(finite_plate_factor(20.0), 1.0);
  EXPECT_NEAR(finite_plate_factor(3.25), (1.088 + 1.064) / 2, 1e-12);
}

TEST(Breakable, CantileverBreaksInBendingAtTheRootAtTheBendingStrength) {
  // scenarios/validation/cantilever_015.toml (seed paper Fig. 7, eq. 6): 10 % is the
  // validation target's tolerance (docs/model/validation_targets.md); the tip load grows by 0.2 N/s x 0.02 s = 4 mN per step, 0.15 %
  // of the 2.64 N failure load, so the load resolution is not what limits it
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/cantilever_015.toml");
  const RunSummary s = run_simulation(scene, test_run("cantilever.h5"));
  ASSERT_FALSE(s.validation.is_null());
  EXPECT_EQ(s.validation["failure_mode"], "bending") << s.validation.dump();
  EXPECT_TRUE(s.validation["at_root"].get<bool>());
  EXPECT_LT(std::abs(s.validation["rel_error"].get<double>()), 0.10);
  EXPECT_EQ(s.breaks_by_mode[static_cast<int>(FailureMode::kBending)], s.breaks);
  // the root joint's stress from the joint feedback follows eq. 6 applied to the tip load
  // (1 %: the quasi-static ramp lags the beam by a step)
  const auto& h = s.validation["history"];
  const double P = h["tip_load_N"].back().get<double>(), lever = s.validation["lever_m"].get<double>();
  const double applied_kPa = 6 * P * lever / (0.15 * 0.033 * 0.033) / 1e3;
  EXPECT_NEAR(h["root_joint_stress_kPa"].back().get<double>(), applied_kPa, 0.01 * applied_kPa);
}

TEST(Breakable, FloatingCantileverPushedDownBreaksAtTheBendingStrengthByEquationSix) {
  // scenarios/validation/cantilever_floating_015.toml, the paper's test: the tip pushed down
  // at 5 mm/s; 10 % is the validation target's tolerance on sigma' = 6 (P_c - P_b) l / (L_e T_e^2).
  // With the paper's joints (Bullet's CFM, swept): eq. 6 reads P_b as the push 0.5-1.5 s after
  // the break, which grows with the tip's depth at the break, so the check holds only for
  // joints as stiff in this test as the paper's. The elastic joints (the default) reach the
  // breaking moment at 3.9 mm instead of 2.2 mm and miss it (next test)
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/cantilever_floating_015.toml",
                                 {"fracture.joint_stiffness=cfm", "solver.method=pgs"});
  const RunSummary s =
      run_simulation(scene, test_run("cantilever_floating.h5"));
  ASSERT_FALSE(s.validation.is_null());
  const auto& v = s.validation;
  EXPECT_TRUE(v["floating"].get<bool>());
  EXPECT_EQ(v["failure_mode"], "bending") << v.dump();
  EXPECT_TRUE(v["at_root"].get<bool>());
  EXPECT_LT(std::abs(v["rel_error"].get<double>()), 0.10) << v.dump();
  // the fragment hangs on the pusher: a positive buoyancy, well below the peak push
  const double pb = v["fragment_buoyancy_N"].get<double>(), pc = v["load_at_failure_N"].get<double>();
  EXPECT_GT(pb, 0.0);
  EXPECT_LT(pb, 0.5 * pc);
  // the push force peaks at the break (Fig. 7a): every earlier sample is lower
  const auto& t = v["history"]["time_s"];
  const auto& p = v["history"]["tip_load_N"];
  for (std::size_t i = 0; i < t.size() && t[i].get<double>() < v["time_of_failure_s"].get<double>(); ++i)
    EXPECT_LE(p[i].get<double>(), pc + 1e-9) << "t = " << t[i];
}

TEST(Breakable, FloatingCantileverWithElasticJointsBreaksAtTheRootInBending) {
  // the same test at the default (elastic joints, the accelerated projected gradient): the
  // root joint fails in bending when its stress reaches sigma_b, but eq. 6 applied to the
  // push gives far less (measured 7.6 kPa, -79 %: the fragment's P_b is read 0.5-1.5 s
  // after a later, deeper break). A known miss of the paper's data reduction with these
  // joints, stated in docs/model/validation_targets.md; asserted here so it cannot change
  // unseen: the root stress at failure within 1 % of sigma_b (the break criterion on the
  // joint's decomposed loads, docs/model/breakage.md), and eq. 6 below the target
  const Scene scene =
      load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/cantilever_floating_015.toml");
  const RunSummary s = run_simulation(scene, test_run("cantilever_floating_elastic.h5"));
  ASSERT_FALSE(s.validation.is_null());
  const auto& v = s.validation;
  EXPECT_EQ(v["failure_mode"], "bending") << v.dump();
  EXPECT_TRUE(v["at_root"].get<bool>());
  EXPECT_NEAR(v["root_joint_stress_at_failure_kPa"].get<double>(), 36.4, 0.01 * 36.4);
  EXPECT_LT(v["rel_error"].get<double>(), -0.10) << "eq. 6 now meets the target: update validation_targets.md";
}
