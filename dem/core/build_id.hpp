// Which build of icedem made a run: the source's git commit, whether its tracked files differed
// from it, the build type and the compiler. Written into every output's /meta and the run
// summary, so that a sweep's records kept across machines and sessions say which build made
// each (runs of different builds are different samples once a change moves the dynamics).
// The values are generated at build time (cmake/build_id.cmake).
#pragma once

#include <string>

namespace icedem {

struct BuildId {
  std::string commit;    // 40 hex digits, or "unknown" (not built from a git checkout)
  bool modified;         // tracked sources differed from the commit when it was built
  std::string type;      // CMAKE_BUILD_TYPE
  std::string compiler;  // compiler id and version

  /// One line: "<commit>[ (modified)], <type>, <compiler>".
  std::string text() const { return commit + (modified ? " (modified)" : "") + ", " + type + ", " + compiler; }
};

BuildId build_id();

}  // namespace icedem
