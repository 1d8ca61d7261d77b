// Reach: the floes kept out of Bullet's world until reached (dem/world/unreached_floes.hpp) enter it
// once something that moves comes near: the structure or an awake body.
#pragma once

#include "dem/input/scene.hpp"
#include "dem/world/world.hpp"

namespace icedem {

/// Put into the world every unreached floe that the structure's box or an awake body's box comes
/// within kReachMargin of, plus what it travels in two steps. Call at the start of each step,
/// before any Bullet step of it.
void enter_reached_floes(const Scene& scene, World& world);

}  // namespace icedem
