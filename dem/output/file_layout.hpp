// A new output file laid out from the schema (dem/output/schema.hpp): /meta with the run's
// metadata and status "running", the per-step series, /bodies, and the empty snapshot and
// break datasets; at the end of a run, the floe margins. The recorder fills what this creates.
#pragma once

#include <H5Cpp.h>

#include <string>
#include <vector>

#include "dem/core/hdf5_io.hpp"
#include "dem/output/rows.hpp"

namespace icedem {

/// The growing datasets of an output file.
struct OutputDatasets {
  std::vector<Series> series;  // series_columns() order
  // snapshots: the first holds every body, each later one the bodies whose pose or awake flag
  // changed since the one before (snapshot i: rows end_row[i-1] to end_row[i] of snap_body etc.)
  Series snap_time, snap_end_row, snap_body, snap_position, snap_orientation, snap_awake;
  Series snap_mooring;  // a moored run's lines at each snapshot (k x lines x points x 3); none when towed
  Series events;
  // the bodies' outlines: rows appended as floes split (fracture.mode = "analytic")
  Series body_floe_id, body_thickness, body_vertex_offset, body_vertices, body_parent, body_born;
  // level ice cut by closed forms (RunMeta::level_sheet): its breaks and outlines; none otherwise
  Series sheet_breaks, sheet_outline_end_row, sheet_outline_vertices;

  /// Releases every dataset: HDF5 closes a file only once no object of it is open.
  void close();
};

/// Lays out `file` (new and empty) for a run with one body per outline, flushing it at the end
/// so that a process killed from here on leaves a file that says what run it belongs to.
OutputDatasets create_output_layout(H5::H5File& file, const RunMeta& run, const std::vector<BodyOutline>& outlines,
                                    const std::vector<JointRecord>& joints);

/// Appends `outlines` to /bodies (their /bodies/parent and /bodies/born included).
void append_bodies(OutputDatasets& d, const std::vector<BodyOutline>& outlines);

/// The growing datasets of `file`, laid out by create_output_layout and written up to some
/// row: a run resumed from a checkpoint appends after them.
OutputDatasets open_output_layout(H5::H5File& file);

/// The memory type of FractureEvent rows (the file's packed type is built from the same fields).
H5::CompType fracture_event_mem_type();

/// The memory type of SheetBreakRecord rows (/sheet/breaks).
H5::CompType sheet_break_mem_type();

/// Appends the sheet's outline `outline` (m, tank frame) to /sheet/outline_*: its vertices, then its end row (a file
/// cut between the writes holds vertices no row names, never a row without its vertices).
void append_sheet_outline(OutputDatasets& d, const std::vector<Eigen::Vector2d>& outline);

/// Writes /fracture/floe_max_ratio and /fracture/floe_min_distance (one value per layout floe).
void write_floe_margin_datasets(H5::H5File& file, const std::vector<double>& max_ratio,
                                const std::vector<double>& min_distance);

/// Now, as ISO 8601 UTC (e.g. 2026-11-23T07:00:00Z), for /meta started_utc and finished_utc.
std::string utc_now_iso8601();

}  // namespace icedem
