// The output guard of every command (dem/output/output_guard.hpp), one table: what a command
// may write, and what it must refuse before any work, with the reason in the message.
#include "dem/output/output_guard.hpp"

#include <gtest/gtest.h>

#include <H5Cpp.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "dem/core/errors.hpp"

namespace icedem {
namespace {

namespace fs = std::filesystem;

struct Row {
  const char* what;
  std::vector<PlannedOutput> outputs;
  std::vector<std::string> inputs;
  const char* refusal;  // a part of the message; nullptr: accepted
};

class OutputGuard : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::remove_all(dir_);
    fs::create_directories(dir_ + "/a_directory");
    std::ofstream(at("s.toml")) << "seed = 1\n";
    std::ofstream(at("layout.csv")) << "x,z\n";
    std::ofstream(at("notes.txt")) << "a user's notes\n";
    std::ofstream(at("empty.h5")).close();
    H5::H5File(at("old_run.h5"), H5F_ACC_TRUNC).createGroup("/meta");
    H5::H5File checkpoint(at("killed.h5.checkpoint"), H5F_ACC_TRUNC);
    checkpoint.createGroup("/meta");
    checkpoint.createGroup("/checkpoint");
  }
  std::string at(const std::string& name) const { return dir_ + "/" + name; }
  // a directory per test: ctest runs the tests of this file in parallel processes
  const std::string dir_ = std::string(ICEDEM_TEST_TMP) + "/output_guard_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name();
};

TEST_F(OutputGuard, RefusesWhatWouldDestroyAUsersFilesAndNothingElse) {
  const std::string s = at("s.toml"), layout = at("layout.csv");
  const std::vector<std::string> in{s, layout};
  auto run = [&](const std::string& name) { return PlannedOutput{"-o", at(name), OutputKind::kRun, true}; };
  auto file = [&](const std::string& option, const std::string& name) {
    return PlannedOutput{option, at(name), OutputKind::kFile};
  };
  const std::vector<Row> rows{
      {"a new run output", {run("new.h5")}, in, nullptr},
      {"a run output replacing an earlier run's", {run("old_run.h5")}, in, nullptr},
      {"a run output replacing an empty file", {run("empty.h5")}, in, nullptr},
      {"a run output and a summary", {run("new.h5"), file("--summary-json", "new.json")}, in, nullptr},
      {"an STL beside the scenario", {file("-o", "cone.stl")}, in, nullptr},
      {"a case directory, new", {{"-o", at("case"), OutputKind::kDirectory}}, in, nullptr},
      {"a case directory, existing", {{"-o", at("a_directory"), OutputKind::kDirectory}}, in, nullptr},
      {"an empty name", {{"-o", "", OutputKind::kRun, true}}, in, "give a file name"},
      {"the scenario as the run's output", {run("s.toml")}, in, "input of the command"},
      {"the scenario as an STL", {file("-o", "s.toml")}, in, "input of the command"},
      {"the layout file as a CSV", {file("-o", "layout.csv")}, in, "input of the command"},
      {"the scenario as a calibrated scenario", {file("--write", "s.toml")}, in, "input of the command"},
      {"a scenario named as the run's temporary checkpoint", {run("x.h5")}, {at("x.h5.checkpoint.tmp")},
       "input of the command"},
      {"a scenario named as the run's checkpoint", {run("x.h5")}, {at("x.h5.checkpoint")}, "input of the command"},
      {"the summary on the run's own output", {run("new.h5"), file("--summary-json", "new.h5")}, in,
       "writes that file already"},
      {"the summary on the run's checkpoint", {run("new.h5"), file("--summary-json", "new.h5.checkpoint")}, in,
       "writes that file already"},
      {"the summary on another run's output", {run("new.h5"), file("--summary-json", "old_run.h5")}, in,
       "HDF5 file"},
      {"an STL on a run's output", {file("-o", "old_run.h5")}, in, "HDF5 file"},
      {"a run output on a killed run's checkpoint", {run("killed.h5.checkpoint")}, in, "checkpoint"},
      {"a run output on a text file", {run("notes.txt")}, in, "not a run's output"},
      {"a file output on a directory", {file("-o", "a_directory")}, in, "is a directory"},
      {"a case directory on a file", {{"-o", at("notes.txt"), OutputKind::kDirectory}}, in, "is a file"},
      {"a directory that does not exist", {run("no_such_dir/x.h5")}, in, "does not exist"},
  };
  for (const Row& row : rows) {
    SCOPED_TRACE(row.what);
    if (!row.refusal) {
      EXPECT_NO_THROW(guard_outputs(row.outputs, row.inputs));
      continue;
    }
    try {
      guard_outputs(row.outputs, row.inputs);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(row.refusal), std::string::npos) << e.what();
    }
  }
  // nothing was touched
  std::ifstream notes(at("notes.txt"));
  std::string line;
  std::getline(notes, line);
  EXPECT_EQ(line, "a user's notes");
  EXPECT_TRUE(fs::exists(at("killed.h5.checkpoint")));
}

TEST_F(OutputGuard, SameFileSeesThroughLinksAndDots) {
  fs::create_symlink(at("s.toml"), at("link.toml"));
  EXPECT_TRUE(same_file(at("link.toml"), at("s.toml")));
  EXPECT_TRUE(same_file(dir_ + "/./a_directory/../s.toml", at("s.toml")));
  EXPECT_FALSE(same_file(at("s.toml"), at("notes.txt")));
  EXPECT_TRUE(same_file(at("not_yet.h5"), dir_ + "/a_directory/../not_yet.h5"));
}

}  // namespace
}  // namespace icedem
