// What a run writes, declared once: every dataset and attribute of the HDF5 file with its
// shape, element type, unit and meaning, and how each per-step series and break field is read
// from the rows of dem/output/rows.hpp. The recorder creates and fills the file from these
// tables, the summary's keys come from summary_fields() (dem/output/summary.hpp), and
// `icedem schema` prints all of it as docs/user/output.md.
//
// Shapes: n = load samples (one per step), nb = bodies, nv = outline vertices, k = snapshots,
// e = breaks, f = layout floes. Every dataset carries `units` ("1" for counts, flags and
// ratios) and `description` attributes. The layout is a stable interface: paths are added,
// none renamed or removed, and /meta format_version changes if that ever has to happen.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "dem/output/rows.hpp"

namespace icedem {

/// Version of the file layout, written to /meta format_version. 2: /bodies grows as floes split
/// (with /bodies/parent and /bodies/born), and a snapshot row's awake flag may be 2, gone. 3: the flag may be
/// 3, left behind (activation.leave_behind). 4: /sheet/breaks radial_crack became crack (0, 1 as before, 2 across
/// the patch).
inline constexpr int kOutputFormatVersion = 4;

/// Points per mooring line in /snapshots/mooring_lines: chords of about 0.27 m on the default 4.06 m
/// lines, which miss their sag by about a centimetre (L_chord^2 w / (8 H)), a picture's accuracy.
inline constexpr int kMooringShapePoints = 16;

/// Element type of a dataset, field or attribute in the file (little-endian).
enum class Element { f8, i4, i8, u1, compound, text };

/// "f8", "i4", ..., as the documentation writes them.
const char* element_name(Element element);

/// A per-step series: one row per load sample, of shape [n] (width 1) or [n x 3].
struct SeriesColumn {
  std::string path;         // HDF5 dataset path, e.g. "/load/force"
  Element element;          // f8 or i4
  int width;                // 1 or 3 values per row
  std::string unit;
  std::string description;
  std::function<double(const LoadSample&, int component)> value;  // the row's value
  bool moored = false;  // written only by runs of a moored structure (RunMeta::mooring_lines > 0)
  bool per_line = false;  // one value per mooring line (width: RunMeta::mooring_lines)
};

/// The per-step series in file order: load, structure, diagnostics (the last from
/// kDiagnosticColumns).
const std::vector<SeriesColumn>& series_columns();

/// A dataset that is not a per-step series: body outlines, snapshots, breaks, floe margins.
struct DatasetEntry {
  std::string path;
  std::string shape;  // e.g. "k x nb x 3"
  Element element;
  std::string unit;
  std::string description;
  bool moored = false;  // written only by runs of a moored structure (RunMeta::mooring_lines > 0)
  bool sheet = false;   // written only by runs of level ice cut by closed forms (RunMeta::level_sheet)
};

const std::vector<DatasetEntry>& other_datasets();

/// The entry of `path` among other_datasets(); std::logic_error if there is none (a writer
/// that uses a path the schema does not declare is a programming error).
const DatasetEntry& dataset_entry(std::string_view path);

/// One field of a /fracture/events row, with where FractureEvent keeps it.
struct EventField {
  const char* name;
  std::size_t offset;  // offsetof(FractureEvent, member)
  Element element;     // i4 or f8
  const char* unit;
  const char* description;
};

const std::vector<EventField>& event_fields();

/// The fields of a /sheet/breaks row, with where SheetBreakRecord keeps them (EventField's offset).
const std::vector<EventField>& sheet_break_fields();

/// An attribute on a group or dataset (the numbers of /stats come from summary_fields()).
struct AttributeEntry {
  const char* object;  // "/meta", "/layout", "/fracture/events"
  const char* name;
  Element element;
  const char* unit;
  const char* description;
};

const std::vector<AttributeEntry>& file_attributes();

/// The whole output, file and summary, as markdown (docs/user/output.md).
std::string output_markdown();

}  // namespace icedem
