// The HDF5 recorder: buffered, crash-tolerant writing of one run's out.h5 (layout in
// dem/output_schema.hpp).
#include "dem/recorder.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include <sys/statvfs.h>

#include <fmt/format.h>

#include "dem/errors.hpp"
#include "dem/hdf5_io.hpp"
#include "dem/output_schema.hpp"

namespace icedem {

namespace {

// rows per chunk of the per-step series: 1024 doubles = 8 KiB, a few seconds of a run
constexpr hsize_t kSeriesChunkRows = 1024;

// target chunk size of the snapshot arrays, bytes (HDF5 advice: 10 KiB to 1 MiB)
constexpr std::size_t kSnapshotChunkBytes = std::size_t(256) << 10;

// set when a file could not be closed: HDF5 keeps it open and crashes when the process ends
// (HDF5 1.10's exit-time cleanup); Recorder::left_a_file_open() tells the program to skip it
bool g_file_left_open = false;

std::string utc_now_iso8601() {
  std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

// fracture events: the in-memory layout is FractureEvent itself, the file layout is packed;
// both are built from the schema's one list of fields
const H5::PredType& event_mem_type(Element e) { return e == Element::i4 ? H5::PredType::NATIVE_INT : H5::PredType::NATIVE_DOUBLE; }
const H5::PredType& event_file_type(Element e) { return e == Element::i4 ? H5::PredType::STD_I32LE : H5::PredType::IEEE_F64LE; }

H5::CompType fracture_mem_type() {
  H5::CompType type(sizeof(FractureEvent));
  for (const EventField& f : event_fields()) type.insertMember(f.name, f.offset, event_mem_type(f.element));
  return type;
}

H5::CompType fracture_file_type() {
  std::size_t size = 0;
  for (const EventField& f : event_fields()) size += event_file_type(f.element).getSize();
  H5::CompType type(size);
  std::size_t offset = 0;
  for (const EventField& f : event_fields()) {
    type.insertMember(f.name, offset, event_file_type(f.element));
    offset += event_file_type(f.element).getSize();
  }
  return type;
}

// "time: s, floe: 1, ...": the units attribute of /fracture/events
std::string event_units() {
  std::string out;
  for (const EventField& f : event_fields()) out += fmt::format("{}{}: {}", out.empty() ? "" : ", ", f.name, f.unit);
  return out;
}

// the file type of a per-step series' element
const H5::PredType& series_file_type(Element e) {
  return e == Element::i4 ? H5::PredType::STD_I32LE : H5::PredType::IEEE_F64LE;
}

// the group and the name of a dataset path: "/load/force" -> "/load", "force"
std::pair<std::string, std::string> split_path(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return {path.substr(0, slash), path.substr(slash + 1)};
}

}  // namespace

struct Recorder::Impl {
  std::string path;
  std::unique_ptr<H5::H5File> file;  // H5 objects are held by pointer: their copy-assignment
  std::unique_ptr<H5::Group> meta;   // operators are unsafe (deprecated implicit copies)
  bool finished = false;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  std::size_t bodies = 0;
  std::size_t appended_rows = 0;

  // per-step series, in series_columns() order
  std::vector<Series> series = std::vector<Series>(series_columns().size());
  // snapshots
  Series snap_time, snap_position, snap_orientation, snap_awake;
  // fracture events
  Series events;
  H5::CompType event_mem_type = fracture_mem_type();

  // buffers of rows not yet written
  std::vector<LoadSample> load_buffer;
  std::vector<double> snap_time_buffer, snap_position_buffer, snap_orientation_buffer;
  std::vector<uint8_t> snap_awake_buffer;
  std::vector<FractureEvent> event_buffer;

  void require_open(const char* what) const {
    if (finished)
      throw std::logic_error(std::string("Recorder::") + what + " called after finish() on '" +
                             path + "'");
  }

  double elapsed_s() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }

