// The validation cases (dem/validation/): the plate against Hertz, the cantilevers against
// eq. 6, and the finite-plate table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

// The wide cantilever (dem/validation/wide_cantilever.hpp; scenarios/validation/
// wide_cantilever_015.toml: a 0.9 x 0.45 m plate of 0.15 m elements in air, clamped along one
// edge, loaded along the other): the plate's bending strength across it at the first break,
// by the direction of the element grid (fracture.lattice_angle)
namespace {

// `scenario` (in scenarios/validation/) with the grid's shape and angle, and `sets` beside them
nlohmann::json wide_cantilever(const std::string& shape, double angle_deg,
                               const std::string& scenario = "wide_cantilever_015.toml",
                               std::vector<std::string> sets = {}) {
  sets.insert(sets.end(), {"fracture.element_shape=\"" + shape + "\"", "fracture.lattice_angle=" + std::to_string(angle_deg)});
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/" + scenario, sets);
  const ValidationResult r = run_validation_case(scene);
  EXPECT_TRUE(r.value) << shape << " at " << angle_deg << " deg: " << r.note;
  return r.to_json();
}

double strength_ratio(const nlohmann::json& r) { return r["value"].get<double>() / r["reference"].get<double>(); }

}  // namespace

// Squares along the grid: the root line's three joints share the moment equally, so the plate
// breaks there, in bending, when M = B T^2 sigma_b / 6 (eq. 3 summed over the line): within 3 %
// (the load grows 0.5 N/s over steps of 0.02 s, 0.2 % of the load at the break; measured +0.1 %)
TEST(WideCantilever, SquaresAlongTheGridBreakAtTheBendingStrength) {
  const nlohmann::json r = wide_cantilever("square", 0);
  EXPECT_NEAR(strength_ratio(r), 1.0, 0.03) << r.dump();
  EXPECT_TRUE(r["at_root"].get<bool>());
  EXPECT_EQ(r["failure_mode"].get<std::string>(), "bending");
  EXPECT_EQ(r["root_joints"].get<int>(), 3);
}

// Across the grid a square lattice is stronger: at 45 degrees the crack zig-zags through sqrt(2)
// times the face length per length of line, each face loaded at 45 degrees to its own bending
// axis. Measured 1.49 sigma_b; asked: more than 1.2 (the straight line's 1.0 plus a margin far
// beyond the 0.1 % scatter of the break's step)
TEST(WideCantilever, SquaresAcrossTheGridAreStronger) {
  EXPECT_GT(strength_ratio(wide_cantilever("square", 45)), 1.2);
}

// A hexagonal grid's strength varies less with the direction than a square grid's (the
// paper's reason for hexagons: cracks closer to any direction), and it is above the bending
// strength in every direction: a crack through hexagons always zig-zags (per length of line
// its faces are 2/sqrt(3) = 1.15 times as long, at 30 degrees to it). Measured on this plate:
// hexagons 1.31-1.51 sigma_b at 0, 10, 20 and 30 degrees (spread 1.15), squares 1.00, 1.36
// and 1.49 at 0, 20 and 45 degrees (spread 1.49)
TEST(WideCantilever, HexagonsVaryLessWithDirectionThanSquares) {
  std::vector<double> hexagons, squares;
  for (double a : {0.0, 10.0, 20.0, 30.0}) hexagons.push_back(strength_ratio(wide_cantilever("hexagon", a)));
  for (double a : {0.0, 20.0, 45.0}) squares.push_back(strength_ratio(wide_cantilever("square", a)));
  const auto spread = [](const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end()) / *std::min_element(v.begin(), v.end());
  };
  EXPECT_LT(spread(hexagons), spread(squares));
  EXPECT_GT(*std::min_element(hexagons.begin(), hexagons.end()), 1.0);
  std::printf("wide cantilever, strength / sigma_b: hexagons %.2f %.2f %.2f %.2f (0-30 deg), squares %.2f %.2f %.2f "
              "(0, 20, 45 deg)\n", hexagons[0], hexagons[1], hexagons[2], hexagons[3], squares[0], squares[1], squares[2]);
}

