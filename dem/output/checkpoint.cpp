#include "dem/output/checkpoint.hpp"

#include <H5Cpp.h>

#include <filesystem>
#include <map>
#include <type_traits>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dem/core/errors.hpp"
#include "dem/core/field_count.hpp"
#include "dem/core/hdf5_io.hpp"
#include "dem/core/isolated_read.hpp"
#include "dem/input/scenario.hpp"
#include "dem/output/file_digest.hpp"

namespace icedem {
namespace {

constexpr const char* kGroup = "/checkpoint";
constexpr const char* kDigest = "digest";  // attribute of kGroup: the digest of everything else

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

std::string read_string(const H5::Group& group, const std::string& name) {
  H5::Attribute attr = group.openAttribute(name);
  std::string value;
  attr.read(attr.getStrType(), value);
  return value;
}

// Writes each field it is shown as a dataset of `group` named after it: plain data as its
// bytes, a vector as its records, Eigen's vectors by their numbers (they are not plain data), a
// struct with fields of its own (the fracture stage's, the load) as a group of them
struct FieldWriter {
  const H5::Group& group;
  template <typename T>
  void operator()(const char* name, const T& v) const {
    if constexpr (HasFields<T>::value) {
      visit_fields(v, FieldWriter{group.createGroup(name)});
    } else if constexpr (IsVector<T>::value) {
      write_records(group, name, v);
    } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
      write_records(group, name, v.data(), 3);
    } else {
      write_records(group, name, &v, 1);
    }
  }
};

// Reads back what FieldWriter wrote
struct FieldReader {
  const H5::Group& group;
  const std::string& path;
  template <typename T>
  void operator()(const char* name, T& v) const {
    if constexpr (HasFields<T>::value) {
      visit_fields(v, FieldReader{group.openGroup(name), path});
    } else if constexpr (IsVector<T>::value) {
      v = read_records<typename T::value_type>(group, name, path);
    } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
      const std::vector<double> x = read_records<double>(group, name, path);
      if (x.size() != 3) throw InputError(fmt::format("{}: checkpoint record {} is not a vector of 3", path, name));
      v = Eigen::Vector3d(x[0], x[1], x[2]);
    } else {
      v = read_record<T>(group, name, path);
    }
  }
};

// a manifold's row in the checkpoint: its bodies and where its points are
struct ManifoldRow {
  int body0, body1;
  int first, count;
};

void write_world(const H5::Group& g, const WorldState& world) {
  write_records(g, "bodies", world.bodies);
  write_records(g, "lattice_replaced", world.lattice_replaced);
  write_records(g, "joint_broken", world.joint_broken);
  write_records(g, "floe_splits", world.splits);
  write_records(g, "floes_left", world.left);
  std::vector<ManifoldRow> rows;
  std::vector<btManifoldPoint> points;
  std::vector<int> has_memory;
  std::vector<btVector3> memory;
  std::vector<int> crushed;
  std::vector<double> crushed_depth;
  for (const ManifoldState& m : world.manifolds) {
    rows.push_back({m.body0, m.body1, static_cast<int>(points.size()), static_cast<int>(m.points.size())});
    crushed.push_back(m.crushed);
    crushed_depth.push_back(m.crushed_depth);
    points.insert(points.end(), m.points.begin(), m.points.end());
    has_memory.insert(has_memory.end(), m.has_friction_memory.begin(), m.has_friction_memory.end());
    memory.insert(memory.end(), m.friction_memory.begin(), m.friction_memory.end());
  }
  write_records(g, "manifolds", rows);
  write_records(g, "contact_points", points);
  write_records(g, "friction_remembered", has_memory);
  write_records(g, "friction_memory", memory);
  write_records(g, "manifold_crushed", crushed);
  write_records(g, "manifold_crushed_depth", crushed_depth);
}

