// Outlines recorded from runs and kept as test data (tests/unit/data/*.txt): one vertex "x z" (m, tank frame) a line,
// lines starting with '#' the file's own description.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

#include "dem/layout/polygon.hpp"

namespace icedem::testing {

/// The outline in `name` under tests/unit/data, its vertices in the file's order; empty if the file cannot be read.
inline Polygon read_outline(const std::string& name) {
  std::ifstream in(std::string(ICEDEM_SOURCE_DIR) + "/tests/unit/data/" + name);
  Polygon outline;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double x = 0, z = 0;
    row >> x >> z;
    outline.emplace_back(x, z);
  }
  return outline;
}

}  // namespace icedem::testing
