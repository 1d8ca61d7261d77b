// From a Scene to its World: the settings the world is made with, the
// structure from its profile, the fixed boundaries (mother ice, tank) and the
// floes, rigid or breakable.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "dem/input/scene.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// The World's settings from the scene (solver, activation, gravity, crushing,
/// broadphase bounds, ice and water for the floe shapes).
WorldSettings world_settings(const Scene& scene);

/// Inside of the tank (x, y, z), m: between its end walls and side walls, from
/// the floor up to the walls' top; ice outside it has escaped.
Eigen::AlignedBox3d tank_box(const Scene& scene);

/// Whether a floe of this outline is made of breakable elements (fracture.mode).
bool is_breakable(const Scene& scene, const Polygon& outline);

/// Height of a floe's centre at t = 0, m: at its equilibrium draft, or
/// resting on the layers below it (rafted ice, layout.layers).
double initial_height(const Scene& scene, const Floe& floe);

/// Add the scene's hull (structure.profile) with its reference point at `start`.
void add_profile_structure(World& world, const Scene& scene, const Eigen::Vector3d& start);

/// Add the mother ice along the channel sides and end, the tank walls and floor.
void add_boundaries(World& world, const Scene& scene);

/// Add floes floating at their equilibrium draft, at rest: rigid bodies, or
/// lattices of elements and joints where the scene makes them breakable. Floe
/// ids continue from the floes already in the world.
void add_floes(World& world, const Scene& scene, const std::vector<Floe>& floes);

/// The scene's full world: structure, boundaries and the given floes; the structure's reference point
/// at `structure_start` (the State's at t = 0: a moored structure floats at its own draft).
std::unique_ptr<World> build_world(const Scene& scene, const std::vector<Floe>& floes,
                                   const Eigen::Vector3d& structure_start);

}  // namespace icedem
