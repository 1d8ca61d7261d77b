// The HDF5 recorder: buffered, crash-tolerant writing of one run's out.h5 (layout in
// dem/output/schema.hpp).
#include "dem/output/recorder.hpp"

#include <H5Cpp.h>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>

#include <sys/statvfs.h>

#include <fmt/format.h>

#include "dem/core/build_id.hpp"
#include "dem/core/errors.hpp"
#include "dem/core/hdf5_io.hpp"
#include "dem/output/file_layout.hpp"
#include "dem/output/schema.hpp"

namespace icedem {

namespace {

// set when a file could not be closed: HDF5 keeps it open and crashes when the process ends
// (HDF5 1.10's exit-time cleanup); Recorder::left_a_file_open() tells the program to skip it
bool g_file_left_open = false;

// how every output file is opened
H5::FileAccPropList output_access() {
  // no file lock: readers may watch a running file (they see the last flush)
  H5::FileAccPropList access = unlocked_access();
  // HDF5 1.8 format: the 1.10 superblock (v3) marks an open file and refuses to open it
  // after a crash until `h5clear -s`; 1.8 files open normally (tested by test_recorder)
  access.setLibverBounds(H5F_LIBVER_V18, H5F_LIBVER_V18);
  // closing the file closes any object still open, so finish() really releases it
  access.setFcloseDegree(H5F_CLOSE_STRONG);
  return access;
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

  OutputDatasets data;  // the growing datasets (dem/output/file_layout.hpp)
  H5::CompType event_mem_type = fracture_event_mem_type();
  H5::CompType sheet_break_type = sheet_break_mem_type();

  // buffers of rows not yet written
  std::vector<LoadSample> load_buffer;
  std::vector<double> snap_time_buffer, snap_position_buffer, snap_orientation_buffer;
  std::vector<int64_t> snap_end_row_buffer;
  std::vector<int> snap_body_buffer;
  std::vector<uint8_t> snap_awake_buffer;
  std::vector<double> snap_mooring_buffer;  // a moored run's lines, x y z of each point
  // the last snapshot's field, every body (position, orientation w x y z, awake): a snapshot
  // writes the rows of the bodies that differ from it
  std::vector<double> last_position, last_orientation;
  std::vector<uint8_t> last_awake;  // BodyActivity, or kNoRow for a body without a row yet
  static constexpr uint8_t kNoRow = 255;
  int64_t snapshot_rows = 0;  // rows written or buffered so far
  std::vector<FractureEvent> event_buffer;

  // an empty field for a new file
  void start_field() {
    last_position.assign(3 * bodies, 0.0);
    last_orientation.assign(4 * bodies, 0.0);
    last_awake.assign(bodies, kNoRow);
  }

  // the field of the last snapshot a file holds, for a run resumed from its checkpoint: its rows
  // replayed in order (rows after the last snapshot's end, from a cut write, are written over)
  void read_field() {
    start_field();
    const hsize_t k = data.snap_time.rows;
    if (data.snap_mooring.dataset) data.snap_mooring.rows = k;  // written before the times: as many or more
    if (k == 0) {
      data.snap_body.rows = data.snap_position.rows = data.snap_orientation.rows = data.snap_awake.rows = 0;
      return;
    }
    // the first `n` rows of a series (a cut write may have left more)
    auto read_rows = [](Series& s, hsize_t n, void* out, const H5::DataType& type) {
      std::vector<hsize_t> block{n};
      block.insert(block.end(), s.row_shape.begin(), s.row_shape.end());
      const std::vector<hsize_t> start(block.size(), 0);
      H5::DataSpace file_space = s.dataset->getSpace();
      file_space.selectHyperslab(H5S_SELECT_SET, block.data(), start.data());
      H5::DataSpace mem_space(static_cast<int>(block.size()), block.data());
      s.dataset->read(out, type, mem_space, file_space);
    };
    std::vector<int64_t> end(k);
    read_rows(data.snap_end_row, k, end.data(), H5::PredType::NATIVE_INT64);
    data.snap_end_row.rows = k;
    const hsize_t rows = static_cast<hsize_t>(end.back());
    std::vector<int> body(rows);
    std::vector<double> position(3 * rows), orientation(4 * rows);
    std::vector<uint8_t> awake(rows);
    if (rows > 0) {
      read_rows(data.snap_body, rows, body.data(), H5::PredType::NATIVE_INT);
      read_rows(data.snap_position, rows, position.data(), H5::PredType::NATIVE_DOUBLE);
      read_rows(data.snap_orientation, rows, orientation.data(), H5::PredType::NATIVE_DOUBLE);
      read_rows(data.snap_awake, rows, awake.data(), H5::PredType::NATIVE_UINT8);
    }
    data.snap_body.rows = data.snap_position.rows = data.snap_orientation.rows = data.snap_awake.rows = rows;
    for (hsize_t r = 0; r < rows; ++r) {
      const std::size_t b = static_cast<std::size_t>(body[r]);
      std::copy(&position[3 * r], &position[3 * r] + 3, &last_position[3 * b]);
      std::copy(&orientation[4 * r], &orientation[4 * r] + 4, &last_orientation[4 * b]);
      last_awake[b] = awake[r];
    }
    snapshot_rows = static_cast<int64_t>(rows);
  }

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
    return load_buffer.size() * sizeof(LoadSample) + snapshot_buffer_bytes() +
           event_buffer.size() * sizeof(FractureEvent);
  }