  // every write to the file ends here, so the file on disk is consistent between writes
  void flush_file() { file->flush(H5F_SCOPE_GLOBAL); }

  // A write the disk cannot take is refused before it starts: one that fails half-way
  // leaves HDF5 unable to close the file (and HDF5 1.10 crashes at exit on such a file).
  // The margin covers chunk rounding and the metadata a flush and a close write.
  static constexpr std::size_t kSpaceMargin = std::size_t(1) << 20;  // bytes
  void require_space(std::size_t bytes) const {
    struct statvfs fs {};
    const std::string dir = std::filesystem::absolute(path).parent_path().string();
    if (statvfs(dir.c_str(), &fs) != 0) return;  // unknown: let the write say
    const double free_bytes = static_cast<double>(fs.f_bavail) * static_cast<double>(fs.f_frsize);
    if (free_bytes < static_cast<double>(bytes + kSpaceMargin))
      throw OutputError(fmt::format("disk full: {} has {:.0f} kB free, the output needs {:.0f} kB more for its next "
                                    "block and {:.0f} kB to close; free some space and run again",
                                    dir, free_bytes / 1e3, bytes / 1e3, kSpaceMargin / 1e3));
  }

  // bytes the buffered rows take in the file (as in memory: doubles and ints, unpadded)
  std::size_t buffered_bytes() const {
    return load_buffer.size() * sizeof(LoadSample) +
           8 * (snap_time_buffer.size() + snap_position_buffer.size() + snap_orientation_buffer.size()) +
           snap_awake_buffer.size() + event_buffer.size() * sizeof(FractureEvent);
  }

  // the buffered rows that did not fit: dropped, so that the file can still be closed
  std::size_t drop_buffers() {
    const std::size_t rows = load_buffer.size();
    load_buffer.clear();
    snap_time_buffer.clear();
    snap_position_buffer.clear();
    snap_orientation_buffer.clear();
    snap_awake_buffer.clear();
    event_buffer.clear();
    return rows;
  }

  void write_load_block() {
    const std::size_t n = load_buffer.size();
    if (n == 0) return;
    require_space(buffered_bytes());
    // gather the buffered samples column by column, as the schema reads them
    std::vector<double> values;
    std::vector<int> integers;
    for (std::size_t c = 0; c < series.size(); ++c) {
      const SeriesColumn& col = series_columns()[c];
      values.resize(n * col.width);
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < col.width; ++k) values[col.width * i + k] = col.value(load_buffer[i], k);
      if (col.element == Element::i4) {
        integers.assign(values.begin(), values.end());
        series[c].write(integers.data(), n, H5::PredType::NATIVE_INT);
      } else {
        series[c].write(values.data(), n, H5::PredType::NATIVE_DOUBLE);
      }
    }
    load_buffer.clear();
  }

  void write_snapshot_block() {
    const std::size_t k = snap_time_buffer.size();
    if (k == 0) return;
    require_space(buffered_bytes());
    snap_time.write(snap_time_buffer.data(), k, H5::PredType::NATIVE_DOUBLE);
    snap_position.write(snap_position_buffer.data(), k, H5::PredType::NATIVE_DOUBLE);
    snap_orientation.write(snap_orientation_buffer.data(), k, H5::PredType::NATIVE_DOUBLE);
    snap_awake.write(snap_awake_buffer.data(), k, H5::PredType::NATIVE_UINT8);
    snap_time_buffer.clear();
    snap_position_buffer.clear();
    snap_orientation_buffer.clear();
    snap_awake_buffer.clear();
  }

  void write_event_block() {
    if (event_buffer.empty()) return;
    require_space(buffered_bytes());
    events.write(event_buffer.data(), event_buffer.size(), event_mem_type);
    event_buffer.clear();
  }

  void write_all() {
    write_load_block();
    write_snapshot_block();
    write_event_block();
    write_attr(*meta, "wall_time_s", elapsed_s());
    flush_file();
  }

