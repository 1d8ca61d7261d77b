// The HDF5 recorder: round trip of every dataset and attribute through the HDF5 C++ API, the
// run status life cycle, and files left by runs that died (exception unwinding, SIGKILL).
#include "dem/output/recorder.hpp"

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <tuple>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include <tuple>
#include <vector>

#include "dem/core/build_id.hpp"

namespace icedem {
namespace {

std::string tmp_path(const std::string& name) {
  std::filesystem::create_directories(ICEDEM_TEST_TMP);
  return std::string(ICEDEM_TEST_TMP) + "/" + name;
}

RunMeta test_meta() {
  RunMeta meta;
  // longer than the 64 KiB limit of a compact HDF5 attribute: the resolved scenario of a
  // large layout must still fit
  meta.scenario_text = "# resolved scenario\n" + std::string(100000, 'x') + "\nseed = 7\n";
  meta.scenario_path = "scenarios/paper/small_floes.toml";
  meta.command_line = "icedem run scenarios/paper/small_floes.toml -o out.h5";
  meta.version = "0.1.0";
  meta.build = std::string(40, 'f') + " (modified), RelWithDebInfo, GNU 12.2.0";
  meta.bullet_version = "3.24";
  meta.precision = "double";
  meta.seed = 18446744073709551557ull;  // near 2^64: checks the full unsigned range
  return meta;
}

std::vector<BodyOutline> test_bodies() {
  return {
      {1, {{-0.15, -0.15}, {0.15, -0.15}, {0.15, 0.15}, {-0.15, 0.15}}, 0.033},
      {2, {{-0.3, -0.3}, {0.3, -0.3}, {0.3, 0.3}, {-0.3, 0.3}}, 0.033},
      {2, {{0.0, 0.0}, {0.2, 0.0}, {0.25, 0.1}, {0.1, 0.2}, {-0.05, 0.1}}, 0.040},
  };
}

// a sample whose every field is a distinct function of the row index
LoadSample sample(int i) {
  LoadSample s;
  s.time = 0.02 * i;
  s.force = {-1.0 * i, 2.0 * i, 3.0 * i + 0.5};
  s.moment = {0.1 * i, -0.2 * i, 0.3 * i};
  s.structure_position = {2.0 + 0.0014 * i, 0.0, 0.25};
  s.cone_contacts = i % 7;
  s.awake_bodies = 100 + i;
  s.diagnostics = {0.125 * i, 0.01 * i, 0.5 * i, 100.0 - i, 1e-4 * i, 2e-4 * i};
  return s;
}

std::vector<BodyPose> poses(int k, std::size_t bodies) {
  std::vector<BodyPose> out;
  for (std::size_t b = 0; b < bodies; ++b) {
    const double angle = 0.1 * k + 0.5 * static_cast<double>(b);
    out.push_back({Eigen::Vector3d(k + 0.1 * b, -0.01 * b, 0.5 * k),
                   Eigen::Quaterniond(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY())),
                   (k + b) % 2 == 0});
  }
  return out;
}

// --- reading helpers (HDF5 C++ API) ---

std::vector<hsize_t> shape(const H5::H5File& file, const std::string& name) {
  H5::DataSpace space = file.openDataSet(name).getSpace();
  std::vector<hsize_t> dims(static_cast<std::size_t>(space.getSimpleExtentNdims()));
  space.getSimpleExtentDims(dims.data());
  return dims;
}

template <typename T>
std::vector<T> read(const H5::H5File& file, const std::string& name, const H5::PredType& type) {
  H5::DataSet dataset = file.openDataSet(name);
  std::vector<T> data(static_cast<std::size_t>(dataset.getSpace().getSimpleExtentNpoints()));
  if (!data.empty()) dataset.read(data.data(), type);
  return data;
}

// the snapshots as full fields (k x nb rows): the file holds, per snapshot, the rows of the
// bodies that changed since the one before, each body keeping its latest row
struct Field {
  std::vector<double> position, orientation;  // k x nb x 3, k x nb x 4
  std::vector<uint8_t> awake;                 // k x nb
};
Field full_field(const H5::H5File& file, std::size_t nb);

std::vector<double> read_doubles(const H5::H5File& file, const std::string& name) {
  return read<double>(file, name, H5::PredType::NATIVE_DOUBLE);
}

Field full_field(const H5::H5File& file, std::size_t nb) {
  const auto end = read<int64_t>(file, "/snapshots/end_row", H5::PredType::NATIVE_INT64);
  const auto body = read<int>(file, "/snapshots/rows/body", H5::PredType::NATIVE_INT);
  const std::vector<double> pos = read_doubles(file, "/snapshots/rows/position");
  const std::vector<double> ori = read_doubles(file, "/snapshots/rows/orientation");
  const auto awake = read<uint8_t>(file, "/snapshots/rows/awake", H5::PredType::NATIVE_UINT8);
  Field f;
  std::vector<double> p(3 * nb, 0.0), o(4 * nb, 0.0);
  std::vector<uint8_t> a(nb, 0);
  std::size_t row = 0;
  for (int64_t e : end) {
    for (; row < static_cast<std::size_t>(e); ++row) {
      const std::size_t b = static_cast<std::size_t>(body[row]);
      std::copy(&pos[3 * row], &pos[3 * row] + 3, &p[3 * b]);
      std::copy(&ori[4 * row], &ori[4 * row] + 4, &o[4 * b]);
      a[b] = awake[row];
    }
    f.position.insert(f.position.end(), p.begin(), p.end());
    f.orientation.insert(f.orientation.end(), o.begin(), o.end());
    f.awake.insert(f.awake.end(), a.begin(), a.end());
  }
  return f;
}

std::string string_attr(const H5::H5Object& object, const std::string& name) {
  H5::Attribute attr = object.openAttribute(name);
  std::string value;
  attr.read(attr.getStrType(), value);
  return value;
}

double double_attr(const H5::H5Object& object, const std::string& name) {
  double value = 0.0;
  object.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &value);
  return value;
}

