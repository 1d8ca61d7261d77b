// Breakable floes of any outline in the real Bullet world (dem/fracture/ice_lattice.cpp, the
// outline lattice of dem/fracture/outline_lattice.hpp): a photo's or a hexagonal floe becomes
// its elements and joints with the floe's mass, floats as built (every joint frame agrees with
// both its elements), and hangs on its joints with the weight it carries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dem/fracture/fracture.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/outline_lattice.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/world/bullet_eigen.hpp"
#include "tests/physics/breakable_scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

namespace {

// a floe from the photo example (scenarios/examples/floes_from_photo.csv, its first floe,
// 0.29 x 0.27 m), scaled up to 0.6 m, turned by 0.4 rad
Floe photo_floe() {
  const Polygon outline = {{-0.10789, 0.12775}, {0.10199, 0.12775}, {0.12179, 0.10399}, {0.14159, -0.00293},
                           {0.14159, -0.05046}, {0.09803, -0.13758}, {-0.13165, -0.10194}, {-0.15145, -0.04649}};
  Polygon big;
  for (const Eigen::Vector2d& v : outline) big.push_back(2.0 * v);
  const Eigen::Vector2d c = centroid(big);
  for (Eigen::Vector2d& v : big) v -= c;
  return Floe{Eigen::Vector2d(10.0, 0.0), 0.4, big};
}

double total_mass(const World& world) {
  double m = 0;
  for (const FloeBody& f : world.floes()) m += f.shape->mass;
  return m;
}

}  // namespace

TEST(OutlineLatticeWorld, AnyOutlineBecomesItsElementsAndJoints) {
  for (const char* shape : {"square", "hexagon"}) {
    SCOPED_TRACE(shape);
    const Scene scene = bench({std::string("fracture.element_shape=\"") + shape + "\""});
    const Floe floe = photo_floe();
    State state = initial_state(scene, {floe});
    double yaw = 0;
    const OutlineLattice lattice = floe_outline_lattice(floe.shape, scene.fracture, yaw);
    ASSERT_GT(lattice.elements.size(), 8u);
    EXPECT_EQ(state.world->floes().size(), lattice.elements.size());
    EXPECT_EQ(state.world->joints().size(), lattice.joints.size());
    // the ice's mass is the floe's less the parts too small to be elements (dropped, under 5 %
    // of a cell each, and under 1 % of the floe): a convex outline's parts are their own hulls
    EXPECT_NEAR(total_mass(*state.world), 930.0 * (area(floe.shape) - lattice.dropped_area) * 0.033, 1e-9);
    EXPECT_LT(lattice.dropped_area, 0.01 * area(floe.shape));
    for (const IceJoint& j : state.world->joints()) EXPECT_GT(j.face_length, 0.0);
  }
}

TEST(OutlineLatticeWorld, FloatsAsBuilt) {
  // at its draft in still water a floe of cut elements stays as it was built: a joint frame
  // turned wrongly on either side would pull its elements round at the first step. 1 s;
  // 0.1 mm and 1 mrad are far below what one misplaced frame does (a 60-degree hexagon face:
  // centimetres)
  for (const char* shape : {"square", "hexagon"}) {
    SCOPED_TRACE(shape);
    const Scene scene = bench({std::string("fracture.element_shape=\"") + shape + "\""});
    State state = initial_state(scene, {photo_floe()});
    World& world = *state.world;
    std::vector<Eigen::Isometry3d> start;
    for (const FloeBody& f : world.floes()) start.push_back(body_pose(*f.body));
    for (int i = 0; i < 50; ++i) step(scene, state);
    const Eigen::Isometry3d first_start = start[0], first_now = body_pose(*world.floes()[0].body);
    double moved = 0, turned = 0;
    for (std::size_t e = 1; e < world.floes().size(); ++e) {
      // each element's pose relative to the first element's, then and now
      const Eigen::Isometry3d then = first_start.inverse() * start[e];
      const Eigen::Isometry3d now = first_now.inverse() * body_pose(*world.floes()[e].body);
      moved = std::max(moved, (now.translation() - then.translation()).norm());
      turned = std::max(turned, Eigen::AngleAxisd(then.linear().transpose() * now.linear()).angle());
    }
    EXPECT_LT(moved, 1e-4);
    EXPECT_LT(turned, 1e-3);
    for (int n : state.fracture.breaks_by_mode) EXPECT_EQ(n, 0);
  }
}

TEST(OutlineLatticeWorld, AHexagonalCantileverHangsOnItsJoints) {
  // a 0.6 x 0.3 m floe of hexagons 0.15 m across, in the air, the elements of its left third
  // held fixed: the joints across the cut carry the free part's weight, exactly (statics;
  // 1 %: the converged solve up to the joints' tiny sag)
  const Scene scene = bench({"fracture.element_shape=\"hexagon\"", "solver.method_iterations=5000",
                             "solver.joint_merit_tolerance=1e-8", "solver.merit_tolerance=1e-8"});
  State state = initial_state(scene, {strip(0.6, 0.3)});
  World& world = *state.world;
  lift(world);
  const double x0 = 10.0 - 0.1;  // the floe spans x = 9.7 .. 10.3
  std::vector<char> fixed(world.floes().size(), 0);
  double free_mass = 0;
  for (std::size_t e = 0; e < world.floes().size(); ++e) {
    btRigidBody& b = *world.floes()[e].body;
    if (b.getCenterOfMassPosition().x() < x0) {
      fixed[e] = 1;
      b.setMassProps(0, btVector3(0, 0, 0));
      b.updateInertiaTensor();
    } else {
      free_mass += world.floes()[e].shape->mass;
    }
  }
  ASSERT_GT(free_mass, 0.0);
  for (int i = 0; i < 50; ++i) step(scene, state);
  double held = 0;
  int cut = 0;
  for (const IceJoint& j : world.joints()) {
    if (fixed[j.body_a] == fixed[j.body_b]) continue;
    ++cut;
    const double up_on_a = j.feedback->m_appliedForceBodyA.y();
    held += fixed[j.body_a] ? -up_on_a : up_on_a;  // the force on the free element
  }
  EXPECT_GE(cut, 2);
  const double weight = free_mass * scene.water.gravity;
  EXPECT_NEAR(held, weight, 0.01 * weight);
}
