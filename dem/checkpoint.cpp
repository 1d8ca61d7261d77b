#include "dem/checkpoint.hpp"

#include <H5Cpp.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <type_traits>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include "dem/errors.hpp"
#include "dem/hdf5_io.hpp"

namespace icedem {
namespace {

constexpr const char* kGroup = "/checkpoint";

// Records are written as this build holds them in memory: bytes, with their size as an
// attribute so that a checkpoint of another layout is refused, not misread
template <typename T>
void write_records(const H5::Group& group, const std::string& name, const T* data, std::size_t count) {
  static_assert(std::is_trivially_copyable_v<T>, "a checkpoint record must be plain data");
  const hsize_t bytes = count * sizeof(T);
  H5::DataSpace space(1, &bytes);
  H5::DataSet set = group.createDataSet(name, H5::PredType::STD_U8LE, space);
  if (bytes) set.write(data, H5::PredType::NATIVE_UINT8);
  write_attr(set, "record_bytes", static_cast<uint64_t>(sizeof(T)));
}
template <typename T>
void write_records(const H5::Group& group, const std::string& name, const std::vector<T>& v) {
  write_records(group, name, v.data(), v.size());
}

template <typename T>
std::vector<T> read_records(const H5::Group& group, const std::string& name, const std::string& path) {
  H5::DataSet set = group.openDataSet(name);
  uint64_t record = 0;
  set.openAttribute("record_bytes").read(H5::PredType::NATIVE_UINT64, &record);
  const hsize_t bytes = static_cast<hsize_t>(set.getSpace().getSimpleExtentNpoints());
  if (record != sizeof(T) || bytes % sizeof(T) != 0)
    throw InputError(fmt::format("{}: checkpoint record {} has {} bytes, this build's {}: the checkpoint was written by "
                                 "another build of icedem",
                                 path, name, record, sizeof(T)));
  std::vector<T> out(bytes / sizeof(T));
  if (bytes) set.read(out.data(), H5::PredType::NATIVE_UINT8);
  return out;
}

template <typename T>
T read_record(const H5::Group& group, const std::string& name, const std::string& path) {
  const std::vector<T> v = read_records<T>(group, name, path);
  if (v.size() != 1) throw InputError(fmt::format("{}: checkpoint record {} is not one record", path, name));
  return v.front();
}

double read_double(const H5::Group& group, const std::string& name) {
  double value = 0;
  group.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &value);
  return value;
}

std::string read_string(const H5::Group& group, const std::string& name) {
  H5::Attribute attr = group.openAttribute(name);
  std::string value;
  attr.read(attr.getStrType(), value);
  return value;
}

// a manifold's row in the checkpoint: its bodies and where its points are
struct ManifoldRow {
  int body0, body1;
  int first, count;
};

// the LoadReading's numbers and the structure's motion (Eigen's vectors are not plain data)
struct LoadRow {
  double force[3], moment[3];
  int contacts;
};
struct MotionRow {
  double position[3], velocity[3];
};

void write_group(H5::H5File& file, const Checkpoint& c) {
  const H5::Group g = file.createGroup(kGroup);
  write_attr(g, "version", c.version);
  write_attr(g, "time", c.time);
  write_attr(g, "step", static_cast<double>(c.step));
  write_attr(g, "first_contact_time",
             c.first_contact_time ? *c.first_contact_time : std::numeric_limits<double>::quiet_NaN());
  write_attr(g, "awake_floes", c.awake_floes);
  write_attr(g, "contact_points", c.contact_points);
  write_attr(g, "awake_sum", c.history.awake_sum);
  write_records(g, "breaks_by_mode", c.breaks_by_mode.data(), c.breaks_by_mode.size());
  write_records(g, "breaks_by_mechanism", c.breaks_by_mechanism.data(), c.breaks_by_mechanism.size());
  write_records(g, "floe_margins", c.floe_margins);
  write_records(g, "filtered_joint_loads", c.filtered_joint_loads);
  const LoadRow load{{c.load.force.x(), c.load.force.y(), c.load.force.z()},
                     {c.load.moment.x(), c.load.moment.y(), c.load.moment.z()},
                     c.load.contacts};
  write_records(g, "load", &load, 1);
  const MotionRow motion{{c.structure_position.x(), c.structure_position.y(), c.structure_position.z()},
                         {c.structure_velocity.x(), c.structure_velocity.y(), c.structure_velocity.z()}};
  write_records(g, "structure_motion", &motion, 1);
  write_records(g, "diagnostics", &c.diagnostics, 1);
  write_records(g, "stage_times", &c.stage_times, 1);
  // the world
  write_records(g, "bodies", c.world.bodies);
  write_records(g, "lattice_replaced", c.world.lattice_replaced);
  write_records(g, "joint_broken", c.world.joint_broken);
  write_records(g, "floe_splits", c.world.splits);
  std::vector<ManifoldRow> rows;
  std::vector<btManifoldPoint> points;
  std::vector<int> has_memory;
  std::vector<btVector3> memory;
  for (const ManifoldState& m : c.world.manifolds) {
    rows.push_back({m.body0, m.body1, static_cast<int>(points.size()), static_cast<int>(m.points.size())});
    points.insert(points.end(), m.points.begin(), m.points.end());
    has_memory.insert(has_memory.end(), m.has_friction_memory.begin(), m.has_friction_memory.end());
    memory.insert(memory.end(), m.friction_memory.begin(), m.friction_memory.end());
  }
  write_records(g, "manifolds", rows);
  write_records(g, "contact_points", points);
  write_records(g, "friction_remembered", has_memory);
  write_records(g, "friction_memory", memory);
  // the run loop's history
  write_records(g, "history_time", c.history.time);
  write_records(g, "history_surge", c.history.surge);
  write_records(g, "history_heave", c.history.heave);
  write_records(g, "history_sway", c.history.sway);
  write_records(g, "history_diagnostics", c.history.diagnostics);
  write_records(g, "history_health", &c.history.health, 1);
}

Checkpoint read_group(const H5::H5File& file, const std::string& path) {
  if (!file.nameExists(kGroup)) throw InputError(fmt::format("{}: not a checkpoint (no {} group)", path, kGroup));
  const H5::Group g = file.openGroup(kGroup);
  Checkpoint c;
  c.version = read_string(g, "version");
  if (c.version != ICEDEM_VERSION)
    throw InputError(fmt::format("{}: a checkpoint of icedem {}, this is {}: resume it with that version", path,
                                 c.version, ICEDEM_VERSION));
  c.time = read_double(g, "time");
  c.step = std::lround(read_double(g, "step"));
  const double first = read_double(g, "first_contact_time");
  if (!std::isnan(first)) c.first_contact_time = first;
  c.awake_floes = static_cast<int>(read_double(g, "awake_floes"));
  c.contact_points = static_cast<int>(read_double(g, "contact_points"));
  c.history.awake_sum = read_double(g, "awake_sum");
  const std::vector<int> modes = read_records<int>(g, "breaks_by_mode", path);
  const std::vector<int> mechanisms = read_records<int>(g, "breaks_by_mechanism", path);
  if (modes.size() != c.breaks_by_mode.size() || mechanisms.size() != c.breaks_by_mechanism.size())
    throw InputError(fmt::format("{}: the checkpoint counts other failure modes: another build of icedem", path));
  std::copy(modes.begin(), modes.end(), c.breaks_by_mode.begin());
  std::copy(mechanisms.begin(), mechanisms.end(), c.breaks_by_mechanism.begin());
  c.floe_margins = read_records<FloeFailureMargin>(g, "floe_margins", path);
  c.filtered_joint_loads = read_records<JointLoads>(g, "filtered_joint_loads", path);
  const LoadRow load = read_record<LoadRow>(g, "load", path);
  c.load.force = Eigen::Vector3d(load.force[0], load.force[1], load.force[2]);
  c.load.moment = Eigen::Vector3d(load.moment[0], load.moment[1], load.moment[2]);
  c.load.contacts = load.contacts;
  const MotionRow motion = read_record<MotionRow>(g, "structure_motion", path);
  c.structure_position = Eigen::Vector3d(motion.position[0], motion.position[1], motion.position[2]);
  c.structure_velocity = Eigen::Vector3d(motion.velocity[0], motion.velocity[1], motion.velocity[2]);
  c.diagnostics = read_record<StepDiagnostics>(g, "diagnostics", path);
  c.stage_times = read_record<StageTimes>(g, "stage_times", path);
  c.world.bodies = read_records<BodyState>(g, "bodies", path);
  c.world.lattice_replaced = read_records<uint8_t>(g, "lattice_replaced", path);
  c.world.joint_broken = read_records<uint8_t>(g, "joint_broken", path);
  if (H5Lexists(g.getId(), "floe_splits", H5P_DEFAULT) > 0)  // written since floes split (fracture.mode "analytic")
    c.world.splits = read_records<FloeSplit>(g, "floe_splits", path);
  const std::vector<ManifoldRow> rows = read_records<ManifoldRow>(g, "manifolds", path);
  const std::vector<btManifoldPoint> points = read_records<btManifoldPoint>(g, "contact_points", path);
  const std::vector<int> has_memory = read_records<int>(g, "friction_remembered", path);
  const std::vector<btVector3> memory = read_records<btVector3>(g, "friction_memory", path);
  for (const ManifoldRow& r : rows) {
    if (r.first < 0 || r.count <= 0 || static_cast<std::size_t>(r.first + r.count) > points.size() ||
        points.size() != has_memory.size() || points.size() != memory.size())
      throw InputError(fmt::format("{}: the checkpoint's contact points do not add up: the file is damaged", path));
    ManifoldState m;
    m.body0 = r.body0;
    m.body1 = r.body1;
    m.points.assign(points.begin() + r.first, points.begin() + r.first + r.count);
    m.has_friction_memory.assign(has_memory.begin() + r.first, has_memory.begin() + r.first + r.count);
    m.friction_memory.assign(memory.begin() + r.first, memory.begin() + r.first + r.count);
    c.world.manifolds.push_back(std::move(m));
  }
  c.history.time = read_records<double>(g, "history_time", path);
  c.history.surge = read_records<double>(g, "history_surge", path);
  c.history.heave = read_records<double>(g, "history_heave", path);
  c.history.sway = read_records<double>(g, "history_sway", path);
  c.history.diagnostics = read_records<StepDiagnostics>(g, "history_diagnostics", path);
  c.history.health = read_record<DiagnosticExtremes>(g, "history_health", path);
  return c;
}

// the file's bytes on the disk before it is renamed into place
void sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

std::string checkpoint_path(const std::string& output) { return output + ".checkpoint"; }

Checkpoint take_checkpoint(const State& state, const RunHistory& history) {
  Checkpoint c;
  c.version = ICEDEM_VERSION;
  c.time = state.time;
  c.step = state.step;
  c.first_contact_time = state.first_contact_time;
  c.breaks_by_mode = state.breaks_by_mode;
  c.breaks_by_mechanism = state.breaks_by_mechanism;
  c.floe_margins = state.floe_margins;
  c.filtered_joint_loads = state.filtered_joint_loads;
  c.load = state.load;
  c.diagnostics = state.diagnostics;
  c.awake_floes = state.awake_floes;
  c.contact_points = state.contact_points;
  c.structure_position = state.structure_position;
  c.structure_velocity = state.structure_velocity;
  c.stage_times = state.stage_times;
  c.world = capture_world(*state.world);
  c.history = history;
  return c;
}

void write_checkpoint(const std::string& output, const Checkpoint& checkpoint) {
  const std::string target = checkpoint_path(output), temporary = target + ".tmp";
  QuietHdf5 quiet;
  try {
    std::filesystem::copy_file(output, temporary, std::filesystem::copy_options::overwrite_existing);
    {
      H5::H5File file(temporary, H5F_ACC_RDWR);
      write_group(file, checkpoint);
      file.close();
    }
    sync_file(temporary);
    std::filesystem::rename(temporary, target);  // atomic: the last checkpoint until now
  } catch (const H5::Exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw OutputError(fmt::format("cannot write the checkpoint {}: {}", target, hdf5_reason(e)));
  } catch (const std::filesystem::filesystem_error& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw OutputError(fmt::format("cannot write the checkpoint {}: {}", target, e.what()));
  }
}

Checkpoint read_checkpoint(const std::string& path) {
  QuietHdf5 quiet;
  try {
    const H5::H5File file(path, H5F_ACC_RDONLY, H5::FileCreatPropList::DEFAULT, unlocked_access());
    return read_group(file, path);
  } catch (const H5::Exception& e) {
    throw InputError(fmt::format("{}: cannot read the checkpoint: {}", path, hdf5_reason(e)));
  }
}

OutputMeta read_output_meta(const std::string& path) {
  QuietHdf5 quiet;
  try {
    const H5::H5File file(path, H5F_ACC_RDONLY, H5::FileCreatPropList::DEFAULT, unlocked_access());
    const H5::Group meta = file.openGroup("/meta");
    OutputMeta m{read_string(meta, "status"), read_string(meta, "scenario"), read_string(meta, "scenario_path"),
                 read_string(meta, "message")};
    const H5::DataSet time = file.openDataSet("/load/time");
    const H5::DataSpace space = time.getSpace();
    hsize_t rows = 0;
    space.getSimpleExtentDims(&rows);
    m.rows = static_cast<long>(rows);
    if (rows > 0) {
      const hsize_t last = rows - 1, one = 1;
      H5::DataSpace select = time.getSpace();
      select.selectHyperslab(H5S_SELECT_SET, &one, &last);
      time.read(&m.last_time, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(1, &one), select);
    }
    return m;
  } catch (const H5::Exception& e) {
    throw InputError(fmt::format("{}: not an icedem output file ({})", path, hdf5_reason(e)));
  }
}

void remove_checkpoint_group(const std::string& path) {
  QuietHdf5 quiet;
  try {
    // the file is locked by its run (dem/output_lock.hpp), not by HDF5
    H5::H5File file(path, H5F_ACC_RDWR, H5::FileCreatPropList::DEFAULT, unlocked_access());
    if (file.nameExists(kGroup)) file.unlink(kGroup);
  } catch (const H5::Exception& e) {
    throw OutputError(fmt::format("{}: cannot remove the checkpoint group: {}", path, hdf5_reason(e)));
  }
}

void restore_state(const Checkpoint& c, State& state) {
  restore_world(*state.world, c.world);
  state.time = c.time;
  state.step = c.step;
  state.first_contact_time = c.first_contact_time;
  state.breaks_by_mode = c.breaks_by_mode;
  state.breaks_by_mechanism = c.breaks_by_mechanism;
  state.floe_margins = c.floe_margins;
  state.filtered_joint_loads = c.filtered_joint_loads;
  state.load = c.load;
  state.diagnostics = c.diagnostics;
  state.awake_floes = c.awake_floes;
  state.contact_points = c.contact_points;
  state.stage_times = c.stage_times;
  state.structure_position = c.structure_position;
  state.structure_velocity = c.structure_velocity;
  state.flow->set_structure(state.structure_position, state.structure_velocity);
}

}  // namespace icedem
