// Scenario files: TOML in, validated Scene out.
//
// Every key is declared in dem/input/scenario_keys.cpp. Unknown keys, wrong types and
// out-of-range values raise InputError naming file:line, the key, the value and
// what was expected (with the nearest key for a typo). Overrides given as
// `key.path=value` (the CLI's --set) are applied after the file.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "dem/input/scenario_keys.hpp"
#include "dem/input/scene.hpp"
#include "dem/input/scene_builder.hpp"  // make_scene, load_scene

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

/// Throws InputError naming where `path` was set (file:line, --set, or the scenario file for
/// a default), its value and `problem`.
[[noreturn]] void fail_key(const Scenario& scenario, const std::string& path, const std::string& problem);

/// `text` cut to a length a message can quote, saying how long it was.
std::string excerpt(const std::string& text);

/// Why `path` is not a readable regular file ("" if it is): missing, a directory or a device,
/// or what the system says (a path too long, a symlink loop); never throws.
std::string not_a_file(const std::filesystem::path& path);

}  // namespace icedem
