// Lays out a new output file from the schema (dem/output/file_layout.hpp).
#include "dem/output/file_layout.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <ctime>
#include <utility>

#include <fmt/format.h>

#include "dem/output/schema.hpp"

namespace icedem {

namespace {

// rows per chunk of the per-step series: 1024 doubles = 8 KiB, a few seconds of a run
constexpr hsize_t kSeriesChunkRows = 1024;

// rows per chunk of /bodies (a 96,000-floe field: 24 chunks, each a few kB compressed)
constexpr hsize_t kBodyChunkRows = 4096;

// target chunk size of the snapshot arrays, bytes (HDF5 advice: 10 KiB to 1 MiB)
constexpr std::size_t kSnapshotChunkBytes = std::size_t(256) << 10;

// the HDF5 types of an i4 or f8 element: in the file (little-endian), and in memory
const H5::PredType& file_type(Element e) { return e == Element::i4 ? H5::PredType::STD_I32LE : H5::PredType::IEEE_F64LE; }
const H5::PredType& memory_type(Element e) { return e == Element::i4 ? H5::PredType::NATIVE_INT : H5::PredType::NATIVE_DOUBLE; }

// fracture events and the sheet's breaks: the in-memory layout is the record itself, the file layout is packed;
// both are built from the schema's one list of fields
H5::CompType packed_file_type(const std::vector<EventField>& fields) {
  std::size_t size = 0;
  for (const EventField& f : fields) size += file_type(f.element).getSize();
  H5::CompType type(size);
  std::size_t offset = 0;
  for (const EventField& f : fields) {
    type.insertMember(f.name, offset, file_type(f.element));
    offset += file_type(f.element).getSize();
  }
  return type;
}

// "time: s, floe: 1, ...": the units attribute of a dataset of records
std::string field_units(const std::vector<EventField>& fields) {
  std::string out;
  for (const EventField& f : fields) out += fmt::format("{}{}: {}", out.empty() ? "" : ", ", f.name, f.unit);
  return out;
}

H5::CompType memory_type_of(const std::vector<EventField>& fields, std::size_t size) {
  H5::CompType type(size);
  for (const EventField& f : fields) type.insertMember(f.name, f.offset, memory_type(f.element));
  return type;
}

// the group and the name of a dataset path: "/load/force" -> "/load", "force"
std::pair<std::string, std::string> split_path(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return {path.substr(0, slash), path.substr(slash + 1)};
}

// the group a dataset path lives in, created on first use
H5::Group parent_group(H5::H5File& file, const std::string& path) {
  const std::string group = split_path(path).first;
  return file.nameExists(group) ? file.openGroup(group) : file.createGroup(group);
}

// a growing dataset of one of the schema's other datasets (units and description from it)
Series schema_series(H5::H5File& file, const std::string& path, const H5::DataType& type, const std::vector<hsize_t>& row_shape,
                     hsize_t chunk_rows, const std::string& units) {
  const DatasetEntry& e = dataset_entry(path);
  // the snapshots' rows grow with the field's motion; shuffle and deflate halve them. /bodies
  // holds the field: compressed, a field of equal outlines costs almost nothing
  const bool compress = path.rfind("/snapshots/rows/", 0) == 0 || path.rfind("/bodies/", 0) == 0;
  return create_series(parent_group(file, path), split_path(path).second, type, row_shape, chunk_rows, units,
                       e.description, compress);
}
Series schema_series(H5::H5File& file, const std::string& path, const H5::DataType& type, const std::vector<hsize_t>& row_shape,
                     hsize_t chunk_rows) {
  return schema_series(file, path, type, row_shape, chunk_rows, dataset_entry(path).unit);
}

// a fixed dataset of the schema, written in one go
void schema_fixed(H5::H5File& file, const std::string& path, const H5::DataType& file_type, const H5::DataType& mem_type,
                  const std::vector<hsize_t>& dims, const void* data) {
  const DatasetEntry& e = dataset_entry(path);
  // /bodies grows with the field: compressed, a field of equal outlines costs almost nothing
  write_fixed(parent_group(file, path), split_path(path).second, file_type, mem_type, dims, data, e.unit, e.description,
              true);
}

// every growing dataset of OutputDatasets besides the per-step series, with its path: what a
// reopened file opens and what closing releases
const std::vector<std::pair<Series OutputDatasets::*, const char*>>& growing_datasets() {
  static const std::vector<std::pair<Series OutputDatasets::*, const char*>> all{
      {&OutputDatasets::snap_time, "/snapshots/time"},
      {&OutputDatasets::snap_end_row, "/snapshots/end_row"},
      {&OutputDatasets::snap_body, "/snapshots/rows/body"},
      {&OutputDatasets::snap_position, "/snapshots/rows/position"},
      {&OutputDatasets::snap_orientation, "/snapshots/rows/orientation"},
      {&OutputDatasets::snap_awake, "/snapshots/rows/awake"},
      {&OutputDatasets::events, "/fracture/events"},
      {&OutputDatasets::body_floe_id, "/bodies/floe_id"},
      {&OutputDatasets::body_thickness, "/bodies/thickness"},
      {&OutputDatasets::body_vertex_offset, "/bodies/vertex_offset"},
      {&OutputDatasets::body_vertices, "/bodies/vertices"},
      {&OutputDatasets::body_parent, "/bodies/parent"},
      {&OutputDatasets::body_born, "/bodies/born"},
  };
  return all;
}

// the analytic level sheet's datasets (RunMeta::level_sheet): in its runs' files only
const std::vector<std::pair<Series OutputDatasets::*, const char*>>& sheet_datasets() {
  static const std::vector<std::pair<Series OutputDatasets::*, const char*>> all{
      {&OutputDatasets::sheet_breaks, "/sheet/breaks"},
      {&OutputDatasets::sheet_outline_end_row, "/sheet/outline_end_row"},
      {&OutputDatasets::sheet_outline_vertices, "/sheet/outline_vertices"},
  };
  return all;
}

}  // namespace

std::string utc_now_iso8601() {
  std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

H5::CompType fracture_event_mem_type() { return memory_type_of(event_fields(), sizeof(FractureEvent)); }

H5::CompType sheet_break_mem_type() { return memory_type_of(sheet_break_fields(), sizeof(SheetBreakRecord)); }

void append_sheet_outline(OutputDatasets& d, const std::vector<Eigen::Vector2d>& outline) {
  std::vector<double> vertices;
  for (const Eigen::Vector2d& v : outline) vertices.insert(vertices.end(), {v.x(), v.y()});
  const int64_t end = static_cast<int64_t>(d.sheet_outline_vertices.rows + outline.size());
  d.sheet_outline_vertices.write(vertices.data(), outline.size(), H5::PredType::NATIVE_DOUBLE);
  d.sheet_outline_end_row.write(&end, 1, H5::PredType::NATIVE_INT64);
}

OutputDatasets create_output_layout(H5::H5File& file, const RunMeta& run, const std::vector<BodyOutline>& outlines,
                                    const std::vector<JointRecord>& joints) {
  OutputDatasets d;
  d.series.resize(series_columns().size());
  // metadata first: a file killed at any later point says what run it belongs to
  const H5::Group m = file.createGroup("/meta");
  write_attr(m, "format_version", kOutputFormatVersion);
  write_attr(m, "scenario", run.scenario_text);
  write_attr(m, "scenario_path", run.scenario_path);
  write_attr(m, "command_line", run.command_line);
  write_attr(m, "version", run.version);
  write_attr(m, "build", run.build);
  write_attr(m, "bullet_version", run.bullet_version);
  write_attr(m, "precision", run.precision);
  write_attr(m, "seed", run.seed);
  write_attr(m, "started_utc", utc_now_iso8601());
  write_attr(m, "status", std::string("running"));
  write_attr(m, "message", std::string(""));
  write_attr(m, "wall_time_s", 0.0);

  // per-step series: load, structure, diagnostics
  for (std::size_t c = 0; c < d.series.size(); ++c) {
    const SeriesColumn& col = series_columns()[c];
    if (col.moored && run.mooring_lines == 0) continue;  // a towed run's file has none of a moored one's
    const std::vector<hsize_t> row_shape = col.per_line      ? std::vector<hsize_t>{hsize_t(run.mooring_lines)}
                                           : col.width == 1 ? std::vector<hsize_t>{}
                                                            : std::vector<hsize_t>{hsize_t(col.width)};
    d.series[c] = create_series(parent_group(file, col.path), split_path(col.path).second, file_type(col.element),
                              row_shape, kSeriesChunkRows, col.unit, col.description);
  }

  const H5::DataType& f8 = H5::PredType::IEEE_F64LE;

  // body outlines: a flat vertex list indexed by offsets (CSR), since outlines differ in size;
  // growing datasets, since a floe that splits adds its pieces (fracture.mode = "analytic")
  const H5::DataType& i4_file = H5::PredType::STD_I32LE;
  d.body_floe_id = schema_series(file, "/bodies/floe_id", i4_file, {}, kBodyChunkRows);
  d.body_thickness = schema_series(file, "/bodies/thickness", f8, {}, kBodyChunkRows);
  d.body_vertex_offset = schema_series(file, "/bodies/vertex_offset", H5::PredType::STD_I64LE, {}, kBodyChunkRows);
  d.body_vertices = schema_series(file, "/bodies/vertices", f8, {2}, 4 * kBodyChunkRows);
  d.body_parent = schema_series(file, "/bodies/parent", i4_file, {}, kBodyChunkRows);
  d.body_born = schema_series(file, "/bodies/born", f8, {}, kBodyChunkRows);
  const int64_t zero = 0;
  d.body_vertex_offset.write(&zero, 1, H5::PredType::NATIVE_INT64);
  append_bodies(d, outlines);

  // the joints of breakable floes (all of them from the start: dormant lattices' joints exist too)
  const hsize_t nj = joints.size();
  std::vector<int> joint_bodies, joint_floe, joint_index;
  std::vector<double> joint_midpoint;
  for (const JointRecord& j : joints) {
    joint_bodies.insert(joint_bodies.end(), {j.body_a, j.body_b});
    joint_floe.push_back(j.floe);
    joint_index.push_back(j.index);
    joint_midpoint.insert(joint_midpoint.end(), {j.midpoint_a.x(), j.midpoint_a.y(), j.midpoint_a.z()});
  }
  const H5::DataType& i4 = H5::PredType::STD_I32LE;
  schema_fixed(file, "/joints/bodies", i4, H5::PredType::NATIVE_INT, {nj, 2}, joint_bodies.data());
  schema_fixed(file, "/joints/floe", i4, H5::PredType::NATIVE_INT, {nj}, joint_floe.data());
  schema_fixed(file, "/joints/index", i4, H5::PredType::NATIVE_INT, {nj}, joint_index.data());
  schema_fixed(file, "/joints/midpoint", f8, H5::PredType::NATIVE_DOUBLE, {nj, 3}, joint_midpoint.data());

  // snapshots: rows of the bodies that changed, chunks of about kSnapshotChunkBytes
  const hsize_t snap_rows = kSnapshotChunkBytes / (4 * sizeof(double));
  d.snap_time = schema_series(file, "/snapshots/time", f8, {}, 256);
  d.snap_end_row = schema_series(file, "/snapshots/end_row", H5::PredType::STD_I64LE, {}, 256);
  d.snap_body = schema_series(file, "/snapshots/rows/body", i4, {}, snap_rows);
  d.snap_position = schema_series(file, "/snapshots/rows/position", f8, {3}, snap_rows);
  d.snap_orientation = schema_series(file, "/snapshots/rows/orientation", f8, {4}, snap_rows);
  d.snap_awake = schema_series(file, "/snapshots/rows/awake", H5::PredType::STD_U8LE, {}, snap_rows);
  if (run.mooring_lines > 0)
    d.snap_mooring = schema_series(file, "/snapshots/mooring_lines", f8,
                                   {hsize_t(run.mooring_lines), hsize_t(kMooringShapePoints), 3}, 64);

  // fracture events (/fracture/floe_* are written at the end, by write_floe_margins)
  d.events = schema_series(file, "/fracture/events", packed_file_type(event_fields()), {}, 256,
                           field_units(event_fields()));
  if (run.level_sheet) {
    d.sheet_breaks = schema_series(file, "/sheet/breaks", packed_file_type(sheet_break_fields()), {}, 256,
                                   field_units(sheet_break_fields()));
    d.sheet_outline_end_row = schema_series(file, "/sheet/outline_end_row", H5::PredType::STD_I64LE, {}, 256);
    d.sheet_outline_vertices = schema_series(file, "/sheet/outline_vertices", f8, {2}, 4096);
  }
  file.flush(H5F_SCOPE_GLOBAL);
  return d;
}

void append_bodies(OutputDatasets& d, const std::vector<BodyOutline>& outlines) {
  const std::size_t n = outlines.size();
  if (n == 0) return;
  std::vector<int> floe_id(n), parent(n);
  std::vector<double> thickness(n), born(n), vertices;
  std::vector<int64_t> offset(n);
  int64_t end = static_cast<int64_t>(d.body_vertices.rows);
  for (std::size_t i = 0; i < n; ++i) {
    floe_id[i] = outlines[i].floe_id;
    parent[i] = outlines[i].parent;
    thickness[i] = outlines[i].thickness;
    born[i] = outlines[i].born;
    for (const Eigen::Vector2d& v : outlines[i].outline) vertices.insert(vertices.end(), {v.x(), v.y()});
    offset[i] = end += static_cast<int64_t>(outlines[i].outline.size());
  }
  // the vertices and offsets before the bodies that name them: a file cut between the writes
  // holds vertices no body uses, never a body without its outline
  d.body_vertices.write(vertices.data(), vertices.size() / 2, H5::PredType::NATIVE_DOUBLE);
  d.body_vertex_offset.write(offset.data(), n, H5::PredType::NATIVE_INT64);
  d.body_thickness.write(thickness.data(), n, H5::PredType::NATIVE_DOUBLE);
  d.body_parent.write(parent.data(), n, H5::PredType::NATIVE_INT);
  d.body_born.write(born.data(), n, H5::PredType::NATIVE_DOUBLE);
  d.body_floe_id.write(floe_id.data(), n, H5::PredType::NATIVE_INT);
}

OutputDatasets open_output_layout(H5::H5File& file) {
  auto open = [&](const std::string& path) {
    return open_series(file.openGroup(split_path(path).first), split_path(path).second);
  };
  OutputDatasets d;
  for (const SeriesColumn& col : series_columns()) {
    // a moored run's columns are in its file only (the group, then the dataset: HDF5 asks in turn)
    const auto [group, name] = split_path(col.path);
    if (col.moored && !(file.nameExists(group) && file.openGroup(group).nameExists(name))) {
      d.series.emplace_back();
      continue;
    }
    d.series.push_back(open(col.path));
  }
  for (const auto& [member, path] : growing_datasets()) d.*member = open(path);
  if (file.nameExists("/snapshots") && file.openGroup("/snapshots").nameExists("mooring_lines"))
    d.snap_mooring = open("/snapshots/mooring_lines");
  if (file.nameExists("/sheet"))
    for (const auto& [member, path] : sheet_datasets()) d.*member = open(path);
  return d;
}

void write_floe_margin_datasets(H5::H5File& file, const std::vector<double>& max_ratio,
                                const std::vector<double>& min_distance) {
  const hsize_t n = max_ratio.size();
  schema_fixed(file, "/fracture/floe_max_ratio", H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, {n},
               max_ratio.data());
  schema_fixed(file, "/fracture/floe_min_distance", H5::PredType::IEEE_F64LE, H5::PredType::NATIVE_DOUBLE, {n},
               min_distance.data());
}

void OutputDatasets::close() {
  for (const auto& [member, path] : growing_datasets()) (this->*member).dataset.reset();
  snap_mooring.dataset.reset();
  for (const auto& [member, path] : sheet_datasets()) (this->*member).dataset.reset();
  for (Series& s : series) s.dataset.reset();
}

}  // namespace icedem