  std::size_t snapshot_buffer_bytes() const {
    return snap_time_buffer.size() * sizeof(double) +
           (snap_position_buffer.size() + snap_orientation_buffer.size()) * sizeof(double) +
           snap_awake_buffer.size();
  }

  /// Calls `fn` with the group or dataset at `object_path`, creating missing groups along it.
  template <typename Fn>
  void with_object(const std::string& object_path, Fn fn) {
    if (object_path.empty() || object_path[0] != '/')
      throw std::invalid_argument("Recorder: attribute target '" + object_path +
                                  "' must be an absolute HDF5 path such as \"/stats\"");
    // walk the path one component at a time: nameExists fails on a missing parent
    std::string prefix;
    std::size_t pos = 1;
    while (pos <= object_path.size()) {
      std::size_t next = object_path.find('/', pos);
      if (next == std::string::npos) next = object_path.size();
      if (next > pos) {
        prefix += "/" + object_path.substr(pos, next - pos);
        if (!file->nameExists(prefix)) file->createGroup(prefix);
      }
      pos = next + 1;
    }
    if (prefix.empty()) prefix = "/";
    if (prefix != "/" && file->childObjType(prefix) == H5O_TYPE_DATASET) {
      fn(static_cast<const H5::H5Object&>(file->openDataSet(prefix)));
    } else {
      fn(static_cast<const H5::H5Object&>(file->openGroup(prefix)));
    }
  }

  // the group a dataset path lives in, created on first use
  H5::Group parent_group(const std::string& path) {
    const std::string group = split_path(path).first;
    return file->nameExists(group) ? file->openGroup(group) : file->createGroup(group);
  }

  // a growing dataset of one of the schema's other datasets (units and description from it)
  Series schema_series(const std::string& path, const H5::DataType& type, const std::vector<hsize_t>& row_shape,
                       hsize_t chunk_rows, const std::string& units) {
    const DatasetEntry& e = dataset_entry(path);
    return create_series(parent_group(path), split_path(path).second, type, row_shape, chunk_rows, units,
                         e.description);
  }
  Series schema_series(const std::string& path, const H5::DataType& type, const std::vector<hsize_t>& row_shape,
                       hsize_t chunk_rows) {
    return schema_series(path, type, row_shape, chunk_rows, dataset_entry(path).unit);
  }

  // a fixed dataset of the schema, written in one go
  void schema_fixed(const std::string& path, const H5::DataType& file_type, const H5::DataType& mem_type,
                    const std::vector<hsize_t>& dims, const void* data) {
    const DatasetEntry& e = dataset_entry(path);
    write_fixed(parent_group(path), split_path(path).second, file_type, mem_type, dims, data, e.unit, e.description);
  }