std::string status_of(const std::string& path) {
  H5::H5File file(path, H5F_ACC_RDONLY);
  return string_attr(file.openGroup("/meta"), "status");
}

// every load series has n rows holding sample(0..n-1)
void expect_load_rows(const H5::H5File& file, int n) {
  EXPECT_EQ(shape(file, "/load/time"), (std::vector<hsize_t>{hsize_t(n)}));
  EXPECT_EQ(shape(file, "/load/force"), (std::vector<hsize_t>{hsize_t(n), 3}));
  EXPECT_EQ(shape(file, "/load/moment"), (std::vector<hsize_t>{hsize_t(n), 3}));
  EXPECT_EQ(shape(file, "/load/surge"), (std::vector<hsize_t>{hsize_t(n)}));
  EXPECT_EQ(shape(file, "/load/cone_contacts"), (std::vector<hsize_t>{hsize_t(n)}));
  EXPECT_EQ(shape(file, "/structure/position"), (std::vector<hsize_t>{hsize_t(n), 3}));
  EXPECT_EQ(shape(file, "/diagnostics/awake_bodies"), (std::vector<hsize_t>{hsize_t(n)}));
  const std::vector<double> t = read_doubles(file, "/load/time");
  const std::vector<double> f = read_doubles(file, "/load/force");
  const std::vector<double> m = read_doubles(file, "/load/moment");
  const std::vector<double> surge = read_doubles(file, "/load/surge");
  const std::vector<double> p = read_doubles(file, "/structure/position");
  const auto contacts = read<int>(file, "/load/cone_contacts", H5::PredType::NATIVE_INT);
  const auto awake = read<int>(file, "/diagnostics/awake_bodies", H5::PredType::NATIVE_INT);
  // the diagnostics' dataset names spelled out here, independently of dem/core/diagnostics.hpp
  const std::vector<double> w = read_doubles(file, "/diagnostics/max_angular_speed");
  const std::vector<double> v = read_doubles(file, "/diagnostics/max_speed");
  const std::vector<double> ke = read_doubles(file, "/diagnostics/kinetic_energy");
  const std::vector<double> mass = read_doubles(file, "/diagnostics/ice_mass");
  const std::vector<double> gap = read_doubles(file, "/diagnostics/max_joint_gap");
  const std::vector<double> depth = read_doubles(file, "/diagnostics/max_cone_penetration");
  ASSERT_EQ(t.size(), std::size_t(n));
  for (const auto* d : {&w, &v, &ke, &mass, &gap, &depth}) ASSERT_EQ(d->size(), std::size_t(n));
  // doubles are stored as IEEE f8: the round trip is bit-exact
  for (int i = 0; i < n; ++i) {
    const LoadSample s = sample(i);
    ASSERT_EQ(t[i], s.time) << "row " << i;
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(f[3 * i + k], s.force[k]) << "row " << i;
      ASSERT_EQ(m[3 * i + k], s.moment[k]) << "row " << i;
      ASSERT_EQ(p[3 * i + k], s.structure_position[k]) << "row " << i;
    }
    ASSERT_EQ(surge[i], -s.force.x()) << "row " << i;  // surge = -force_x
    ASSERT_EQ(contacts[i], s.cone_contacts) << "row " << i;
    ASSERT_EQ(awake[i], s.awake_bodies) << "row " << i;
    ASSERT_EQ(w[i], s.diagnostics.max_angular_speed) << "row " << i;
    ASSERT_EQ(v[i], s.diagnostics.max_speed) << "row " << i;
    ASSERT_EQ(ke[i], s.diagnostics.kinetic_energy) << "row " << i;
    ASSERT_EQ(mass[i], s.diagnostics.ice_mass) << "row " << i;
    ASSERT_EQ(gap[i], s.diagnostics.max_joint_gap) << "row " << i;
    ASSERT_EQ(depth[i], s.diagnostics.max_cone_penetration) << "row " << i;
  }
}

