// Element joints as springs of the ice (dem/world/joint_springs.hpp): the rows' stiffness
// from the ice's modulus and the element's geometry, and a lattice whose modulus does
// not depend on the step.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dem/input/scenario.hpp"
#include "dem/validation/calibration.hpp"
#include "dem/validation/case.hpp"
#include "dem/validation/plate_theory.hpp"
#include "dem/world/joint_springs.hpp"

using namespace icedem;

namespace {

// the quick plate-deflection scene of the calibration tests (1.5 m of 0.15 m elements,
// 6 s), joints solved exactly by the Newton method: what it measures is the joints'
// stiffness, not how far an iteration got
double plate_modulus(std::vector<std::string> set) {
  set.insert(set.begin(), {"validation.plate_size=1.5", "time.duration=6", "solver.method=\"newton\""});
  const Scene s = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_deflection_27_015.toml", set);
  return modulus_from_compliance(s, measure_plate_compliance(s), plate_finite_factor(s));
}

}  // namespace

TEST(JointSprings, RowsAreTheIceBetweenTwoElementCentres) {
  FractureSettings f{};
  f.element_size = 0.15;
  f.stiffness_scale = 1.0;
  IceSettings ice{};
  ice.thickness = 0.033;
  ice.elastic_modulus = 60e6;
  ice.poisson_ratio = 0.25;
  const double E = 60e6, G = E / 2.5, H = 0.033, L = 0.15;
  // a joint along body x: axial along x, shears along y and z, torsion about x,
  // in-plane bending about y, out-of-plane (plate) bending about z
  const JointSprings x = elastic_joint_springs(f, ice, Eigen::Vector3d::UnitX());
  EXPECT_DOUBLE_EQ(x(0), E * H);
  EXPECT_DOUBLE_EQ(x(1), G * H);
  EXPECT_DOUBLE_EQ(x(2), G * H);
  EXPECT_DOUBLE_EQ(x(3), G * H * H * H / 3);
  EXPECT_DOUBLE_EQ(x(4), E * H * L * L / 12);
  EXPECT_DOUBLE_EQ(x(5), E * H * H * H / 12);
  // along z the roles of x and z swap; the scale multiplies every row
  f.stiffness_scale = 2.0;
  const JointSprings z = elastic_joint_springs(f, ice, Eigen::Vector3d::UnitZ());
  EXPECT_DOUBLE_EQ(z(2), 2 * E * H);
  EXPECT_DOUBLE_EQ(z(0), 2 * G * H);
  EXPECT_DOUBLE_EQ(z(5), 2 * G * H * H * H / 3);
  EXPECT_DOUBLE_EQ(z(3), 2 * E * H * H * H / 12);
  // in a joint's own frame, for elements cut at an outline: between two squares (face and
  // distance L) the rows along x above; a face half as long at the same distance holds half
  // of every row but the in-plane bending, an eighth (its section's L^3)
  const JointSprings own = elastic_joint_springs_along(f, ice, L, L);
  for (int r = 0; r < 6; ++r) EXPECT_NEAR(own(r), 2 * x(r), 1e-9 * own(r)) << r;
  const JointSprings half = elastic_joint_springs_along(f, ice, L / 2, L);
  for (int r : {0, 1, 2, 3, 5}) EXPECT_NEAR(half(r), own(r) / 2, 1e-9 * own(r)) << r;
  EXPECT_NEAR(half(4), own(4) / 8, 1e-9 * own(4));
}

// The issue the springs solve: with Bullet's ERP and CFM the plate's modulus grows as
// 1/h^2 (measured 60, 195, 635 MPa at 1, 2, 4 substeps). With springs it is the same at
// dt, dt/2, dt/4 and 1, 2, 4 substeps: within 2 % (measured: the same to four digits,
// 64.17 MPa; the deflection is taken once the plate has settled, a static state).
TEST(JointSprings, PlateModulusIsTheSameAtAnyStep) {
  const std::vector<std::string> elastic{"fracture.joint_stiffness=\"elastic\""};
  auto with = [&](const std::string& extra) {
    std::vector<std::string> s = elastic;
    s.push_back(extra);
    return plate_modulus(s);
  };
  const double base = plate_modulus(elastic);
  for (const char* step : {"time.substeps=2", "time.substeps=4", "time.dt=0.01", "time.dt=0.005"}) {
    const double e = with(step);
    EXPECT_NEAR(e, base, 0.02 * base) << step;
    std::printf("elastic joints: %s: %.2f MPa (at dt = 0.02 s, 1 substep: %.2f MPa)\n", step, e / 1e6,
                base / 1e6);
  }
  // and Bullet's CFM at the same plate: the modulus moves by far more than 2 % with the step
  const double cfm_1 = plate_modulus({}), cfm_2 = plate_modulus({"time.substeps=2"});
  EXPECT_GT(cfm_2, 1.5 * cfm_1);
  std::printf("Bullet's CFM: %.1f MPa at 1 substep, %.1f MPa at 2\n", cfm_1 / 1e6, cfm_2 / 1e6);
}