  void create_layout(const RunMeta& run, const std::vector<BodyOutline>& outlines) {
    // metadata first: a file killed at any later point says what run it belongs to
    meta = std::make_unique<H5::Group>(file->createGroup("/meta"));
    const H5::Group& m = *meta;
    write_attr(m, "format_version", kOutputFormatVersion);
    write_attr(m, "scenario", run.scenario_text);
    write_attr(m, "scenario_path", run.scenario_path);
    write_attr(m, "command_line", run.command_line);
    write_attr(m, "version", run.version);
    write_attr(m, "bullet_version", run.bullet_version);
    write_attr(m, "precision", run.precision);
    write_attr(m, "seed", run.seed);
    write_attr(m, "started_utc", utc_now_iso8601());
    write_attr(m, "status", std::string("running"));
    write_attr(m, "message", std::string(""));
    write_attr(m, "wall_time_s", 0.0);

    // per-step series: load, structure, diagnostics
    for (std::size_t c = 0; c < series.size(); ++c) {
      const SeriesColumn& col = series_columns()[c];
      const std::vector<hsize_t> row_shape = col.width == 1 ? std::vector<hsize_t>{} : std::vector<hsize_t>{hsize_t(col.width)};
      series[c] = create_series(parent_group(col.path), split_path(col.path).second, series_file_type(col.element),
                                row_shape, kSeriesChunkRows, col.unit, col.description);
    }

    const H5::DataType& f8 = H5::PredType::IEEE_F64LE;

    // body outlines: a flat vertex list indexed by offsets (CSR), since outlines differ in size
    bodies = outlines.size();
    std::vector<int> floe_id(bodies);
    std::vector<double> thickness(bodies), vertices;
    std::vector<int64_t> offset(bodies + 1, 0);
    for (std::size_t i = 0; i < bodies; ++i) {
      floe_id[i] = outlines[i].floe_id;
      thickness[i] = outlines[i].thickness;
      for (const Eigen::Vector2d& v : outlines[i].outline) {
        vertices.push_back(v.x());
        vertices.push_back(v.y());
      }
      offset[i + 1] = offset[i] + static_cast<int64_t>(outlines[i].outline.size());
    }
    const hsize_t nb = bodies, nv = vertices.size() / 2;
    schema_fixed("/bodies/floe_id", H5::PredType::STD_I32LE, H5::PredType::NATIVE_INT, {nb}, floe_id.data());
    schema_fixed("/bodies/thickness", f8, H5::PredType::NATIVE_DOUBLE, {nb}, thickness.data());
    schema_fixed("/bodies/vertex_offset", H5::PredType::STD_I64LE, H5::PredType::NATIVE_INT64, {nb + 1}, offset.data());
    schema_fixed("/bodies/vertices", f8, H5::PredType::NATIVE_DOUBLE, {nv, 2}, vertices.data());

    // snapshots: chunks of whole snapshots, sized so that a chunk stays near kSnapshotChunkBytes
    const std::size_t snapshot_bytes = std::max<std::size_t>(bodies, 1) * 4 * sizeof(double);
    const hsize_t snap_rows = std::clamp<hsize_t>(kSnapshotChunkBytes / snapshot_bytes, 1, 256);
    snap_time = schema_series("/snapshots/time", f8, {}, 256);
    snap_position = schema_series("/snapshots/position", f8, {nb, 3}, snap_rows);
    snap_orientation = schema_series("/snapshots/orientation", f8, {nb, 4}, snap_rows);
    snap_awake = schema_series("/snapshots/awake", H5::PredType::STD_U8LE, {nb}, snap_rows);

    // fracture events (/fracture/floe_* are written at the end, by write_floe_margins)
    events = schema_series("/fracture/events", fracture_file_type(), {}, 256, event_units());
    flush_file();
  }

  // every object must be closed for the file to close: HDF5 keeps it open while any is
  void close() {
    for (Series* s : {&snap_time, &snap_position, &snap_orientation, &snap_awake, &events}) s->dataset.reset();
    for (Series& s : series) s.dataset.reset();
    meta.reset();
    file->close();
    finished = true;
  }
};

Recorder::Recorder(const std::string& path, const RunMeta& meta,
                   const std::vector<BodyOutline>& bodies)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  // HDF5's own error printing off for the process: every failure becomes one message of ours
  // (objects closed in destructors would otherwise print kilobytes of HDF5 stack traces)
  H5::Exception::dontPrint();
  QuietHdf5 quiet;
  impl_->require_space(0);  // a full disk: say so before the run, not after
  // create the file
  try {
    H5::FileAccPropList access;
    // HDF5 1.8 format: the 1.10 superblock (v3) marks an open file and refuses to open it
    // after a crash until `h5clear -s`; 1.8 files open normally (tested by test_recorder)
    access.setLibverBounds(H5F_LIBVER_V18, H5F_LIBVER_V18);
    // no file lock: readers may watch a running file (they see the last flush)
#if H5_VERSION_GE(1, 10, 7)
    H5Pset_file_locking(access.getId(), false, true);
#endif
    // closing the file closes any object still open, so finish() really releases it
    access.setFcloseDegree(H5F_CLOSE_STRONG);
    impl_->file = std::make_unique<H5::H5File>(path, H5F_ACC_TRUNC,
                                               H5::FileCreatPropList::DEFAULT, access);
  } catch (const H5::Exception& e) {
    std::string reason = hdf5_reason(e);
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec))
      reason = "directory '" + parent.string() + "' does not exist";
    throw OutputError("cannot create output file '" + path + "': " + reason);
  }
  // lay it out
  try {
    impl_->create_layout(meta, bodies);
  } catch (const H5::Exception& e) {
    std::string reason = hdf5_reason(e);
    try {
      impl_->close();
    } catch (const H5::Exception&) {
      // already failing; the first error is the one to report
    }
    throw OutputError("cannot write the layout of output file '" + path + "': " + reason);
  }
}