TEST(Recorder, RoundTripKeepsEveryValueAndShape) {
  const std::string path = tmp_path("recorder_round_trip.h5");
  const std::vector<BodyOutline> bodies = test_bodies();
  const int n = 1234;  // two full 500-row blocks and a partial one
  const int k = 7;
  const std::vector<FractureEvent> events{
      {1.5, 2, 17, 1, 1.02, 3.25, -0.5, 1, 1, 0.05, 0.0, 12.5, 3.0, 4.0, 0.1, 1.02, 0.3, 0.0, 0.0},
      {1.5, 2, 18, 3, 1.5, 3.5, 0.125, 3, 0, 0.01, 0.75, 0.0, 0.0, 0.5, 0.2, 0.1, 0.4, 1.5, 0.0},
      {9.25, 5, 0, 2, 3.75, 7.0, 1.0, 2, 0, 0.2, 0.125, 0.0, 25.0, 2.0, 0.0, 0.0, 3.75, 0.0, 0.25}};
  {
    Recorder rec(path, test_meta(), bodies);
    for (int i = 0; i < n; ++i) {
      rec.append(sample(i));
      if (i % 200 == 0) rec.append_snapshot(0.02 * i, poses(i / 200, bodies.size()));
      if (i == 300) rec.flush();  // a flush in the middle must not duplicate or lose rows
    }
    for (const FractureEvent& e : events) rec.append_fracture(e);
    rec.set_attributes("/stats", {{"mean_fx_N", 41.5}, {"std_fx_N", 12.25}});
    rec.set_attributes("/stats", {{"mean_fx_N", 42.5}});  // replaces the earlier value
    rec.set_attribute("/layout", "source", "generated");
    rec.set_attributes("/layout", {{"concentration", 0.75}});
    rec.set_attribute("/fracture/events", "mode_names", "1 compression, 2 shear, 3 bending");
    EXPECT_EQ(rec.load_rows(), std::size_t(n));
    rec.finish("complete", "", 12.5);
    EXPECT_TRUE(rec.finished());
  }

  H5::H5File file(path, H5F_ACC_RDONLY);
  expect_load_rows(file, n);
  EXPECT_EQ(string_attr(file.openDataSet("/load/force"), "units"), "N");
  EXPECT_EQ(string_attr(file.openDataSet("/load/moment"), "units"), "N m");
  EXPECT_EQ(string_attr(file.openDataSet("/structure/position"), "units"), "m");

  // bodies: ids, thickness, CSR outlines
  const std::size_t nb = bodies.size();
  EXPECT_EQ(read<int>(file, "/bodies/floe_id", H5::PredType::NATIVE_INT),
            (std::vector<int>{1, 2, 2}));
  EXPECT_EQ(read_doubles(file, "/bodies/thickness"), (std::vector<double>{0.033, 0.033, 0.040}));
  EXPECT_EQ(read<int64_t>(file, "/bodies/vertex_offset", H5::PredType::NATIVE_INT64),
            (std::vector<int64_t>{0, 4, 8, 13}));
  EXPECT_EQ(shape(file, "/bodies/vertices"), (std::vector<hsize_t>{13, 2}));
  const std::vector<double> vertices = read_doubles(file, "/bodies/vertices");
  EXPECT_EQ(vertices[2 * 10 + 0], 0.25);  // body 2, vertex 2: (0.25, 0.1)
  EXPECT_EQ(vertices[2 * 10 + 1], 0.1);

  // snapshots: 7 of 3 bodies, quaternions stored (w, x, y, z)
  EXPECT_EQ(shape(file, "/snapshots/time"), (std::vector<hsize_t>{hsize_t(k)}));
  EXPECT_EQ(shape(file, "/snapshots/end_row"), (std::vector<hsize_t>{hsize_t(k)}));
  const std::vector<double> st = read_doubles(file, "/snapshots/time");
  const Field field = full_field(file, nb);
  const std::vector<double>& pos = field.position;
  const std::vector<double>& ori = field.orientation;
  const std::vector<uint8_t>& awake = field.awake;
  for (int j = 0; j < k; ++j) {
    EXPECT_EQ(st[j], 0.02 * (200 * j));
    const std::vector<BodyPose> expected = poses(j, nb);
    for (std::size_t b = 0; b < nb; ++b) {
      const std::size_t row = j * nb + b;
      for (int c = 0; c < 3; ++c) EXPECT_EQ(pos[3 * row + c], expected[b].position[c]);
      const Eigen::Quaterniond& q = expected[b].orientation;
      EXPECT_EQ(ori[4 * row + 0], q.w());
      EXPECT_EQ(ori[4 * row + 1], q.x());
      EXPECT_EQ(ori[4 * row + 2], q.y());
      EXPECT_EQ(ori[4 * row + 3], q.z());
      EXPECT_EQ(awake[row], expected[b].awake ? 1 : 0);
    }
  }

  // fracture events: a compound of every FractureEvent field, in declaration order; read back
  // by name into the in-memory struct, every field must survive exactly
  EXPECT_EQ(shape(file, "/fracture/events"), (std::vector<hsize_t>{3}));
  H5::DataSet event_set = file.openDataSet("/fracture/events");
  H5::CompType event_type = event_set.getCompType();
  ASSERT_EQ(event_type.getNmembers(), 19);
  EXPECT_EQ(event_type.getMemberName(0), "time");
  EXPECT_EQ(event_type.getMemberName(4), "ratio");
  EXPECT_EQ(event_type.getMemberName(6), "z");
  EXPECT_EQ(event_type.getMemberName(7), "mechanism");
  EXPECT_EQ(event_type.getMemberName(18), "ratio_in_plane_bending");
  H5::CompType mem(sizeof(FractureEvent));
  auto f8 = [&](const char* name, std::size_t offset) { mem.insertMember(name, offset, H5::PredType::NATIVE_DOUBLE); };
  auto i4 = [&](const char* name, std::size_t offset) { mem.insertMember(name, offset, H5::PredType::NATIVE_INT); };
  f8("time", offsetof(FractureEvent, time));
  i4("floe", offsetof(FractureEvent, floe));
  i4("joint", offsetof(FractureEvent, joint));
  i4("mode", offsetof(FractureEvent, mode));
  f8("ratio", offsetof(FractureEvent, ratio));
  f8("x", offsetof(FractureEvent, x));
  f8("z", offsetof(FractureEvent, z));
  i4("mechanism", offsetof(FractureEvent, mechanism));
  i4("touching_structure", offsetof(FractureEvent, touching_structure));
  f8("depth", offsetof(FractureEvent, depth));
  f8("distance", offsetof(FractureEvent, distance));
  f8("structure_force", offsetof(FractureEvent, structure_force));
  f8("press_down", offsetof(FractureEvent, press_down));
  f8("press_toward", offsetof(FractureEvent, press_toward));
  f8("ratio_compression", offsetof(FractureEvent, ratio_compression));
  f8("ratio_shear", offsetof(FractureEvent, ratio_shear));
  f8("ratio_bending", offsetof(FractureEvent, ratio_bending));
  f8("ratio_tension", offsetof(FractureEvent, ratio_tension));
  f8("ratio_in_plane_bending", offsetof(FractureEvent, ratio_in_plane_bending));
  std::vector<FractureEvent> back(3);
  event_set.read(back.data(), mem);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const FractureEvent& a = back[i];
    const FractureEvent& b = events[i];
    EXPECT_EQ(std::make_tuple(a.time, a.floe, a.joint, a.mode, a.ratio, a.x, a.z),
              std::make_tuple(b.time, b.floe, b.joint, b.mode, b.ratio, b.x, b.z));
    EXPECT_EQ(std::make_tuple(a.mechanism, a.touching_structure, a.depth, a.distance, a.structure_force,
                              a.press_down, a.press_toward),
              std::make_tuple(b.mechanism, b.touching_structure, b.depth, b.distance, b.structure_force,
                              b.press_down, b.press_toward));
    EXPECT_EQ(std::make_tuple(a.ratio_compression, a.ratio_shear, a.ratio_bending, a.ratio_tension,
                              a.ratio_in_plane_bending),
              std::make_tuple(b.ratio_compression, b.ratio_shear, b.ratio_bending, b.ratio_tension,
                              b.ratio_in_plane_bending));
  }
  EXPECT_EQ(string_attr(event_set, "mode_names"), "1 compression, 2 shear, 3 bending");

  // metadata
  H5::Group meta = file.openGroup("/meta");
  const RunMeta expected = test_meta();
  EXPECT_EQ(string_attr(meta, "scenario"), expected.scenario_text);
  EXPECT_EQ(string_attr(meta, "scenario_path"), expected.scenario_path);
  EXPECT_EQ(string_attr(meta, "command_line"), expected.command_line);
  EXPECT_EQ(string_attr(meta, "version"), expected.version);
  EXPECT_EQ(string_attr(meta, "build"), expected.build);
  EXPECT_EQ(string_attr(meta, "bullet_version"), expected.bullet_version);
  EXPECT_EQ(string_attr(meta, "precision"), "double");
  uint64_t seed = 0;
  meta.openAttribute("seed").read(H5::PredType::NATIVE_UINT64, &seed);
  EXPECT_EQ(seed, expected.seed);
  EXPECT_EQ(string_attr(meta, "status"), "complete");
  EXPECT_EQ(string_attr(meta, "message"), "");
  EXPECT_EQ(double_attr(meta, "wall_time_s"), 12.5);
  EXPECT_EQ(string_attr(meta, "started_utc").size(), 20u);  // 2024-05-01T12:00:00Z
  EXPECT_EQ(string_attr(meta, "started_utc").back(), 'Z');

  // statistics and layout attributes
  H5::Group stats = file.openGroup("/stats");
  EXPECT_EQ(double_attr(stats, "mean_fx_N"), 42.5);
  EXPECT_EQ(double_attr(stats, "std_fx_N"), 12.25);
  H5::Group layout = file.openGroup("/layout");
  EXPECT_EQ(string_attr(layout, "source"), "generated");
  EXPECT_EQ(double_attr(layout, "concentration"), 0.75);
}

