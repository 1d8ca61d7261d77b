// Single impacts with the crushing contact law (dem/contact/crushing.hpp) against the
// energy balance of crushing (docs/model/crushing.md): a floe's corner driven along the
// normal of a 45-degree face, as the cone's, at 0.07 m/s, stops when the work of the
// crushing force over the penetration has taken its kinetic energy,
//
//   1/2 m_eff v_n^2 = integral of F d(delta) = K delta_max^3 / 3,   F = K delta^2,
//   K = sigma_c tan(phi/2) / (sin beta cos^2 beta) = 4.118e5 N/m^2 (phi = 90 deg, beta = 45 deg),
//
// so F_max = K^(1/3) (3 E_k)^(2/3). The floe cannot turn (its inertia made huge: the
// contact's lever arm would otherwise change m_eff as it turns), nothing else acts on it
// (no gravity, no water, no friction), and its mass along the normal is m_eff: its own, or
// with the water's added mass in heave (a factor on its heave response, as
// dem/water/added_mass.hpp sets it), 1 / m_eff = n^T M^-1 n.
// The rigid contact beside it stops the floe within one step, its peak m_eff v_n / h set by
// the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <btBulletDynamicsCommon.h>

#include "dem/world/contact_solver.hpp"
#include "dem/world/world.hpp"
#include "tests/support/box_world.hpp"

using icedem::ContactLaw;
using icedem::ContactSolver;
using icedem::CrushingLaw;
using icedem::CrushingScope;
using icedem::SolverSettings;
using namespace icedem::testing;

namespace {

constexpr double kThickness = 0.033;   // m
constexpr double kIceDensity = 930.0;  // kg/m^3
constexpr double kStrength = 145.6e3;  // Pa, the paper's compressive strength
constexpr double kSpeed = 0.07;        // m/s along the face's normal
const double kBeta = M_PI / 4;         // the face's normal from the horizontal
const double kCornerStiffness = kStrength / (std::sin(kBeta) * std::pow(std::cos(kBeta), 2));  // K, N/m^2

struct Impact {
  double peak_force = 0;        // N, largest normal force on the face in a step
  double peak_penetration = 0;  // m, deepest point of the manifold
  double peak_time = 0;         // s, when the force peaked (from first contact)
  double rebound = 0;           // m/s, the floe's speed away from the face at the end
};

// a square floe of side `side`, its corner along +x, driven at kSpeed along the normal of a fixed
// 45-degree face at step h; `heave_factor`: its response to a vertical force over its mass's
// (1: no added mass); crushing or rigid contacts
// `ice_edge`: the face is instead the straight vertical edge of a fixed body of ice, `edge` (kIce: a floe held
// fixed; kHeldIce: the analytic level sheet's prism); `scope`: the contacts the law acts on (contact.crushing_contacts)
Impact impact(double side, double h, double heave_factor, bool crushing, bool ice_edge = false,
              CrushingScope scope = CrushingScope::kAllIce, icedem::Material edge = icedem::kIce) {
  SolverSettings s = test_solver_settings();
  s.method = "apgd";
  s.merit_tolerance = s.joint_merit_tolerance = s.structure_merit_tolerance = 1e-9;
  s.method_iterations = 20000;
  ContactLaw law;
  if (crushing) law.crushing = CrushingLaw{kStrength, 0.0, kThickness * kThickness};
  law.crushing_scope = scope;
  Bench bench(std::make_unique<ContactSolver>(s, law));
  bench.world().setGravity(btVector3(0, 0, 0));
  // the face: a large fixed block whose face through the origin has the normal n (toward -x, up),
  // or a fixed floe whose straight edge is at x = 0
  const btVector3 n = ice_edge ? btVector3(-1, 0, 0) : btVector3(-std::cos(kBeta), std::sin(kBeta), 0);
  btTransform block = at(0, 0, 0);
  if (!ice_edge) block.setRotation(btQuaternion(btVector3(0, 0, 1), kBeta));
  block.setOrigin(-n * (ice_edge ? 0.3 : 0.5));
  btRigidBody* face = ice_edge ? bench.box({0.3, kThickness / 2, 0.3}, block, 0.0, 0.0, edge)
                               : bench.box({0.5, 0.5, 0.5}, block, 0.0, 0.0, icedem::kStructure);
  // the floe: its corner 1 mm off the face, on the face's normal through the origin
  const double mass = kIceDensity * side * side * kThickness;
  btTransform pose = at(0, 0, 0);
  pose.setRotation(btQuaternion(btVector3(0, 1, 0), M_PI / 4));
  btRigidBody* floe = bench.box({side / 2, kThickness / 2, side / 2}, pose, mass, 0.0, icedem::kIce);
  floe->setMassProps(mass, btVector3(1e12, 1e12, 1e12));  // it cannot turn
  floe->updateInertiaTensor();
  floe->setLinearFactor(btVector3(1, heave_factor, 1));
  // the corner nearest the face (the floe's bottom vertex along +x: the face leans over the
  // floe), placed 1 mm from it
  const double reach = side / std::sqrt(2.0);
  const btVector3 corner_offset(reach, ice_edge ? 0.0 : -kThickness / 2, 0);
  const btVector3 corner = n * 1e-3;  // 1 mm off the face, on its outer side
  pose.setOrigin(corner - corner_offset);
  floe->setWorldTransform(pose);
  floe->getMotionState()->setWorldTransform(pose);
  floe->setLinearVelocity(-n * kSpeed);
  face->setFriction(0.0);
  floe->setFriction(0.0);

  Impact out;
  double first = -1;
  for (int step = 0; step < static_cast<int>(std::lround(0.6 / h)); ++step) {
    bench.world().stepSimulation(h, 0);
    const btVector3 force = contact_force_on(bench.world(), face) * (kDt / h);  // the helper divides by kDt
    const double normal = -force.dot(n);  // the floe pushes the face along -n
    const double depth = deepest_overlap(bench.world());
    if (first < 0 && normal > 0) first = (step + 1) * h;
    if (normal > out.peak_force) out.peak_force = normal, out.peak_time = (step + 1) * h - first;
    out.peak_penetration = std::max(out.peak_penetration, depth);
  }
  out.rebound = floe->getLinearVelocity().dot(n);
  return out;
}

// the floe's mass along the face's normal: 1 / m_eff = n^T M^-1 n, M^-1 = diag(1, heave, 1) / m
double effective_mass(double side, double heave_factor) {
  const double mass = kIceDensity * side * side * kThickness;
  const double c = std::cos(kBeta), s = std::sin(kBeta);
  return mass / (c * c + heave_factor * s * s);
}

// the energy balance's peak force and penetration for a mass m_eff at kSpeed
double balance_force(double m_eff) {
  const double energy = 0.5 * m_eff * kSpeed * kSpeed;
  return std::cbrt(kCornerStiffness) * std::pow(3 * energy, 2.0 / 3.0);
}
double balance_penetration(double m_eff) { return std::cbrt(3 * 0.5 * m_eff * kSpeed * kSpeed / kCornerStiffness); }

}  // namespace