  // the buffered rows that did not fit: dropped, so that the file can still be closed
  std::size_t drop_buffers() {
    const std::size_t rows = load_buffer.size();
    load_buffer.clear();
    snap_time_buffer.clear();
    snap_end_row_buffer.clear();
    snap_body_buffer.clear();
    snap_position_buffer.clear();
    snap_orientation_buffer.clear();
    snap_awake_buffer.clear();
    snap_mooring_buffer.clear();
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
    for (std::size_t c = 0; c < data.series.size(); ++c) {
      const SeriesColumn& col = series_columns()[c];
      if (!data.series[c].dataset) continue;  // a moored run's column in a towed run's file
      const int width = col.per_line ? static_cast<int>(data.series[c].row_shape.at(0)) : col.width;
      values.resize(n * width);
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < width; ++k) values[width * i + k] = col.value(load_buffer[i], k);
      if (col.element == Element::i4) {
        integers.assign(values.begin(), values.end());
        data.series[c].write(integers.data(), n, H5::PredType::NATIVE_INT);
      } else {
        data.series[c].write(values.data(), n, H5::PredType::NATIVE_DOUBLE);
      }
    }
    load_buffer.clear();
  }

  void write_snapshot_block() {
    const std::size_t k = snap_time_buffer.size();
    if (k == 0) return;
    require_space(buffered_bytes());
    const std::size_t rows = snap_body_buffer.size();
    // the rows first, then the snapshots that point into them: a file cut between the two
    // holds rows no snapshot names, never a snapshot without its rows
    data.snap_body.write(snap_body_buffer.data(), rows, H5::PredType::NATIVE_INT);
    data.snap_position.write(snap_position_buffer.data(), rows, H5::PredType::NATIVE_DOUBLE);
    data.snap_orientation.write(snap_orientation_buffer.data(), rows, H5::PredType::NATIVE_DOUBLE);
    data.snap_awake.write(snap_awake_buffer.data(), rows, H5::PredType::NATIVE_UINT8);
    if (data.snap_mooring.dataset) data.snap_mooring.write(snap_mooring_buffer.data(), k, H5::PredType::NATIVE_DOUBLE);
    data.snap_end_row.write(snap_end_row_buffer.data(), k, H5::PredType::NATIVE_INT64);
    data.snap_time.write(snap_time_buffer.data(), k, H5::PredType::NATIVE_DOUBLE);
    snap_time_buffer.clear();
    snap_end_row_buffer.clear();
    snap_body_buffer.clear();
    snap_position_buffer.clear();
    snap_orientation_buffer.clear();
    snap_awake_buffer.clear();
    snap_mooring_buffer.clear();
  }

