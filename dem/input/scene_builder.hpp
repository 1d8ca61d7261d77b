// Scenario -> Scene: every key into its Scene field, by name, choice keys into their enums,
// the keys checked against each other, and the ice's derived properties computed once.
#pragma once

#include <string>
#include <vector>

#include "dem/input/scene.hpp"

namespace icedem {

struct Scenario;

/// Check the keys against each other and build the Scene. Throws InputError naming the key.
Scene make_scene(const Scenario& scenario);

/// read_scenario + make_scene.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace icedem
