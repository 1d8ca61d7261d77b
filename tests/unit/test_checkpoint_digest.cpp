// A checkpoint carries a digest of everything in it (dem/output/file_digest.hpp), and one changed or
// damaged after it was written is refused, naming the part that differs: the scenario in /meta, a
// recorded row, a record of the world, a flipped bit on the disk. An untouched one, or a copy of it,
// reads back.
#include <gtest/gtest.h>

#include <H5Cpp.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "dem/core/errors.hpp"
#include "dem/core/hdf5_io.hpp"
#include "dem/output/checkpoint.hpp"
#include "dem/output/file_digest.hpp"

namespace icedem {
namespace {

namespace fs = std::filesystem;

// a directory of its own per test: ctest runs the tests of this file in parallel processes
std::string fresh_dir(const std::string& name) {
  const std::string dir = std::string(ICEDEM_TEST_TMP) + "/checkpoint_digest/" + name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// an output as a run leaves it: its scenario in /meta, rows of loads (compressed, as recorded)
std::string make_output(const std::string& dir) {
  const std::string path = dir + "/run.h5";
  H5::H5File file(path, H5F_ACC_TRUNC);
  const H5::Group meta = file.createGroup("/meta");
  write_attr(meta, "status", std::string("running"));
  write_attr(meta, "scenario", std::string("[friction]\nice_ice = 0.5\n"));
  write_attr(meta, "scenario_path", std::string("s.toml"));
  write_attr(meta, "message", std::string());
  const H5::Group load = file.createGroup("/load");
  Series time = create_series(load, "time", H5::PredType::IEEE_F64LE, {}, 64, "s", "time");
  Series surge = create_series(load, "surge", H5::PredType::IEEE_F64LE, {}, 64, "N", "surge", true);
  for (int i = 0; i < 500; ++i) {
    const double t = 0.02 * (i + 1), f = 10.0 + std::sin(t);
    time.write(&t, 1, H5::PredType::NATIVE_DOUBLE);
    surge.write(&f, 1, H5::PredType::NATIVE_DOUBLE);
  }
  return path;
}

Checkpoint some_checkpoint() {
  Checkpoint c;
  c.version = ICEDEM_VERSION;
  c.values.time = 10.0;
  c.values.step = 500;
  c.history.surge = {1.0, 2.0, 3.0};
  c.world.joint_broken = {0, 1, 0};
  return c;
}

// `what` run on the checkpoint file, opened for writing with HDF5
template <typename Edit>
void edit(const std::string& path, Edit&& what) {
  H5::H5File file(path, H5F_ACC_RDWR);
  what(file);
}

// the InputError's message read_checkpoint throws, "" if it reads the file
std::string refusal(const std::string& path) {
  try {
    read_checkpoint(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointDigest, AnUntouchedCheckpointAndACopyOfItReadBack) {
  const std::string dir = fresh_dir("untouched"), output = make_output(dir);
  write_checkpoint(output, some_checkpoint());
  EXPECT_EQ(refusal(checkpoint_path(output)), "");
  fs::copy_file(checkpoint_path(output), dir + "/copy.h5.checkpoint");
  EXPECT_EQ(refusal(dir + "/copy.h5.checkpoint"), "") << "the digest is of the contents, not of where they lie";
}

TEST(CheckpointDigest, TheDigestIsOfTheContentsPartByPart) {
  const std::string dir = fresh_dir("parts"), output = make_output(dir);
  const H5::H5File file(output, H5F_ACC_RDONLY);
  const FileDigest digest = file_digest(file);
  // one part per top-level group (and the root's own attributes), each a SHA-256
  ASSERT_EQ(digest.size(), 3u);
  EXPECT_TRUE(digest.count("/") && digest.count("/meta") && digest.count("/load"));
  for (const auto& [part, hex] : digest) EXPECT_EQ(hex.size(), 64u) << part;
  EXPECT_EQ(parse_digest(format_digest(digest)), digest);
  EXPECT_THROW(parse_digest("/meta 12ab\n"), std::invalid_argument);
}

TEST(CheckpointDigest, AnEditedScenarioIsRefusedNamingMeta) {
  const std::string dir = fresh_dir("scenario"), output = make_output(dir);
  write_checkpoint(output, some_checkpoint());
  edit(checkpoint_path(output),
       [](H5::H5File& f) { write_attr(f.openGroup("/meta"), "scenario", std::string("[friction]\nice_ice = 0.9\n")); });
  const std::string why = refusal(checkpoint_path(output));
  EXPECT_NE(why.find("/meta (the scenario and the run's metadata) differs"), std::string::npos) << why;
}

TEST(CheckpointDigest, AChangedRecordedRowIsRefusedNamingLoad) {
  const std::string dir = fresh_dir("row"), output = make_output(dir);
  write_checkpoint(output, some_checkpoint());
  edit(checkpoint_path(output), [](H5::H5File& f) {
    H5::DataSet set = f.openDataSet("/load/surge");
    H5::DataSpace space = set.getSpace();
    const hsize_t row = 123, one = 1;
    space.selectHyperslab(H5S_SELECT_SET, &one, &row);
    const double value = 38.0;  // a load the run never recorded
    set.write(&value, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(1, &one), space);
  });
  const std::string why = refusal(checkpoint_path(output));
  EXPECT_NE(why.find("/load (the recorded loads) differs"), std::string::npos) << why;
  EXPECT_EQ(why.find("/meta"), std::string::npos) << "only what changed is named: " << why;
}

TEST(CheckpointDigest, AChangedRecordOfTheStateOrWorldIsRefused) {
  const std::string dir = fresh_dir("record"), output = make_output(dir);
  write_checkpoint(output, some_checkpoint());
  edit(checkpoint_path(output), [](H5::H5File& f) {
    H5::DataSet set = f.openDataSet("/checkpoint/world/joint_broken");
    const std::vector<uint8_t> broken{1, 1, 0};  // a joint the run had not broken
    set.write(broken.data(), H5::PredType::NATIVE_UINT8);
  });
  EXPECT_NE(refusal(checkpoint_path(output)).find("/checkpoint/world (the bodies, joints and contacts)"),
            std::string::npos);
}

TEST(CheckpointDigest, AnAddedOrRemovedGroupIsNamed) {
  const std::string dir = fresh_dir("added"), output = make_output(dir);
  write_checkpoint(output, some_checkpoint());
  edit(checkpoint_path(output), [](H5::H5File& f) {
    f.createGroup("/extra");
    f.unlink("/load");
  });
  const std::string why = refusal(checkpoint_path(output));
  EXPECT_NE(why.find("/extra (added)"), std::string::npos) << why;
  EXPECT_NE(why.find("/load (missing)"), std::string::npos) << why;
}

// bits flipped on the disk, anywhere in the file: refused as an InputError (exit 2), whether the
// flip lands in a value (the digest differs) or in HDF5's own structures (the file does not read, or
// HDF5 crashes reading it, in the child that reads it first). A flip in bytes no one reads (the
// slack HDF5 leaves in its headers and trees) leaves the checkpoint as written: it reads back whole
TEST(CheckpointDigest, FlippedBitsOnTheDiskAreRefusedOrChangeNothing) {
  const std::string dir = fresh_dir("bits"), output = make_output(dir);
  const Checkpoint written = some_checkpoint();
  write_checkpoint(output, written);
  std::ifstream in(checkpoint_path(output), std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int refused = 0, tried = 0;
  for (std::size_t at = 0; at < bytes.size(); at += bytes.size() / 97 + 1) {
    std::vector<char> damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x04);
    const std::string path = dir + "/flip.h5.checkpoint";
    std::ofstream(path, std::ios::binary).write(damaged.data(), static_cast<std::streamsize>(damaged.size()));
    ++tried;
    try {
      const Checkpoint read = read_checkpoint(path);
      EXPECT_TRUE(read.values.time == written.values.time && read.values.step == written.values.step &&
                  read.history.surge == written.history.surge && read.world.joint_broken == written.world.joint_broken)
          << "a flip at byte " << at << " was read as a different checkpoint";
    } catch (const InputError&) {
      ++refused;
    }  // any other exception fails the test: it would be exit 1, not the documented 2
  }
  std::cout << refused << " of " << tried << " flips refused, the others in bytes no one reads\n";
  EXPECT_GT(refused, tried / 5) << "the flips should reach the values and HDF5's structures";
}

TEST(CheckpointDigest, ACheckpointWithoutADigestIsAnEarlierBuilds) {
  const std::string dir = fresh_dir("no_digest"), output = make_output(dir);
  write_checkpoint(output, some_checkpoint());
  edit(checkpoint_path(output), [](H5::H5File& f) { f.openGroup("/checkpoint").removeAttr("digest"); });
  EXPECT_NE(refusal(checkpoint_path(output)).find("an earlier build"), std::string::npos);
}

TEST(CheckpointDigest, ADirectoryOrAFifoIsRefusedBeforeHdf5OpensIt) {
  const std::string dir = fresh_dir("special");
  EXPECT_NE(refusal(dir).find("not a regular file"), std::string::npos);
  const std::string fifo = dir + "/fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(refusal(fifo).find("not a regular file"), std::string::npos) << "opening it would block";
  EXPECT_THROW(read_output_meta(fifo), InputError);
}

}  // namespace
}  // namespace icedem