TEST(Recorder, FinishRecordsStatusMessageAndWallTime) {
  // (a file that was never finished says "running": see KilledProcessLeavesFlushedRowsReadable)
  const std::string path = tmp_path("recorder_status.h5");
  Recorder rec(path, test_meta(), test_bodies());
  rec.append(sample(0));
  rec.flush();
  rec.finish("interrupted", "stopped by SIGINT at t = 12.3 s", 4.0);

  // finish() closed the file: it opens here although `rec` still exists
  H5::H5File file(path, H5F_ACC_RDONLY);
  H5::Group meta = file.openGroup("/meta");
  EXPECT_EQ(string_attr(meta, "status"), "interrupted");
  EXPECT_EQ(string_attr(meta, "message"), "stopped by SIGINT at t = 12.3 s");
  EXPECT_EQ(double_attr(meta, "wall_time_s"), 4.0);
  EXPECT_EQ(string_attr(meta, "finished_utc").size(), 20u);  // 2024-05-01T12:00:00Z
  expect_load_rows(file, 1);
}

TEST(Recorder, DestroyedDuringExceptionLeavesIncompleteFileWithAllRows) {
  const std::string path = tmp_path("recorder_unwound.h5");
  const int n = 777;  // one written block and a buffered remainder
  try {
    Recorder rec(path, test_meta(), test_bodies());
    for (int i = 0; i < n; ++i) rec.append(sample(i));
    rec.append_snapshot(1.0, poses(1, 3));
    rec.append_fracture({1.0, 1, 2, 3, 1.1});
    throw std::runtime_error("simulated blow-up");
  } catch (const std::runtime_error&) {
  }
  H5::H5File file(path, H5F_ACC_RDONLY);
  H5::Group meta = file.openGroup("/meta");
  EXPECT_EQ(string_attr(meta, "status"), "incomplete");
  EXPECT_NE(string_attr(meta, "message").find("exception"), std::string::npos);
  expect_load_rows(file, n);
  EXPECT_EQ(shape(file, "/snapshots/end_row"), (std::vector<hsize_t>{1}));
  EXPECT_EQ(shape(file, "/fracture/events"), (std::vector<hsize_t>{1}));
}