WorldState read_world(const H5::Group& g, const std::string& path) {
  WorldState world;
  world.bodies = read_records<BodyState>(g, "bodies", path);
  world.lattice_replaced = read_records<uint8_t>(g, "lattice_replaced", path);
  world.joint_broken = read_records<uint8_t>(g, "joint_broken", path);
  world.splits = read_records<FloeSplit>(g, "floe_splits", path);
  if (g.nameExists("floes_left")) world.left = read_records<int>(g, "floes_left", path);  // not before leave_behind
  const std::vector<ManifoldRow> rows = read_records<ManifoldRow>(g, "manifolds", path);
  const std::vector<btManifoldPoint> points = read_records<btManifoldPoint>(g, "contact_points", path);
  const std::vector<int> has_memory = read_records<int>(g, "friction_remembered", path);
  const std::vector<btVector3> memory = read_records<btVector3>(g, "friction_memory", path);
  // the crushed ice of crushing manifolds (none in a checkpoint made before it was kept)
  std::vector<int> crushed(rows.size(), 0);
  std::vector<double> crushed_depth(rows.size(), 0.0);
  if (g.nameExists("manifold_crushed")) {
    crushed = read_records<int>(g, "manifold_crushed", path);
    crushed_depth = read_records<double>(g, "manifold_crushed_depth", path);
  }
  if (crushed.size() != rows.size() || crushed_depth.size() != rows.size())
    throw InputError(fmt::format("{}: the checkpoint's crushed ice does not match its contact manifolds: the file is "
                                 "damaged", path));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const ManifoldRow& r = rows[k];
    if (r.first < 0 || r.count <= 0 || static_cast<std::size_t>(r.first + r.count) > points.size() ||
        points.size() != has_memory.size() || points.size() != memory.size())
      throw InputError(fmt::format("{}: the checkpoint's contact points do not add up: the file is damaged", path));
    ManifoldState m;
    m.body0 = r.body0;
    m.body1 = r.body1;
    m.points.assign(points.begin() + r.first, points.begin() + r.first + r.count);
    m.has_friction_memory.assign(has_memory.begin() + r.first, has_memory.begin() + r.first + r.count);
    m.friction_memory.assign(memory.begin() + r.first, memory.begin() + r.first + r.count);
    m.crushed = crushed[k];
    m.crushed_depth = crushed_depth[k];
    world.manifolds.push_back(std::move(m));
  }
  return world;
}

void write_group(H5::H5File& file, const Checkpoint& c) {
  const H5::Group g = file.createGroup(kGroup);
  write_attr(g, "version", c.version);
  visit_fields(c.values, FieldWriter{g.createGroup("state")});
  visit_fields(c.history, FieldWriter{g.createGroup("history")});
  write_world(g.createGroup("world"), c.world);
  if (c.sheet) {
    const H5::Group sheet = g.createGroup("sheet");
    write_records(sheet, "breaks", c.sheet->breaks);
    write_records(sheet, "floe_loads", &c.sheet->floe_loads, 1);
  }
}

// what a part of the file holds, for a refusal to say what it was that changed
std::string described_part(const std::string& part) {
  static const std::map<std::string, std::string> kParts{
      {"/", "the file's own attributes"},
      {"/meta", "the scenario and the run's metadata"},
      {"/load", "the recorded loads"},
      {"/checkpoint", "the checkpoint's version"},
      {"/checkpoint/state", "the run's state"},
      {"/checkpoint/history", "what the statistics are made from"},
      {"/checkpoint/world", "the bodies, joints and contacts"},
      {"/checkpoint/sheet", "the level sheet's breaks"},
  };
  const auto it = kParts.find(part.substr(0, part.find(' ')));
  return it == kParts.end() ? "" : " (" + it->second + ")";
}

// The checkpoint as it was written, or an InputError naming what differs: a checkpoint changed or
// damaged since (an edited scenario, a flipped bit in a record) is never continued
void check_digest(const H5::H5File& file, const H5::Group& g, const std::string& path) {
  FileDigest recorded, now;
  try {
    recorded = parse_digest(read_string(g, kDigest));
    now = file_digest(file, kGroup, kDigest);
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("{}: the checkpoint's digest is damaged ({}): it cannot be resumed", path, e.what()));
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("{}: the checkpoint cannot be read whole ({}): it is damaged and cannot be resumed",
                                 path, e.what()));
  }
  std::vector<std::string> differ = digest_differences(recorded, now);
  for (std::string& part : differ) part += described_part(part);
  if (!differ.empty())
    throw InputError(fmt::format("{}: the checkpoint was changed or damaged after it was written: {} differ{} from "
                                 "its digest. It cannot be resumed; run the scenario again",
                                 path, fmt::join(differ, ", "), differ.size() == 1 ? "s" : ""));
}

