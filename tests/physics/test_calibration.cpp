// The joints' calibration (dem/validation/calibration): Bullet's CFM and the elastic joints' scale, and the
// joint iterations the CFM depends on.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/core/errors.hpp"
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

namespace {
// a small, quick plate-deflection scene for the calibration tests
Scene small_plate() {
  return load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_deflection_27_015.toml",
                    {"validation.plate_size=1.5", "time.duration=6", "solver.iterations=30",
                     "fracture.joint_iterations=0", "fracture.erp=0.8"});
}
}  // namespace

TEST(Calibration, FindsTheCfmThatGivesTheTargetModulus) {
  const Scene scene = small_plate();
  // a target the joints can reach: between the stiffest and a soft setting
  const CalibrationResult r = calibrate_cfm(scene, 20e6, 0.02);
  ASSERT_TRUE(r.reached) << r.note;
  EXPECT_NEAR(r.modulus, 20e6, 0.02 * 20e6);
  // the modulus falls as the CFM grows (softer joints)
  EXPECT_GT(r.points[0].modulus, r.points[1].modulus);
  // re-measuring at the calibrated CFM reproduces it (the run is deterministic)
  Scene check = scene;
  check.fracture.cfm = r.value;
  EXPECT_NEAR(modulus_from_compliance(check, measure_plate_compliance(check), plate_finite_factor(check)), r.modulus,
              1e-6 * r.modulus);
}

TEST(Calibration, ScalesTheElasticJointsToTheTargetModulusInTwoOrThreeRuns) {
  // elastic joints are springs: the plate's modulus grows nearly in proportion to their scale
  // when the joints are solved (the default solve, merit 1e-3), so the secant lands within the
  // 2 % tolerance in at most three plate runs; the modulus grows with the scale, by less than
  // in proportion and by more than half of it (measured: 0.87 times the scale, 0.90 times the
  // modulus; the water under the plate takes part of the load)
  const Scene scene = load_scene(
      std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_deflection_27_015_elastic.toml",
      {"validation.plate_size=1.5", "time.duration=6"});
  const CalibrationResult r = calibrate_stiffness_scale(scene, 45e6, 0.02);
  ASSERT_TRUE(r.reached) << r.note;
  EXPECT_EQ(r.key, "fracture.stiffness_scale");
  EXPECT_NEAR(r.modulus, 45e6, 0.02 * 45e6);
  EXPECT_LE(r.points.size(), 3u);
  ASSERT_GE(r.points.size(), 2u);
  const CalibrationPoint &a = r.points[0], &b = r.points[1];
  const double modulus_ratio = b.modulus / a.modulus, scale_ratio = b.value / a.value;
  ASSERT_LT(scale_ratio, 1.0);  // 45 MPa is below the start's modulus: a softer scale
  EXPECT_GT(modulus_ratio, scale_ratio);
  EXPECT_LT(modulus_ratio, std::sqrt(scale_ratio));
  // Bullet's CFM joints are refused: their stiffness is not a scale
  Scene cfm = scene;
  cfm.fracture.elastic_joints = false;
  EXPECT_THROW(calibrate_stiffness_scale(cfm, 45e6), InputError);
}

TEST(Calibration, SaysWhenOnlyMoreIterationsCanStiffenThePlate) {
  const Scene scene = small_plate();
  const CalibrationResult r = calibrate_cfm(scene, 1e12, 0.02);  // far stiffer than PGS allows
  EXPECT_FALSE(r.reached);
  EXPECT_NE(r.note.find("fracture.joint_iterations"), std::string::npos) << r.note;
  EXPECT_EQ(r.points.size(), 1u);  // one look at the stiffest joints is enough to know
}

TEST(Breakable, JointIterationsSolveTheJointsLongerThanTheContacts) {
  // Bullet sweeps a constraint max(override, solver.iterations) times and contacts
  // solver.iterations times: a plate (joints, no contacts) at 5 iterations with 30
  // for its joints must deflect as at 30 iterations, and differ from 5 iterations alone
  auto compliance = [](std::vector<std::string> set) {
    set.insert(set.end(), {"validation.plate_size=1.5", "time.duration=6"});
    const Scene s =
        load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_deflection_27_015.toml", set);
    return measure_plate_compliance(s);
  };
  const double thirty = compliance({"solver.iterations=30", "fracture.joint_iterations=0"});
  const double override = compliance({"solver.iterations=5", "fracture.joint_iterations=30"});
  const double five = compliance({"solver.iterations=5", "fracture.joint_iterations=0"});
  // 1e-6: the same sweeps over the same rows, only the (absent) contacts differ
  EXPECT_NEAR(override, thirty, 1e-6 * thirty);
  EXPECT_GT(five, 1.2 * thirty);  // measured about 2x: five sweeps leave the plate soft
}