// A child process writes `flushed` rows, a snapshot and a break to `path`, flushes, buffers
// 100 rows more and dies: by SIGKILL, or by _exit (no destructors: a crash that runs no
// cleanup). Returns its wait status.
int write_and_die(const std::string& path, int flushed, bool sigkill) {
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    // child: no gtest assertions here, only the exit status reports
    try {
      Recorder rec(path, test_meta(), test_bodies());
      for (int i = 0; i < flushed; ++i) rec.append(sample(i));
      rec.append_snapshot(0.5, poses(0, 3));
      rec.append_fracture({0.5, 1, 2, 3, 1.1});
      rec.flush();
      for (int i = flushed; i < flushed + 100; ++i) rec.append(sample(i));
      if (sigkill) raise(SIGKILL);
      _exit(0);
    } catch (...) {
      _exit(3);
    }
  }
  int wstatus = 0;
  return waitpid(pid, &wstatus, 0) == pid ? wstatus : -1;
}

TEST(Recorder, KilledProcessLeavesFlushedRowsReadable) {
  // the child writes, flushes, buffers more and dies; the parent reads what was flushed
  for (const bool sigkill : {true, false}) {
    SCOPED_TRACE(sigkill ? "SIGKILL" : "_exit");
    const std::string path = tmp_path(sigkill ? "recorder_sigkill.h5" : "recorder_exit.h5");
    const int flushed = 1234;
    const int wstatus = write_and_die(path, flushed, sigkill);
    if (sigkill) {
      ASSERT_TRUE(WIFSIGNALED(wstatus) && WTERMSIG(wstatus) == SIGKILL);
    } else {
      ASSERT_TRUE(WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0);
    }

    H5::H5File file(path, H5F_ACC_RDONLY);
    EXPECT_EQ(string_attr(file.openGroup("/meta"), "status"), "running");
    expect_load_rows(file, flushed);  // the unflushed rows are lost, nothing else
    EXPECT_EQ(shape(file, "/snapshots/end_row"), (std::vector<hsize_t>{1}));
    EXPECT_EQ(shape(file, "/fracture/events"), (std::vector<hsize_t>{1}));
  }
}

