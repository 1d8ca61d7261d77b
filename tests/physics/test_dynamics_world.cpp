// Bullet's step taken apart into the stages step() names (dem/world/dynamics_world.hpp) is Bullet's
// own stepSimulation(h, 0), bit for bit: the same bodies, velocities and contact points after
// a pack has been pushed by the structure, with rigid floes and with breakable ones (joints).
#include "dem/world/dynamics_world.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "dem/input/scene_builder.hpp"
#include "dem/output/world_state.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"

namespace icedem {
namespace {

Scene short_tow(std::vector<std::string> overrides) {
  // the structure starts 0.09 m from the first floes, so the pack is pushed within 3 s; all
  // floes in the world from the start (the step's reach stage is not run here)
  overrides.push_back("structure.start_x=5.3");
  overrides.push_back("activation.unreached_out_of_world=false");
  return load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/examples/short_tow.toml", overrides);
}

// what a step starts from: the structure's target and the water's forces
void prepare(const Scene& scene, State& state, double t_next) {
  state.structure_position = structure_position_at(scene, t_next);
  state.structure_velocity = Eigen::Vector3d(scene.structure.speed, 0.0, 0.0);
  state.world->set_structure_target(state.structure_position);
  state.flow->set_structure(state.structure_position, state.structure_velocity);
  apply_water_forces(scene, state);
}

void expect_stages_are_step_simulation(const Scene& scene, int steps) {
  State bullet = initial_state(scene, scene_layout(scene).floes);
  State staged = initial_state(scene, scene_layout(scene).floes);
  const double h = scene.time.dt / scene.time.substeps;
  for (int k = 1; k <= steps * scene.time.substeps; ++k) {
    prepare(scene, bullet, k * h);
    prepare(scene, staged, k * h);
    bullet.world->dynamics().stepSimulation(h, 0);
    DynamicsWorld& d = staged.world->dynamics();
    d.detect_collisions(h);
    d.find_islands();
    d.solve_contacts(h);
    d.integrate(h);
  }
  const WorldState a = capture_world(*bullet.world), b = capture_world(*staged.world);
  long points = 0;
  for (const ManifoldState& m : a.manifolds) points += static_cast<long>(m.points.size());
  ASSERT_GT(points, 20) << "the structure should have pushed into the pack";
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i)
    EXPECT_EQ(std::memcmp(&a.bodies[i], &b.bodies[i], sizeof(BodyState)), 0) << "body " << i;
  ASSERT_EQ(a.manifolds.size(), b.manifolds.size());
  for (std::size_t i = 0; i < a.manifolds.size(); ++i) {
    ASSERT_EQ(a.manifolds[i].points.size(), b.manifolds[i].points.size());
    for (std::size_t p = 0; p < a.manifolds[i].points.size(); ++p) {
      const btManifoldPoint &x = a.manifolds[i].points[p], &y = b.manifolds[i].points[p];
      EXPECT_EQ(x.m_appliedImpulse, y.m_appliedImpulse) << "manifold " << i << " point " << p;
      EXPECT_EQ(x.m_distance1, y.m_distance1) << "manifold " << i << " point " << p;
    }
  }
  EXPECT_EQ(a.joint_broken, b.joint_broken);
}

// frozen floes outside a region around the structure: the islands' hook releases struck ones
TEST(DynamicsWorld, StagesAreStepSimulationWithRigidFloes) {
  expect_stages_are_step_simulation(short_tow({"activation.freeze_outside_region=true"}), 150);
}

TEST(DynamicsWorld, StagesAreStepSimulationWithJoints) {
  expect_stages_are_step_simulation(short_tow({"fracture.mode=on", "fracture.element_size=0.15"}), 250);
}

}  // namespace
}  // namespace icedem