// The peak force is the energy balance's within 10 % (the force of each step's start in a
// leapfrog is second order: a few per cent where the peak takes 4 steps or more), it moves
// by less than 5 % from dt/2 to dt/4, and the floe does not bounce back (crushing is not elastic)
class CrushingImpact : public ::testing::TestWithParam<std::tuple<double, double>> {};

TEST_P(CrushingImpact, PeakForceIsTheEnergyBalancesAndConvergesWithTheStep) {
  const auto [side, heave_factor] = GetParam();
  const double m_eff = effective_mass(side, heave_factor);
  const double f_balance = balance_force(m_eff), d_balance = balance_penetration(m_eff);
  const Impact full = impact(side, 0.02, heave_factor, true), half = impact(side, 0.01, heave_factor, true),
               quarter = impact(side, 0.005, heave_factor, true);
  const Impact rigid_full = impact(side, 0.02, heave_factor, false), rigid_half = impact(side, 0.01, heave_factor, false);
  std::printf("%.1f m floe, m_eff %.2f kg: balance %.2f N at %.2f mm; crushing %.2f / %.2f / %.2f N (%.2f / %.2f / "
              "%.2f mm, peak after %.3f / %.3f / %.3f s) at dt, dt/2, dt/4; rigid %.1f / %.1f N at dt, dt/2\n",
              side, m_eff, f_balance, 1e3 * d_balance, full.peak_force, half.peak_force, quarter.peak_force,
              1e3 * full.peak_penetration, 1e3 * half.peak_penetration, 1e3 * quarter.peak_penetration,
              full.peak_time, half.peak_time, quarter.peak_time, rigid_full.peak_force, rigid_half.peak_force);
  EXPECT_NEAR(half.peak_force, f_balance, 0.10 * f_balance);
  EXPECT_NEAR(quarter.peak_force, f_balance, 0.10 * f_balance);
  EXPECT_NEAR(quarter.peak_penetration, d_balance, 0.10 * d_balance);
  EXPECT_NEAR(half.peak_force, quarter.peak_force, 0.05 * quarter.peak_force);
  EXPECT_LT(std::abs(full.rebound), 1e-3 * kSpeed) << "a crushed contact does not push the floe back";
  // the rigid contact's peak is the momentum over the step: it doubles when the step halves
  EXPECT_NEAR(rigid_half.peak_force / rigid_full.peak_force, 2.0, 0.2);
}

// the paper's two floe sizes, with and without a heave added mass of 3.7 times the floe's own
// (the thin floe's, dem/water/added_mass.hpp: its heave response over 4.7)
INSTANTIATE_TEST_SUITE_P(Floes, CrushingImpact,
                         ::testing::Values(std::make_tuple(0.3, 1.0), std::make_tuple(0.6, 1.0),
                                           std::make_tuple(0.6, 1.0 / 4.7)));