void Recorder::append(const LoadSample& sample) {
  impl_->require_open("append");
  impl_->load_buffer.push_back(sample);
  ++impl_->appended_rows;
  if (impl_->load_buffer.size() >= kBlockRows) {
    QuietHdf5 quiet;
    try {
      impl_->write_load_block();
      impl_->flush_file();
    } catch (const H5::Exception& e) {
      throw OutputError("cannot write load samples to '" + impl_->path +
                        "': " + hdf5_reason(e));
    }
  }
}

void Recorder::append_snapshot(double time, const std::vector<BodyPose>& poses) {
  impl_->require_open("append_snapshot");
  if (poses.size() != impl_->bodies)
    throw std::invalid_argument("Recorder::append_snapshot: " + std::to_string(poses.size()) +
                                " poses given, the file was created with " +
                                std::to_string(impl_->bodies) + " bodies");
  impl_->snap_time_buffer.push_back(time);
  for (const BodyPose& pose : poses) {
    for (int k = 0; k < 3; ++k) impl_->snap_position_buffer.push_back(pose.position[k]);
    // stored scalar first (w, x, y, z); Eigen keeps (x, y, z, w) in memory
    const Eigen::Quaterniond& q = pose.orientation;
    impl_->snap_orientation_buffer.insert(impl_->snap_orientation_buffer.end(),
                                          {q.w(), q.x(), q.y(), q.z()});
    impl_->snap_awake_buffer.push_back(pose.awake ? 1 : 0);
  }
  if (impl_->snapshot_buffer_bytes() >= kSnapshotBufferBytes) {
    QuietHdf5 quiet;
    try {
      impl_->write_snapshot_block();
      impl_->flush_file();
    } catch (const H5::Exception& e) {
      throw OutputError("cannot write snapshots to '" + impl_->path +
                        "': " + hdf5_reason(e));
    }
  }
}

void Recorder::append_fracture(const FractureEvent& event) {
  impl_->require_open("append_fracture");
  impl_->event_buffer.push_back(event);
  if (impl_->event_buffer.size() >= kBlockRows) {
    QuietHdf5 quiet;
    try {
      impl_->write_event_block();
      impl_->flush_file();
    } catch (const H5::Exception& e) {
      throw OutputError("cannot write fracture events to '" + impl_->path +
                        "': " + hdf5_reason(e));
    }
  }
}

void Recorder::write_floe_margins(const std::vector<double>& max_ratio,
                                  const std::vector<double>& min_distance) {
  impl_->require_open("write_floe_margins");
  if (max_ratio.size() != min_distance.size())
    throw std::invalid_argument("Recorder::write_floe_margins: one ratio and one distance per floe");
  QuietHdf5 quiet;
  try {
    const hsize_t n = max_ratio.size();
    impl_->schema_fixed("/fracture/floe_max_ratio", H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, {n},
                        max_ratio.data());
    impl_->schema_fixed("/fracture/floe_min_distance", H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, {n},
                        min_distance.data());
    impl_->flush_file();
  } catch (const H5::Exception& e) {
    throw OutputError("cannot write floe margins to '" + impl_->path + "': " + hdf5_reason(e));
  }
}

