// Small scenes for tests, written inline as TOML (like MuJoCo's test models).
#pragma once

#include <string>
#include <vector>

#include "dem/input/scenario.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/run/simulation.hpp"

namespace icedem::testing {

/// A Scene from TOML text (defaults fill the rest); `overrides` as for --set.
inline Scene scene_from(const std::string& toml, const std::vector<std::string>& overrides = {}) {
  return make_scene(parse_scenario(toml, "test.toml", ICEDEM_SOURCE_DIR, overrides));
}

/// Options of a test's run: no progress line, the file `name` in the test directory.
inline RunOptions test_run(const std::string& name, const std::string& command_line = "") {
  RunOptions o;
  o.output = std::string(ICEDEM_TEST_TMP) + "/" + name;
  o.progress = false;
  o.command_line = command_line;
  return o;
}

/// Still water, the structure parked far away, every body awake: the bench of
/// single-floe physics tests. `extra` overrides more keys (as --set does).
inline Scene bench_scene(std::vector<std::string> extra = {}) {
  std::vector<std::string> keys{"flow.model=still", "structure.speed=0", "structure.start_x=-50",
                                "activation.sleeping=false"};
  keys.insert(keys.end(), extra.begin(), extra.end());
  return scene_from("", keys);
}

/// A square floe of side `side` (m) centred at (x, z), unrotated.
inline Floe square_floe(double x, double z, double side = 0.3) {
  const double a = side / 2;
  return Floe{Eigen::Vector2d(x, z), 0.0, {{-a, -a}, {a, -a}, {a, a}, {-a, a}}};
}

}  // namespace icedem::testing
