// Small scenes for tests, written inline as TOML (like MuJoCo's test models).
#pragma once

#include <string>
#include <vector>

#include "dem/scenario.hpp"

namespace icedem::testing {

/// A Scene from TOML text (defaults fill the rest); `overrides` as for --set.
inline Scene scene_from(const std::string& toml, const std::vector<std::string>& overrides = {}) {
  return make_scene(parse_scenario(toml, "test.toml", ICEDEM_SOURCE_DIR, overrides));
}

}  // namespace icedem::testing
