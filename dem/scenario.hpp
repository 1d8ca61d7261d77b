// Scenario files: TOML in, validated Scene out.
//
// Every key is declared in dem/scenario_keys.cpp. Unknown keys, wrong types and
// out-of-range values raise InputError naming file:line, the key, the value and
// what was expected (with the nearest key for a typo). Overrides given as
// `key.path=value` (the CLI's --set) are applied after the file.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "dem/scenario_keys.hpp"
#include "dem/scene.hpp"

namespace icedem {

/// A resolved key: its value and where it came from ("file.toml:12",
/// "--set", or "default"), so later checks can point at the right line.
struct ResolvedKey {
  KeyValue value;
  std::string origin;
};

/// All keys of a scenario after defaults, file and overrides, before they are
/// turned into a Scene.
struct Scenario {
  std::string path;      // as given by the user
  std::string base_dir;  // directory relative paths in the file refer to
  std::map<std::string, ResolvedKey> keys;

  /// Every key and value as TOML text, grouped by section (written to /meta).
  std::string resolved_text() const;
};

/// Parse `path` and apply `overrides` ("key.path=value"). Throws InputError.
Scenario read_scenario(const std::string& path, const std::vector<std::string>& overrides = {});

/// Parse TOML text (`display_name` is used in messages). Throws InputError.
Scenario parse_scenario(const std::string& toml_text, const std::string& display_name,
                        const std::string& base_dir, const std::vector<std::string>& overrides = {});

/// Check the keys against each other and build the Scene. Throws InputError.
Scene make_scene(const Scenario& scenario);

/// read_scenario + make_scene.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace icedem