// A floe's corner (opening 90 degrees) driven at 0.07 m/s onto the straight edge of a fixed
// floe: the edge, as wide as the floe's section, barely crushes and the corner takes it, A =
// 2 h delta tan(45 deg), F = k delta with k = 2 sigma_c h (9.6 kN/m): the balance gives
// F_max = v sqrt(m k), 11.4 N for the 0.3 m floe, 22.8 N for the 0.6 m, reached after
// (pi / 2) sqrt(m / k): 27 ms and 53 ms, a step or three at 0.02 s: the 0.6 m floe's is
// checked at dt/2 and dt/4 as the impacts on the cone are (the test prints dt and dt/8 beside)
TEST(CrushingImpactOnIce, ACornerIntoAStraightEdgeCrushesTheCorner) {
  const double side = 0.6, m = kIceDensity * side * side * kThickness, k = 2 * kStrength * kThickness;
  const double balance = kSpeed * std::sqrt(m * k);
  const Impact full = impact(side, 0.02, 1.0, true, true), half = impact(side, 0.01, 1.0, true, true),
               quarter = impact(side, 0.005, 1.0, true, true), eighth = impact(side, 0.0025, 1.0, true, true);
  std::printf("0.6 m floe's corner on a floe's edge: balance %.2f N at %.2f mm; crushing %.2f / %.2f / %.2f / %.2f N "
              "(%.2f / %.2f / %.2f / %.2f mm) at dt, dt/2, dt/4, dt/8\n",
              balance, 1e3 * balance / k, full.peak_force, half.peak_force, quarter.peak_force, eighth.peak_force,
              1e3 * full.peak_penetration, 1e3 * half.peak_penetration, 1e3 * quarter.peak_penetration,
              1e3 * eighth.peak_penetration);
  EXPECT_NEAR(half.peak_force, balance, 0.10 * balance);
  EXPECT_NEAR(quarter.peak_force, balance, 0.10 * balance);
  EXPECT_NEAR(half.peak_force, quarter.peak_force, 0.05 * quarter.peak_force);
  EXPECT_LT(std::abs(half.rebound), 1e-3 * kSpeed) << "a crushed contact does not push the floe back";
}

// With the crushing law at the structure only (contact.crushing_contacts = "structure", the
// default), two floes meet as rigid contacts: the corner driven into the fixed floe's edge gives
// the rigid contact's peak to the bit (the same rows, unbounded), the floe's momentum over the
// step, well above the crushing balance of the test above
TEST(CrushingImpactOnIce, WithCrushingAtTheStructureOnlyFloesMeetRigidly) {
  const Impact rigid = impact(0.6, 0.02, 1.0, false, true);
  const Impact at_structure = impact(0.6, 0.02, 1.0, true, true, CrushingScope::kStructure);
  std::printf("0.6 m floe's corner on a floe's edge at dt: rigid %.2f N, crushing at the structure only %.2f N\n",
              rigid.peak_force, at_structure.peak_force);
  EXPECT_DOUBLE_EQ(at_structure.peak_force, rigid.peak_force);
  EXPECT_GT(rigid.peak_force, 1.5 * 22.81);
}

// The held level sheet's edge (a fixed prism of kHeldIce, as dem/fracture/analytic_sheet.cpp makes it) crushes a
// floe's corner as a floe's edge does under contact.crushing_contacts = "structure_and_sheet": the balance of the
// test above (22.8 N for the 0.6 m floe, the corner's section A = 2 h delta tan(45 deg) the same against either edge),
// within its tolerance at dt/2 and dt/4; under "structure" the sheet's edge meets the floe rigidly, the rigid
// contact's peak to the bit
TEST(CrushingImpactOnIce, TheHeldSheetsEdgeCrushesACornerWhereTheSheetIsInTheScope) {
  const double side = 0.6, m = kIceDensity * side * side * kThickness, k = 2 * kStrength * kThickness;
  const double balance = kSpeed * std::sqrt(m * k);
  const auto on_sheet = [&](double h, bool crushing, CrushingScope scope) {
    return impact(side, h, 1.0, crushing, true, scope, icedem::kHeldIce);
  };
  const Impact half = on_sheet(0.01, true, CrushingScope::kStructureAndHeldIce),
               quarter = on_sheet(0.005, true, CrushingScope::kStructureAndHeldIce);
  const Impact rigid = on_sheet(0.02, false, CrushingScope::kStructure),
               structure_only = on_sheet(0.02, true, CrushingScope::kStructure);
  std::printf("0.6 m floe's corner on the held sheet's edge: balance %.2f N; crushing %.2f / %.2f N at dt/2, dt/4; "
              "rigid %.2f N, crushing at the structure only %.2f N at dt\n",
              balance, half.peak_force, quarter.peak_force, rigid.peak_force, structure_only.peak_force);
  EXPECT_NEAR(half.peak_force, balance, 0.10 * balance);
  EXPECT_NEAR(quarter.peak_force, balance, 0.10 * balance);
  EXPECT_LT(std::abs(half.rebound), 1e-3 * kSpeed) << "a crushed contact does not push the floe back";
  EXPECT_DOUBLE_EQ(structure_only.peak_force, rigid.peak_force);
  EXPECT_GT(rigid.peak_force, 1.5 * balance);
}