void Recorder::set_attributes(const std::string& group,
                              const std::map<std::string, double>& values) {
  impl_->require_open("set_attributes");
  QuietHdf5 quiet;
  try {
    impl_->with_object(group, [&](const H5::H5Object& object) {
      for (const auto& [name, value] : values) write_attr(object, name, value);
    });
    impl_->flush_file();
  } catch (const H5::Exception& e) {
    throw OutputError("cannot write attributes on '" + group + "' in '" + impl_->path +
                             "': " + hdf5_reason(e));
  }
}

void Recorder::set_attribute(const std::string& group, const std::string& name,
                             const std::string& value) {
  impl_->require_open("set_attribute");
  QuietHdf5 quiet;
  try {
    impl_->with_object(group, [&](const H5::H5Object& object) { write_attr(object, name, value); });
    impl_->flush_file();
  } catch (const H5::Exception& e) {
    throw OutputError("cannot write attribute '" + name + "' on '" + group + "' in '" +
                             impl_->path + "': " + hdf5_reason(e));
  }
}

void Recorder::flush() {
  impl_->require_open("flush");
  QuietHdf5 quiet;
  try {
    impl_->write_all();
  } catch (const H5::Exception& e) {
    throw OutputError("cannot flush output file '" + impl_->path +
                             "': " + hdf5_reason(e));
  }
}

void Recorder::finish(const std::string& status, const std::string& message,
                      double wall_time_s) {
  impl_->require_open("finish");
  QuietHdf5 quiet;
  try {
    std::string note = message;
    try {
      impl_->write_all();
    } catch (const OutputError& e) {  // the disk is full: close with what fitted
      const std::size_t dropped = impl_->drop_buffers();
      note += fmt::format("{}the last {} load rows (and their snapshots and breaks) did not fit on the disk: {}",
                          note.empty() ? "" : "; ", dropped, e.what());
    }
    write_attr(*impl_->meta, "status", status);
    write_attr(*impl_->meta, "message", note);
    write_attr(*impl_->meta, "wall_time_s", wall_time_s);
    write_attr(*impl_->meta, "finished_utc", utc_now_iso8601());
    impl_->flush_file();
    impl_->close();
  } catch (const H5::Exception& e) {
    g_file_left_open = true;
    throw OutputError("cannot finish output file '" + impl_->path + "': " + hdf5_reason(e));
  }
}

bool Recorder::left_a_file_open() { return g_file_left_open; }

bool Recorder::finished() const { return impl_->finished; }

std::size_t Recorder::load_rows() const { return impl_->appended_rows; }

Recorder::~Recorder() {
  if (!impl_ || impl_->finished) return;
  // the run ended without finish(): keep what we have and say so
  QuietHdf5 quiet;
  try {
    impl_->write_all();
    const bool unwinding = std::uncaught_exceptions() > 0;
    write_attr(*impl_->meta, "status", std::string("incomplete"));
    write_attr(*impl_->meta, "message",
               std::string("the recorder was destroyed without finish()") +
                   (unwinding ? " while an exception was propagating" : ""));
    impl_->flush_file();
    impl_->close();
  } catch (const H5::Exception& e) {
    g_file_left_open = true;
    std::fprintf(stderr, "icedem: could not close output file '%s' cleanly: %s\n",
                 impl_->path.c_str(), hdf5_reason(e).c_str());
  } catch (const std::exception& e) {
    g_file_left_open = true;
    std::fprintf(stderr, "icedem: could not close output file '%s' cleanly: %s\n",
                 impl_->path.c_str(), e.what());
  } catch (...) {
    g_file_left_open = true;
    std::fprintf(stderr, "icedem: could not close output file '%s' cleanly\n",
                 impl_->path.c_str());
  }
}

}  // namespace icedem
