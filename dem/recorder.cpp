// The HDF5 recorder: buffered, crash-tolerant writing of one run's out.h5 (layout in
// recorder.hpp).
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

#include <sys/statvfs.h>

#include <fmt/format.h>

#include "dem/errors.hpp"
#include "dem/hdf5_io.hpp"

namespace icedem {

namespace {

// version of this file layout, written to /meta format_version; bump on incompatible change
constexpr int kFormatVersion = 1;

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
// both are built from this one list of members
struct EventMember {
  const char* name;
  std::size_t offset;
  bool integer;  // i4, else f8
};
const std::vector<EventMember>& event_members() {
  static const std::vector<EventMember> members{
      {"time", offsetof(FractureEvent, time), false},
      {"floe", offsetof(FractureEvent, floe), true},
      {"joint", offsetof(FractureEvent, joint), true},
      {"mode", offsetof(FractureEvent, mode), true},
      {"ratio", offsetof(FractureEvent, ratio), false},
      {"x", offsetof(FractureEvent, x), false},
      {"z", offsetof(FractureEvent, z), false},
      {"mechanism", offsetof(FractureEvent, mechanism), true},
      {"touching_structure", offsetof(FractureEvent, touching_structure), true},
      {"depth", offsetof(FractureEvent, depth), false},
      {"distance", offsetof(FractureEvent, distance), false},
      {"structure_force", offsetof(FractureEvent, structure_force), false},
      {"press_down", offsetof(FractureEvent, press_down), false},
      {"press_toward", offsetof(FractureEvent, press_toward), false},
      {"ratio_compression", offsetof(FractureEvent, ratio_compression), false},
      {"ratio_shear", offsetof(FractureEvent, ratio_shear), false},
      {"ratio_bending", offsetof(FractureEvent, ratio_bending), false},
      {"ratio_tension", offsetof(FractureEvent, ratio_tension), false},
      {"ratio_in_plane_bending", offsetof(FractureEvent, ratio_in_plane_bending), false},
  };
  return members;
}

H5::CompType fracture_mem_type() {
  H5::CompType type(sizeof(FractureEvent));
  for (const EventMember& m : event_members())
    type.insertMember(m.name, m.offset, m.integer ? H5::PredType::NATIVE_INT : H5::PredType::NATIVE_DOUBLE);
  return type;
}

H5::CompType fracture_file_type() {
  std::size_t size = 0;
  for (const EventMember& m : event_members()) size += m.integer ? 4 : 8;
  H5::CompType type(size);
  std::size_t offset = 0;
  for (const EventMember& m : event_members()) {
    type.insertMember(m.name, offset, m.integer ? H5::PredType::STD_I32LE : H5::PredType::IEEE_F64LE);
    offset += m.integer ? 4 : 8;
  }
  return type;
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

  // per-step series
  Series time, force, moment, surge, cone_contacts, structure_position, awake_bodies, contact_points;
  std::vector<Series> diagnostics = std::vector<Series>(kDiagnosticCount);  // kDiagnosticColumns order
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
    // gather the buffered samples column by column
    std::vector<double> t(n), f(3 * n), m(3 * n), sx(n), p(3 * n);
    std::vector<int> contacts(n), awake(n), points(n);
    for (std::size_t i = 0; i < n; ++i) {
      const LoadSample& s = load_buffer[i];
      t[i] = s.time;
      for (int k = 0; k < 3; ++k) {
        f[3 * i + k] = s.force[k];
        m[3 * i + k] = s.moment[k];
        p[3 * i + k] = s.structure_position[k];
      }
      sx[i] = s.surge();
      contacts[i] = s.cone_contacts;
      awake[i] = s.awake_bodies;
      points[i] = s.contact_points;
    }
    const auto& dbl = H5::PredType::NATIVE_DOUBLE;
    const auto& integer = H5::PredType::NATIVE_INT;
    time.write(t.data(), n, dbl);
    force.write(f.data(), n, dbl);
    moment.write(m.data(), n, dbl);
    surge.write(sx.data(), n, dbl);
    cone_contacts.write(contacts.data(), n, integer);
    structure_position.write(p.data(), n, dbl);
    awake_bodies.write(awake.data(), n, integer);
    contact_points.write(points.data(), n, integer);
    std::vector<double> column(n);
    for (std::size_t c = 0; c < diagnostics.size(); ++c) {
      for (std::size_t i = 0; i < n; ++i) column[i] = load_buffer[i].diagnostics.*kDiagnosticColumns[c].field;
      diagnostics[c].write(column.data(), n, dbl);
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

  void create_layout(const RunMeta& run, const std::vector<BodyOutline>& outlines) {
    // metadata first: a file killed at any later point says what run it belongs to
    meta = std::make_unique<H5::Group>(file->createGroup("/meta"));
    const H5::Group& m = *meta;
    write_attr(m, "format_version", kFormatVersion);
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

    const H5::DataType& f8 = H5::PredType::IEEE_F64LE;
    const H5::DataType& i4 = H5::PredType::STD_I32LE;
    const H5::DataType& u1 = H5::PredType::STD_U8LE;

    // per-step load series
    H5::Group load = file->createGroup("/load");
    time = create_series(load, "time", f8, {}, kSeriesChunkRows, "s", "simulation time");
    force = create_series(load, "force", f8, {3}, kSeriesChunkRows, "N",
                          "force by the ice on the structure, tank frame (x surge, y heave up, "
                          "z sway)");
    moment = create_series(load, "moment", f8, {3}, kSeriesChunkRows, "N m",
                           "moment by the ice on the structure about the cone axis at the "
                           "waterline, tank frame");
    surge = create_series(load, "surge", f8, {}, kSeriesChunkRows, "N",
                          "surge load = -force_x: the load resisting towing, positive");
    cone_contacts = create_series(load, "cone_contacts", i4, {}, kSeriesChunkRows, "1",
                                  "contact points between ice and structure");
    H5::Group structure = file->createGroup("/structure");
    structure_position = create_series(structure, "position", f8, {3}, kSeriesChunkRows, "m",
                                       "structure reference point, tank frame");
    H5::Group diagnostics_group = file->createGroup("/diagnostics");
    awake_bodies = create_series(diagnostics_group, "awake_bodies", i4, {}, kSeriesChunkRows, "1",
                                 "bodies being solved (not sleeping)");
    contact_points = create_series(diagnostics_group, "contact_points", i4, {}, kSeriesChunkRows, "1",
                                   "contact points in the whole world (solver load)");
    for (std::size_t c = 0; c < diagnostics.size(); ++c) {
      const DiagnosticColumn& col = kDiagnosticColumns[c];
      diagnostics[c] = create_series(diagnostics_group, col.name, f8, {}, kSeriesChunkRows, col.unit, col.description);
    }

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
    H5::Group body_group = file->createGroup("/bodies");
    write_fixed(body_group, "floe_id", i4, H5::PredType::NATIVE_INT, {nb}, floe_id.data(), "1",
                "floe id of each body; body order is the snapshot order");
    write_fixed(body_group, "thickness", f8, H5::PredType::NATIVE_DOUBLE, {nb},
                thickness.data(), "m", "body thickness");
    write_fixed(body_group, "vertex_offset", H5::PredType::STD_I64LE, H5::PredType::NATIVE_INT64,
                {nb + 1}, offset.data(), "1",
                "outline of body i is vertices[vertex_offset[i]:vertex_offset[i+1]]");
    write_fixed(body_group, "vertices", f8, H5::PredType::NATIVE_DOUBLE, {nv, 2},
                vertices.data(), "m", "outline vertices in the body frame (x, z)");

    // snapshots: chunks of whole snapshots, sized so that a chunk stays near kSnapshotChunkBytes
    const std::size_t snapshot_bytes = std::max<std::size_t>(bodies, 1) * 4 * sizeof(double);
    const hsize_t snap_rows = std::clamp<hsize_t>(kSnapshotChunkBytes / snapshot_bytes, 1, 256);
    H5::Group snapshots = file->createGroup("/snapshots");
    snap_time = create_series(snapshots, "time", f8, {}, 256, "s", "snapshot time");
    snap_position = create_series(snapshots, "position", f8, {nb, 3}, snap_rows, "m",
                                  "body origin, tank frame");
    snap_orientation =
        create_series(snapshots, "orientation", f8, {nb, 4}, snap_rows, "1",
                      "body-to-tank rotation as a unit quaternion (w, x, y, z)");
    snap_awake = create_series(snapshots, "awake", u1, {nb}, snap_rows, "1",
                               "1 if the body was awake (being solved)");

    // fracture events
    H5::Group fracture = file->createGroup("/fracture");
    events = create_series(fracture, "events", fracture_file_type(), {}, 256,
                           "time: s, floe: 1, joint: 1, mode: 1, ratio: 1, x: m, z: m, mechanism: 1, "
                           "touching_structure: 1, depth: m, distance: m, structure_force: N, "
                           "press_down: N, press_toward: N, ratio_*: 1",
                           "joint breaks: time, floe id, joint index, failure mode code, load/threshold "
                           "ratio of the criterion that fired, joint midpoint, and the floe's state at "
                           "the break: mechanism code, contact with the structure, depth below the "
                           "waterline, horizontal distance from the structure's section at its height, "
                           "contact forces of the structure and of other floes (down, towards the axis), "
                           "load ratio of every criterion");
    flush_file();
  }

  // every object must be closed for the file to close: HDF5 keeps it open while any is
  void close() {
    for (Series* s : {&time, &force, &moment, &surge, &cone_contacts, &structure_position,
                      &awake_bodies, &contact_points, &snap_time, &snap_position, &snap_orientation, &snap_awake,
                      &events})
      s->dataset.reset();
    for (Series& s : diagnostics) s.dataset.reset();
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
    const H5::Group fracture = impl_->file->openGroup("/fracture");
    const hsize_t n = max_ratio.size();
    write_fixed(fracture, "floe_max_ratio", H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, {n},
                max_ratio.data(), "1",
                "per layout floe: the largest load / capacity ratio of any of its joints under any "
                "criterion over the run (0 for rigid floes and lattices never awake)");
    write_fixed(fracture, "floe_min_distance", H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, {n},
                min_distance.data(), "m",
                "per layout floe: the closest a joint midpoint came to the structure's section at its "
                "height, horizontally (inf if never checked)");
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