// The checkpoint's group, if this build wrote it: else an InputError saying which did
H5::Group checkpoint_group(const H5::H5File& file, const std::string& path) {
  if (!file.nameExists(kGroup)) throw InputError(fmt::format("{}: not a checkpoint (no {} group)", path, kGroup));
  const H5::Group g = file.openGroup(kGroup);
  const std::string version = read_string(g, "version");
  if (version != ICEDEM_VERSION)
    throw InputError(fmt::format("{}: a checkpoint of icedem {}, this is {}: resume it with that version", path,
                                 version, ICEDEM_VERSION));
  if (!g.nameExists("state") || !g.attrExists(kDigest))
    throw InputError(fmt::format("{}: a checkpoint laid out by an earlier build of icedem {}: resume it with that "
                                 "build", path, version));
  return g;
}

// Throws an InputError unless `path` is a checkpoint of this build whose contents are those it was
// written with. Read in a child process (dem/core/isolated_read.hpp): HDF5 may crash on a damaged
// file rather than say so, and a damaged checkpoint is refused, never the command's end
void verify_checkpoint(const std::string& path) {
  std::error_code ec;
  const double megabytes = static_cast<double>(std::filesystem::file_size(path, ec)) / 1e6;
  const IsolatedResult result = read_isolated(
      [&] {
        QuietHdf5 quiet;
        try {
          const H5::H5File file(path, H5F_ACC_RDONLY, H5::FileCreatPropList::DEFAULT, unlocked_access());
          check_digest(file, checkpoint_group(file, path), path);
        } catch (const H5::Exception& e) {
          throw InputError(fmt::format("{}: cannot read the checkpoint ({}): it is damaged and cannot be resumed", path,
                                       hdf5_reason(e)));
        }
        return std::string();
      },
      60.0 + (ec ? 0.0 : megabytes / 20.0));  // the digest reads 400 MB/s here: twenty times that
  if (!result.ok) {
    if (result.value.rfind(path + ": ", 0) == 0) throw InputError(result.value);  // the reader's own refusal
    throw InputError(fmt::format("{}: the file is damaged ({}): the checkpoint cannot be resumed; run the scenario "
                                 "again",
                                 path, result.value));
  }
}

Checkpoint read_group(const H5::H5File& file, const std::string& path) {
  const H5::Group g = checkpoint_group(file, path);
  Checkpoint c;
  c.version = read_string(g, "version");
  visit_fields(c.values, FieldReader{g.openGroup("state"), path});
  visit_fields(c.history, FieldReader{g.openGroup("history"), path});
  c.world = read_world(g.openGroup("world"), path);
  if (g.nameExists("sheet")) {
    const H5::Group sheet = g.openGroup("sheet");
    c.sheet = SheetState{read_records<SheetBreakRecord>(sheet, "breaks", path), {}};
    const auto totals = read_records<AnalyticSheet::FloeLoadTotals>(sheet, "floe_loads", path);
    if (totals.size() != 1)
      throw InputError(fmt::format("{}: the checkpoint's sheet has {} load totals, not one: the file is damaged", path,
                                   totals.size()));
    c.sheet->floe_loads = totals.front();
  }
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
  Checkpoint c{ICEDEM_VERSION, state, capture_world(*state.world), history, std::nullopt};
  if (state.sheet) c.sheet = SheetState{state.sheet->breaks(), state.sheet->floe_load_totals()};
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
      write_attr(file.openGroup(kGroup), kDigest, format_digest(file_digest(file, kGroup, kDigest)));
      file.close();
    }
    sync_file(temporary);
    std::filesystem::rename(temporary, target);  // atomic: the last checkpoint until now
  } catch (const H5::Exception& e) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw OutputError(fmt::format("cannot write the checkpoint {}: {}", target, hdf5_reason(e)));
  } catch (const std::exception& e) {  // the file system's or the digest's
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw OutputError(fmt::format("cannot write the checkpoint {}: {}", target, e.what()));
  }
}