  void write_event_block() {
    if (event_buffer.empty()) return;
    require_space(buffered_bytes());
    data.events.write(event_buffer.data(), event_buffer.size(), event_mem_type);
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
    return (snap_time_buffer.size() + snap_end_row_buffer.size()) * 8 +
           (snap_position_buffer.size() + snap_orientation_buffer.size() + snap_mooring_buffer.size()) * sizeof(double) +
           4 * snap_body_buffer.size() + snap_awake_buffer.size();
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

  [[noreturn]] void fail_reopen(const std::string& reason) {
    try {
      close();
    } catch (const H5::Exception&) {
      // already failing; the first error is the one to report
    }
    throw OutputError("output file '" + path + "' is not an icedem run's output laid out as this version writes it: " +
                      reason);
  }

  // every object must be closed for the file to close: HDF5 keeps it open while any is
  void close() {
    data.close();
    meta.reset();
    file->close();
    finished = true;
  }
};

Recorder::Recorder(const std::string& path, const RunMeta& meta, const std::vector<BodyOutline>& bodies,
                   const std::vector<JointRecord>& joints)
    : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  // HDF5's own error printing off for the process: every failure becomes one message of ours
  // (objects closed in destructors would otherwise print kilobytes of HDF5 stack traces)
  H5::Exception::dontPrint();
  QuietHdf5 quiet;
  impl_->require_space(0);  // a full disk: say so before the run, not after
  // create the file
  try {
    impl_->file = std::make_unique<H5::H5File>(path, H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT,
                                               output_access());
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
    impl_->data = create_output_layout(*impl_->file, meta, bodies, joints);
    impl_->meta = std::make_unique<H5::Group>(impl_->file->openGroup("/meta"));
    impl_->bodies = bodies.size();
    impl_->start_field();
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

Recorder::Recorder(const std::string& path, Reopen) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  H5::Exception::dontPrint();
  QuietHdf5 quiet;
  try {
    impl_->file = std::make_unique<H5::H5File>(path, H5F_ACC_RDWR, H5::FileCreatPropList::DEFAULT, output_access());
  } catch (const H5::Exception& e) {
    throw OutputError("cannot open output file '" + path + "' to resume it: " + hdf5_reason(e));
  }
  try {
    impl_->data = open_output_layout(*impl_->file);
    impl_->meta = std::make_unique<H5::Group>(impl_->file->openGroup("/meta"));
    impl_->bodies = static_cast<std::size_t>(
        impl_->file->openDataSet("/bodies/floe_id").getSpace().getSimpleExtentNpoints());
    impl_->appended_rows = static_cast<std::size_t>(impl_->data.series.at(0).rows);
    impl_->read_field();
    write_attr(*impl_->meta, "status", std::string("running"));
    write_attr(*impl_->meta, "resumed_utc", utc_now_iso8601());
    write_attr(*impl_->meta, "resumed_build", build_id().text());
    impl_->flush_file();
  } catch (const H5::Exception& e) {
    impl_->fail_reopen(hdf5_reason(e));
  } catch (const std::out_of_range& e) {  // a dataset without the row shape the layout gives it
    impl_->fail_reopen(e.what());
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

void Recorder::append_snapshot(double time, const std::vector<BodyPose>& poses,
                               const std::vector<Eigen::Vector3d>& mooring_points) {
  impl_->require_open("append_snapshot");
  if (poses.size() != impl_->bodies)
    throw std::invalid_argument("Recorder::append_snapshot: " + std::to_string(poses.size()) +
                                " poses given, the file has " +
                                std::to_string(impl_->bodies) + " bodies");
  Impl& m = *impl_;
  const Series& lines = m.data.snap_mooring;
  const std::size_t points = lines.dataset ? lines.row_shape.at(0) * lines.row_shape.at(1) : 0;
  if (mooring_points.size() != points)
    throw std::invalid_argument(fmt::format("Recorder::append_snapshot: {} mooring line points given, the file has "
                                            "{}", mooring_points.size(), points));
  for (const Eigen::Vector3d& p : mooring_points) m.snap_mooring_buffer.insert(m.snap_mooring_buffer.end(), {p.x(), p.y(), p.z()});
  m.snap_time_buffer.push_back(time);
  const bool first = m.data.snap_time.rows + m.snap_time_buffer.size() == 1;
  for (std::size_t b = 0; b < poses.size(); ++b) {
    const BodyPose& pose = poses[b];
    // stored scalar first (w, x, y, z); Eigen keeps (x, y, z, w) in memory
    const Eigen::Quaterniond& q = pose.orientation;
    const double p[3] = {pose.position.x(), pose.position.y(), pose.position.z()};
    const double o[4] = {q.w(), q.x(), q.y(), q.z()};
    const uint8_t awake = pose.awake;
    double* last_p = &m.last_position[3 * b];
    double* last_o = &m.last_orientation[4 * b];
    if (!first && std::equal(p, p + 3, last_p) && std::equal(o, o + 4, last_o) && awake == m.last_awake[b]) continue;
    std::copy(p, p + 3, last_p);
    std::copy(o, o + 4, last_o);
    m.last_awake[b] = awake;
    m.snap_body_buffer.push_back(static_cast<int>(b));
    m.snap_position_buffer.insert(m.snap_position_buffer.end(), p, p + 3);
    m.snap_orientation_buffer.insert(m.snap_orientation_buffer.end(), o, o + 4);
    m.snap_awake_buffer.push_back(awake);
    ++m.snapshot_rows;
  }
  m.snap_end_row_buffer.push_back(m.snapshot_rows);
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

void Recorder::add_bodies(const std::vector<BodyOutline>& bodies) {
  impl_->require_open("add_bodies");
  if (bodies.empty()) return;
  Impl& m = *impl_;
  QuietHdf5 quiet;
  try {
    m.require_space(4096 + 64 * bodies.size());
    append_bodies(m.data, bodies);
    m.flush_file();
  } catch (const H5::Exception& e) {
    throw OutputError("cannot add bodies to '" + m.path + "': " + hdf5_reason(e));
  }
  m.bodies += bodies.size();
  // no row yet: the next snapshot writes theirs, whatever they are doing
  m.last_position.resize(3 * m.bodies, 0.0);
  m.last_orientation.resize(4 * m.bodies, 0.0);
  m.last_awake.resize(m.bodies, Impl::kNoRow);
}

std::size_t Recorder::body_count() const { return impl_->bodies; }

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

void Recorder::append_sheet_outline(const std::vector<Eigen::Vector2d>& outline) {
  impl_->require_open("append_sheet_outline");
  Impl& m = *impl_;
  if (!m.data.sheet_outline_end_row.dataset)
    throw std::logic_error("Recorder::append_sheet_outline: the file has no /sheet (RunMeta::level_sheet)");
  QuietHdf5 quiet;
  try {
    m.require_space(4096 + 16 * outline.size());
    icedem::append_sheet_outline(m.data, outline);
  } catch (const H5::Exception& e) {
    throw OutputError("cannot write the sheet's outline to '" + m.path + "': " + hdf5_reason(e));
  }
}

void Recorder::append_sheet_break(const SheetBreakRecord& record, const std::vector<Eigen::Vector2d>& outline_after) {
  impl_->require_open("append_sheet_break");
  append_sheet_outline(outline_after);
  Impl& m = *impl_;
  QuietHdf5 quiet;
  try {
    m.data.sheet_breaks.write(&record, 1, m.sheet_break_type);
  } catch (const H5::Exception& e) {
    throw OutputError("cannot write the sheet's break to '" + m.path + "': " + hdf5_reason(e));
  }
}

void Recorder::write_floe_margins(const std::vector<double>& max_ratio,
                                  const std::vector<double>& min_distance) {
  impl_->require_open("write_floe_margins");
  if (max_ratio.size() != min_distance.size())
    throw std::invalid_argument("Recorder::write_floe_margins: one ratio and one distance per floe");
  QuietHdf5 quiet;
  try {
    write_floe_margin_datasets(*impl_->file, max_ratio, min_distance);
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
