// The build's identity (dem/core/build_id.hpp): generated at build time from the source's git
// checkout, written into the summary (and /meta, tests/unit/test_recorder.cpp).
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <string>

#include "dem/core/build_id.hpp"
#include "dem/output/summary.hpp"

using namespace icedem;

namespace {

// the exit status of a shell command (its output discarded)
int shell(const std::string& command) { return std::system((command + " >/dev/null 2>&1").c_str()); }

}  // namespace

TEST(BuildId, NamesACommitOfTheSourceItWasBuiltFrom) {
  const BuildId id = build_id();
  const std::string source = ICEDEM_SOURCE_DIR;
  // built from a git checkout with git at hand, the identity is a commit that checkout holds: a
  // generator that failed or parsed git's output wrongly gives "unknown" or something else
  if (shell("git -C '" + source + "' rev-parse HEAD") == 0) {
    ASSERT_TRUE(std::regex_match(id.commit, std::regex("[0-9a-f]{40}"))) << id.commit;
    EXPECT_EQ(shell("git -C '" + source + "' cat-file -e " + id.commit + "^{commit}"), 0) << id.commit;
  } else {
    EXPECT_EQ(id.commit, "unknown");
  }
  EXPECT_FALSE(id.type.empty());
  EXPECT_FALSE(id.compiler.empty());
  EXPECT_EQ(id.text().rfind(id.commit, 0), 0u) << id.text();
  EXPECT_EQ(id.text().find("(modified)") != std::string::npos, id.modified) << id.text();
}

TEST(BuildId, IsInTheRunSummary) {
  RunSummary s;
  s.status = "complete";
  s.build = BuildId{std::string(40, 'a'), true, "Release", "GNU 12.2.0"};
  const nlohmann::json j = summary_json(s)["build"];
  EXPECT_EQ(j["commit"], std::string(40, 'a'));
  EXPECT_EQ(j["modified"], true);
  EXPECT_EQ(j["type"], "Release");
  EXPECT_EQ(j["compiler"], "GNU 12.2.0");
}