Checkpoint read_checkpoint(const std::string& path) {
  // a directory or a FIFO is refused before HDF5 opens it (it would block on a FIFO)
  if (const std::string why = not_a_file(path); !why.empty())
    throw InputError(fmt::format("{}: cannot read the checkpoint: {}", path, why));
  verify_checkpoint(path);  // then HDF5 reads here what it has read whole once already
  QuietHdf5 quiet;
  try {
    const H5::H5File file(path, H5F_ACC_RDONLY, H5::FileCreatPropList::DEFAULT, unlocked_access());
    return read_group(file, path);
  } catch (const H5::Exception& e) {
    throw InputError(fmt::format("{}: cannot read the checkpoint: {}", path, hdf5_reason(e)));
  }
}

namespace {

// /meta of `path`, read here
OutputMeta read_meta_here(const std::string& path) {
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

// an OutputMeta as text, from the child that read it to the command: each field as its length and
// its characters, so that any text comes through
std::string to_text(const OutputMeta& m) {
  std::string out;
  for (const std::string& field : {m.status, m.scenario_text, m.scenario_path, m.message, std::to_string(m.rows),
                                   fmt::format("{:a}", m.last_time)})
    out += std::to_string(field.size()) + ":" + field;
  return out;
}
OutputMeta from_text(const std::string& text) {
  std::vector<std::string> fields;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t colon = text.find(':', at);
    const std::size_t size = std::stoul(text.substr(at, colon - at));
    fields.push_back(text.substr(colon + 1, size));
    at = colon + 1 + size;
  }
  if (fields.size() != 6) throw std::logic_error("read_output_meta: a reply of " + std::to_string(fields.size()) + " fields");
  return OutputMeta{fields[0], fields[1], fields[2], fields[3], std::stol(fields[4]),
                    std::strtod(fields[5].c_str(), nullptr)};
}

}  // namespace

OutputMeta read_output_meta(const std::string& path) {
  if (const std::string why = not_a_file(path); !why.empty())
    throw InputError(fmt::format("{}: not an icedem output file: {}", path, why));
  // in a child: the file may be damaged, and HDF5 may crash on it (dem/core/isolated_read.hpp)
  const IsolatedResult result = read_isolated([&] { return to_text(read_meta_here(path)); }, 60.0);
  if (!result.ok) {
    if (result.value.rfind(path + ": ", 0) == 0) throw InputError(result.value);
    throw InputError(fmt::format("{}: not an icedem output file, or a damaged one ({})", path, result.value));
  }
  return from_text(result.value);
}

void remove_checkpoint_group(const std::string& path) {
  QuietHdf5 quiet;
  try {
    // the file is locked by its run (dem/output/lock.hpp), not by HDF5
    H5::H5File file(path, H5F_ACC_RDWR, H5::FileCreatPropList::DEFAULT, unlocked_access());
    if (file.nameExists(kGroup)) file.unlink(kGroup);
  } catch (const H5::Exception& e) {
    throw OutputError(fmt::format("{}: cannot remove the checkpoint group: {}", path, hdf5_reason(e)));
  }
}

void restore_state(const Checkpoint& c, State& state) {
  if (c.sheet.has_value() != (state.sheet != nullptr))
    throw InputError(fmt::format("the checkpoint {} an analytic level sheet, the scene {}: it is not this scene's",
                                 c.sheet ? "has" : "has no", state.sheet ? "has one" : "has none"));
  if (c.sheet) {  // the sheet's breaks and the floes' splits, in the order they happened
    for (const SheetBreakRecord& b : c.sheet->breaks) {
      replay_splits(*state.world, c.world.splits, std::min<std::size_t>(b.splits_before, c.world.splits.size()));
      state.sheet->replay(*state.world, b);
    }
    state.sheet->set_floe_load_totals(c.sheet->floe_loads);
  }
  restore_world(*state.world, c.world);
  static_cast<StateValues&>(state) = c.values;
  state.flow->set_structure(state.structure_position, state.structure_velocity);
}

}  // namespace icedem