// At their calibrated strength (fracture.strength_scale = 0.787, the unscaled lattice's mean
// over directions; scenarios/validation/wide_cantilever_015_hexagon.toml), hexagons break at the
// bending strength within the cantilevers' 10 % in every direction of the grid, where squares
// meet it along their grid only (1.56 across it). Measured: 1.097, 0.949, 0.979 and 0.976 at 0,
// 10, 20 and 30 degrees (the 60-degree symmetry and its mirror leave no other direction)
TEST(WideCantilever, CalibratedHexagonsBreakAtTheBendingStrengthInEveryDirection) {
  for (double a : {0.0, 10.0, 20.0, 30.0}) {
    const Scene scene =
        load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/wide_cantilever_015_hexagon.toml",
                   {"fracture.lattice_angle=" + std::to_string(a)});
    const ValidationResult r = run_validation_case(scene);
    ASSERT_TRUE(r.value) << a << " deg: " << r.note;
    EXPECT_LE(std::abs(*r.rel_error), 0.10) << a << " deg: " << r.to_json().dump();
    EXPECT_EQ(r.details["failure_mode"].get<std::string>(), "bending") << a << " deg";
  }
}

// The wide cantilever pushed along its plane (validation.plate_load = "along";
// scenarios/validation/plate_compression_015.toml): every section across the plate carries the
// load, and sigma = P / (B T) at the first break is the plate's compressive strength in that
// direction of the grid
namespace {

double compression_ratio(const std::string& scenario, const std::string& shape, double angle_deg,
                         std::vector<std::string> sets = {}) {
  sets.push_back("validation.plate_load=\"along\"");
  return strength_ratio(wide_cantilever(shape, angle_deg, scenario, sets));
}

}  // namespace

// Squares along the grid: the root line's three faces hold L_e T_e sigma_c each (eq. 1), so the
// plate breaks there, in compression, at the compressive strength: within 3 % (the load grows
// 2 N a step, 0.1 % of the 2,162 N at the break; measured +0.1 %)
TEST(PlateCompression, SquaresAlongTheGridBreakAtTheCompressiveStrength) {
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_compression_015.toml");
  const ValidationResult r = run_validation_case(scene);
  ASSERT_TRUE(r.value) << r.note;
  EXPECT_NEAR(strength_ratio(r.to_json()), 1.0, 0.03) << r.to_json().dump();
  EXPECT_EQ(r.details["failure_mode"].get<std::string>(), "compression");
  EXPECT_TRUE(r.details["at_root"].get<bool>());
}

// The hexagons at their calibrated scales (wide_cantilever_015_hexagon.toml: the strength scale
// 0.787 is on the bending capacity only) meet the compressive strength along x, the direction the
// structure pushes them, as the squares do along their grid: within the cantilevers' 10 %
// (measured 0.95 on this 1.2 x 0.9 m plate, 1.07 on the 0.9 x 0.45 m one; with the scale on
// every capacity, as before, 0.75). Off the grid the first break comes earlier, in shear, for
// both lattices (docs/model/breakage.md, "In the plate's plane": squares 0.49-0.75 at 10-45
// degrees on this plate, hexagons 0.60-0.71 at 10-30); the hexagons' weakest direction is no
// weaker than the squares' (a margin of 0.05 against the measured 0.11, far beyond the 0.1 % of
// a step's load growth)
TEST(PlateCompression, CalibratedHexagonsBreakAtTheCompressiveStrengthAlongXAndNoWeakerThanSquaresOffIt) {
  const std::vector<std::string> hexagon_plate{"validation.load_rate=200"};
  const std::string file = "wide_cantilever_015_hexagon.toml";
  EXPECT_NEAR(compression_ratio(file, "hexagon", 0, hexagon_plate), 1.0, 0.10);
  double hexagons = 1e9, squares = 1e9;
  for (double a : {10.0, 20.0, 30.0}) hexagons = std::min(hexagons, compression_ratio(file, "hexagon", a, hexagon_plate));
  for (double a : {10.0, 20.0, 30.0, 45.0})
    squares = std::min(squares, compression_ratio(file, "square", a, {"validation.load_rate=200", "fracture.strength_scale=1"}));
  EXPECT_GT(hexagons, squares + 0.05);
  std::printf("plate in compression, weakest direction's strength / sigma_c: hexagons %.2f, squares %.2f\n", hexagons,
              squares);
}