TEST(Recorder, ReopenedFileContinuesAfterItsRows) {
  // a writer killed after a flush (its file as a checkpoint keeps it), reopened and continued:
  // the rows end as if written in one go, and the rows it had not flushed are not there twice
  const std::string path = tmp_path("recorder_reopen.h5");
  const int flushed = 1234, total = 2000;
  const int wstatus = write_and_die(path, flushed, true);  // its 100 unflushed rows are lost
  ASSERT_TRUE(WIFSIGNALED(wstatus) && WTERMSIG(wstatus) == SIGKILL);
  {
    Recorder rec(path, Recorder::Reopen{});
    EXPECT_EQ(rec.load_rows(), std::size_t(flushed));
    for (int i = flushed; i < total; ++i) rec.append(sample(i));
    rec.append_snapshot(1.5, poses(1, 3));
    EXPECT_THROW(rec.append_snapshot(2.0, poses(2, 2)), std::invalid_argument);  // the file has 3 bodies
    rec.finish("complete", "", 1.0);
  }
  H5::H5File file(path, H5F_ACC_RDONLY);
  EXPECT_EQ(string_attr(file.openGroup("/meta"), "status"), "complete");
  EXPECT_FALSE(string_attr(file.openGroup("/meta"), "resumed_utc").empty());
  // the build that resumed it, beside the one that started it
  EXPECT_EQ(string_attr(file.openGroup("/meta"), "resumed_build"), build_id().text());
  expect_load_rows(file, total);
  EXPECT_EQ(read_doubles(file, "/snapshots/time"), (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(shape(file, "/snapshots/end_row"), (std::vector<hsize_t>{2}));
  EXPECT_EQ(full_field(file, 3).position.size(), 2u * 3 * 3);
  EXPECT_EQ(shape(file, "/fracture/events"), (std::vector<hsize_t>{1}));
}

TEST(Recorder, BodiesAddedMidRunGetTheirOutlinesAndRowsAndSurviveAReopen) {
  // a floe that splits: body 1 goes (snapshot code 2) and two pieces come in at t = 0.7 s,
  // their outlines after the others', their parent and birth recorded; a reopened file (a run
  // resumed from its checkpoint) knows all of them and adds the next
  const std::string path = tmp_path("recorder_added.h5");
  const BodyOutline piece_a{2, {{-0.1, -0.3}, {0.1, -0.3}, {0.1, 0.3}, {-0.1, 0.3}}, 0.033, 1, 0.7};
  const BodyOutline piece_b{2, {{-0.2, -0.3}, {0.2, -0.3}, {0.2, 0.3}}, 0.033, 1, 0.7};
  {
    Recorder rec(path, test_meta(), test_bodies());
    rec.append_snapshot(0.5, poses(0, 3));
    rec.add_bodies({piece_a, piece_b});
    EXPECT_EQ(rec.body_count(), 5u);
    EXPECT_THROW(rec.append_snapshot(1.0, poses(1, 3)), std::invalid_argument);  // the file has 5 bodies now
    std::vector<BodyPose> now = poses(0, 5);  // bodies 0 and 2 unchanged, 1 gone, the pieces new
    now[1].awake = kBodyGone;
    rec.append_snapshot(1.0, now);
    rec.flush();
  }
  {
    Recorder rec(path, Recorder::Reopen{});
    EXPECT_EQ(rec.body_count(), 5u);
    rec.add_bodies({BodyOutline{2, piece_b.outline, 0.033, 4, 1.2}});
    rec.append_snapshot(1.5, poses(0, 6));
    rec.finish("complete", "", 1.0);
  }
  H5::H5File file(path, H5F_ACC_RDONLY);
  EXPECT_EQ(read<int>(file, "/bodies/floe_id", H5::PredType::NATIVE_INT), (std::vector<int>{1, 2, 2, 2, 2, 2}));
  EXPECT_EQ(read<int>(file, "/bodies/parent", H5::PredType::NATIVE_INT), (std::vector<int>{-1, -1, -1, 1, 1, 4}));
  EXPECT_EQ(read_doubles(file, "/bodies/born"), (std::vector<double>{0, 0, 0, 0.7, 0.7, 1.2}));
  // the outlines in order: the three of the start (4, 4, 5 vertices), then 4, 3 and 3
  EXPECT_EQ(read<int64_t>(file, "/bodies/vertex_offset", H5::PredType::NATIVE_INT64),
            (std::vector<int64_t>{0, 4, 8, 13, 17, 20, 23}));
  const std::vector<double> v = read_doubles(file, "/bodies/vertices");
  ASSERT_EQ(v.size(), 2u * 23);
  EXPECT_EQ(v[2 * 13], -0.1);  // piece a's first vertex
  EXPECT_EQ(v[2 * 17 + 1], -0.3);  // piece b's
  // the second snapshot holds the gone body and the pieces, not the unchanged bodies
  const auto end = read<int64_t>(file, "/snapshots/end_row", H5::PredType::NATIVE_INT64);
  const auto body = read<int>(file, "/snapshots/rows/body", H5::PredType::NATIVE_INT);
  const auto awake = read<uint8_t>(file, "/snapshots/rows/awake", H5::PredType::NATIVE_UINT8);
  ASSERT_EQ(end.size(), 3u);
  EXPECT_EQ(std::vector<int>(body.begin() + end[0], body.begin() + end[1]), (std::vector<int>{1, 3, 4}));
  EXPECT_EQ(awake[end[0]], kBodyGone);
  // the third: the body added after the reopen, and body 1, whose flag the test's poses set to 0
  // (no longer 2); every other body is where the second snapshot left it (the reopened file's
  // field is read back from its rows)
  EXPECT_EQ(std::vector<int>(body.begin() + end[1], body.begin() + end[2]), (std::vector<int>{1, 5}));
}

TEST(Recorder, ReopeningAFileThatIsNotAnOutputNamesIt) {
  const std::string path = tmp_path("recorder_not_output.h5");
  { H5::H5File file(path, H5F_ACC_TRUNC); file.createGroup("/meta"); }
  for (const std::string& p : {path, tmp_path("recorder_missing.h5")}) {
    std::filesystem::remove(tmp_path("recorder_missing.h5"));
    try {
      Recorder rec(p, Recorder::Reopen{});
      FAIL() << p << " was reopened";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
  }
}

TEST(Recorder, ZeroBodiesAndNoEventsGiveEmptyDatasets) {
  const std::string path = tmp_path("recorder_empty.h5");
  {
    Recorder rec(path, test_meta(), {});
    for (int i = 0; i < 10; ++i) rec.append(sample(i));
    rec.append_snapshot(0.0, {});
    rec.append_snapshot(0.1, {});
    rec.finish("complete", "", 0.1);
  }
  H5::H5File file(path, H5F_ACC_RDONLY);
  expect_load_rows(file, 10);
  EXPECT_EQ(shape(file, "/bodies/floe_id"), (std::vector<hsize_t>{0}));
  EXPECT_EQ(shape(file, "/bodies/vertex_offset"), (std::vector<hsize_t>{1}));
  EXPECT_EQ(shape(file, "/bodies/vertices"), (std::vector<hsize_t>{0, 2}));
  EXPECT_EQ(shape(file, "/snapshots/time"), (std::vector<hsize_t>{2}));
  EXPECT_EQ(shape(file, "/snapshots/end_row"), (std::vector<hsize_t>{2}));
  EXPECT_EQ(shape(file, "/snapshots/rows/position"), (std::vector<hsize_t>{0, 3}));
  EXPECT_EQ(shape(file, "/fracture/events"), (std::vector<hsize_t>{0}));
}

TEST(Recorder, UnwritablePathThrowsNamingThePath) {
  const std::string path = "/nonexistent-icedem-dir/sub/out.h5";
  try {
    Recorder rec(path, test_meta(), test_bodies());
    FAIL() << "a file in a missing directory was created";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
  }
}

TEST(Recorder, MisuseIsRejected) {
  const std::string path = tmp_path("recorder_misuse.h5");
  Recorder rec(path, test_meta(), test_bodies());
  // a snapshot must hold one pose per body
  EXPECT_THROW(rec.append_snapshot(0.0, poses(0, 2)), std::invalid_argument);
  rec.finish("failed", "NumericalError: body 3 speed 1e6 m/s at step 10", 1.0);
  EXPECT_THROW(rec.append(sample(0)), std::logic_error);
  EXPECT_THROW(rec.flush(), std::logic_error);
  EXPECT_THROW(rec.finish("complete", "", 1.0), std::logic_error);
  EXPECT_EQ(status_of(path), "failed");
}

}  // namespace
}  // namespace icedem
