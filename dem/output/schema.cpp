// The output tables of dem/output/schema.hpp and their markdown.
#include "dem/output/schema.hpp"

#include <cstddef>
#include <stdexcept>

#include <fmt/format.h>

#include "dem/output/summary.hpp"

namespace icedem {

const char* element_name(Element element) {
  switch (element) {
    case Element::f8: return "f8";
    case Element::i4: return "i4";
    case Element::i8: return "i8";
    case Element::u1: return "u1";
    case Element::compound: return "compound";
    case Element::text: return "string";
  }
  return "?";
}

const std::vector<SeriesColumn>& series_columns() {
  using L = const LoadSample&;
  static const std::vector<SeriesColumn> columns = [] {
    std::vector<SeriesColumn> c{
        {"/load/time", Element::f8, 1, "s", "simulation time at the end of the step", [](L s, int) { return s.time; }},
        {"/load/force", Element::f8, 3, "N",
         "force by the ice on the structure, tank frame (x surge, y heave up, z sway), mean over the step",
         [](L s, int k) { return s.force[k]; }},
        {"/load/moment", Element::f8, 3, "N m",
         "moment by the ice on the structure about the cone axis at the waterline, tank frame",
         [](L s, int k) { return s.moment[k]; }},
        {"/load/surge", Element::f8, 1, "N",
         "surge load = -force_x: the load resisting towing, positive when the ice pushes back (as the paper plots it)",
         [](L s, int) { return s.surge(); }},
        {"/load/cone_contacts", Element::i4, 1, "1", "contact points between ice and structure",
         [](L s, int) { return double(s.cone_contacts); }},
        {"/structure/position", Element::f8, 3, "m", "structure reference point, tank frame",
         [](L s, int k) { return s.structure_position[k]; }},
        {"/structure/rotation", Element::f8, 3, "rad",
         "moored: the structure's rotation vector (axis times angle, body to tank; x roll, y yaw, z pitch)",
         [](L s, int k) { return s.structure_rotation[k]; }, true},
        {"/structure/velocity", Element::f8, 3, "m/s", "moored: the reference point's velocity, tank frame",
         [](L s, int k) { return s.structure_velocity[k]; }, true},
        {"/structure/angular_velocity", Element::f8, 3, "rad/s", "moored: the structure's angular velocity, tank frame",
         [](L s, int k) { return s.structure_angular_velocity[k]; }, true},
        {"/mooring/force", Element::f8, 3, "N", "moored: the mooring's force on the structure at the step's end, tank frame",
         [](L s, int k) { return s.mooring_force[k]; }, true},
        {"/mooring/moment", Element::f8, 3, "N m",
         "moored: the mooring's moment on the structure about its reference point, tank frame",
         [](L s, int k) { return s.mooring_moment[k]; }, true},
        {"/mooring/tension", Element::f8, 0, "N",
         "moored: each line's tension at its fairlead (n x lines; the linear mooring: its force's magnitude, n x 1)",
         [](L s, int k) { return s.mooring_tension[k]; }, true, true},
        {"/diagnostics/awake_bodies", Element::i4, 1, "1", "bodies being solved (not sleeping)",
         [](L s, int) { return double(s.awake_bodies); }},
        {"/diagnostics/contact_points", Element::i4, 1, "1", "contact points in the whole world (solver load)",
         [](L s, int) { return double(s.contact_points); }},
    };
    for (const DiagnosticColumn& d : kDiagnosticColumns) {
      const double StepDiagnostics::*field = d.field;
      c.push_back({std::string("/diagnostics/") + d.name, Element::f8, 1, d.unit, d.description,
                   [field](L s, int) { return s.diagnostics.*field; }});
    }
    return c;
  }();
  return columns;
}

const std::vector<DatasetEntry>& other_datasets() {
  static const std::vector<DatasetEntry> entries{
      {"/bodies/floe_id", "nb", Element::i4, "1",
       "floe id of each body; body order is the snapshot order. The bodies of the start come first; a floe that "
       "splits (fracture.mode = \"analytic\") adds its two pieces at the end, with its floe id"},
      {"/bodies/thickness", "nb", Element::f8, "m", "body thickness"},
      {"/bodies/vertex_offset", "nb + 1", Element::i8, "1",
       "outline of body i is vertices[vertex_offset[i]:vertex_offset[i+1]]"},
      {"/bodies/vertices", "nv x 2", Element::f8, "m", "outline vertices in the body frame (x, z)"},
      {"/bodies/parent", "nb", Element::i4, "1",
       "the body a piece was split from (a row of /bodies), -1 for the bodies of the start"},
      {"/bodies/born", "nb", Element::f8, "s", "when the body came into the run: 0, or the time of the split that made it"},
      {"/joints/bodies", "nj x 2", Element::i4, "1",
       "the two bodies (rows of /bodies) each joint of a breakable floe glues; empty for rigid floes"},
      {"/joints/floe", "nj", Element::i4, "1", "floe id of each joint"},
      {"/joints/index", "nj", Element::i4, "1",
       "joint index within its floe: a break in /fracture/events names its joint by (floe, joint)"},
      {"/joints/midpoint", "nj x 3", Element::f8, "m",
       "joint midpoint in the frame of its first body: the glued face is the edge of that body's outline "
       "nearest to it"},
      {"/snapshots/time", "k", Element::f8, "s", "snapshot time (every output.snapshot_interval)"},
      {"/snapshots/end_row", "k", Element::i8, "1",
       "end (exclusive) of each snapshot's rows in /snapshots/rows/*: the first snapshot holds every body, "
       "each later one the bodies whose pose or awake flag changed since the one before"},
      {"/snapshots/rows/body", "m", Element::i4, "1", "the body of a row (index into /bodies)"},
      {"/snapshots/rows/position", "m x 3", Element::f8, "m", "body origin, tank frame"},
      {"/snapshots/rows/orientation", "m x 4", Element::f8, "1",
       "body-to-tank rotation as a unit quaternion (w, x, y, z)"},
      {"/snapshots/rows/awake", "m", Element::u1, "1", "1 if the body was awake (being solved), 0 at rest, 2 gone: split into the pieces whose /bodies/parent "
       "names it (a body has no row before it is born), 3 left behind the structure (activation.leave_behind), out of "
       "the run where it lay"},
      {"/snapshots/mooring_lines", fmt::format("k x lines x {} x 3", kMooringShapePoints), Element::f8, "m",
       fmt::format("moored: each mooring line's shape at the snapshot, {} points from its anchor to its fairlead "
                   "(the catenary solved for the structure's pose; the linear mooring: one straight line from the "
                   "attachment point's rest on the carriage to the attachment point), tank frame",
                   kMooringShapePoints),
       true},
      {"/fracture/events", "e", Element::compound, "",
       "joint breaks and rigid floes' splits, one row per break, with the floe's state at the break (fields below; "
       "empty when nothing breaks)"},
      {"/sheet/breaks", "s", Element::compound, "",
       "level ice cut by closed forms (fracture.mode = \"analytic\"): the sheet's breaks, one row per break (fields "
       "below; each is also a row of /fracture/events, floe and joint -1)",
       false, true},
      {"/sheet/outline_end_row", "s + 1", Element::i8, "1",
       "level ice cut by closed forms: the sheet's outline at the start (row 0) and after each break (row i + 1 after "
       "/sheet/breaks row i) is /sheet/outline_vertices[end_row[i - 1]:end_row[i]] (0 for row 0's start)",
       false, true},
      {"/sheet/outline_vertices", "nv_s x 2", Element::f8, "m",
       "level ice cut by closed forms: the sheet's outlines' vertices (x, z), tank frame, in turn (clockwise in a "
       "plot of x right and z up)",
       false, true},
      {"/fracture/floe_max_ratio", "f", Element::f8, "1",
       "per layout floe: the largest load / capacity ratio of any of its joints under any criterion over the run "
       "(0 for rigid floes and lattices never awake); runs with breakable floes only"},
      {"/fracture/floe_min_distance", "f", Element::f8, "m",
       "per layout floe: the closest a joint midpoint came to the structure's section at its height, horizontally "
       "(inf if never checked); runs with breakable floes only"},
  };
  return entries;
}

const DatasetEntry& dataset_entry(std::string_view path) {
  for (const DatasetEntry& e : other_datasets())
    if (e.path == path) return e;
  throw std::logic_error(fmt::format("output schema: no dataset '{}' is declared (dem/output/schema.cpp)", path));
}

const std::vector<EventField>& event_fields() {
  static const std::vector<EventField> fields{
      {"time", offsetof(FractureEvent, time), Element::f8, "s", "time of the break"},
      {"floe", offsetof(FractureEvent, floe), Element::i4, "1", "floe id"},
      {"joint", offsetof(FractureEvent, joint), Element::i4, "1", "joint index within the floe; -1: the split of a rigid floe (fracture.mode = \"analytic\"), "
       "x and z then the crack's point nearest the floe's centroid"},
      {"mode", offsetof(FractureEvent, mode), Element::i4, "1", "failure mode code (attribute mode_names)"},
      {"ratio", offsetof(FractureEvent, ratio), Element::f8, "1", "load / capacity of the criterion that fired (>= 1)"},
      {"x", offsetof(FractureEvent, x), Element::f8, "m", "joint midpoint at the break, tank frame"},
      {"z", offsetof(FractureEvent, z), Element::f8, "m", "joint midpoint at the break, tank frame"},
      {"mechanism", offsetof(FractureEvent, mechanism), Element::i4, "1",
       "what the floe was doing, code (attribute mechanism_names; docs/model/breakage.md)"},
      {"touching_structure", offsetof(FractureEvent, touching_structure), Element::i4, "1",
       "1 if an element of the floe touched the structure"},
      {"depth", offsetof(FractureEvent, depth), Element::f8, "m", "joint midpoint below the waterline (+ down)"},
      {"distance", offsetof(FractureEvent, distance), Element::f8, "m",
       "horizontal distance of the joint midpoint from the structure's section at its height"},
      {"structure_force", offsetof(FractureEvent, structure_force), Element::f8, "N",
       "the structure's contact force on the floe"},
      {"press_down", offsetof(FractureEvent, press_down), Element::f8, "N",
       "other floes' net contact force on the floe, downward (0 if upward)"},
      {"press_toward", offsetof(FractureEvent, press_toward), Element::f8, "N",
       "other floes' net contact force on the floe, towards the structure axis (0 if away)"},
      {"ratio_compression", offsetof(FractureEvent, ratio_compression), Element::f8, "1",
       "load / capacity in compression (paper eq. 1)"},
      {"ratio_shear", offsetof(FractureEvent, ratio_shear), Element::f8, "1", "load / capacity in shear (eq. 2)"},
      {"ratio_bending", offsetof(FractureEvent, ratio_bending), Element::f8, "1", "load / capacity in bending (eq. 3)"},
      {"ratio_tension", offsetof(FractureEvent, ratio_tension), Element::f8, "1",
       "load / capacity in tension (fracture.tension_strength; 0 when off)"},
      {"ratio_in_plane_bending", offsetof(FractureEvent, ratio_in_plane_bending), Element::f8, "1",
       "load / capacity in in-plane bending (0 when off)"},
  };
  return fields;
}

const std::vector<EventField>& sheet_break_fields() {
  using R = SheetBreakRecord;
  static const std::vector<EventField> fields{
      {"time", offsetof(R, time), Element::f8, "s", "time of the break"},
      {"by_floe", offsetof(R, by_floe), Element::i4, "1",
       "1: a floe's push on the sheet's edge broke it (the rubble the structure pushes), 0: the structure's crushed "
       "zone"},
      {"crack", offsetof(R, crack), Element::i4, "1",
       "how the edge broke: 0 one wedge across its axis, 1 a radial crack and its two wedges together, 2 one crack "
       "across the load's patch"},
      {"pieces", offsetof(R, pieces), Element::i4, "1", "floes made (the last bodies of /bodies born at its time)"},
      {"splits_before", offsetof(R, splits_before), Element::i4, "1", "splits of rigid floes before it"},
      {"x", offsetof(R, x), Element::f8, "m", "the load's centre, tank frame"},
      {"z", offsetof(R, z), Element::f8, "m", "the load's centre, tank frame"},
      {"axis_x", offsetof(R, axis_x), Element::f8, "1", "the load's direction into the sheet (the wedges' axis)"},
      {"axis_z", offsetof(R, axis_z), Element::f8, "1", "the load's direction into the sheet (the wedges' axis)"},
      {"half_width", offsetof(R, half_width), Element::f8, "m", "the load's patch a: half its width across the axis"},
      {"load", offsetof(R, load), Element::f8, "N", "the load normal to the sheet"},
      {"breaking_load", offsetof(R, breaking_load), Element::f8, "N", "the closed form's breaking load (<= load)"},
      {"opening_angle", offsetof(R, opening_angle), Element::f8, "rad",
       "the angle the sheet fills about the centre (pi at a straight edge)"},
      {"crack_distance", offsetof(R, crack_distance), Element::f8, "m",
       "x*: the cracks' distance from the centre (x_c across a patch)"},
      {"hull_x", offsetof(R, hull_x), Element::f8, "m", "the structure's axis at the break (by_floe 0)"},
      {"hull_z", offsetof(R, hull_z), Element::f8, "m", "the structure's axis at the break (by_floe 0)"},
      {"hull_radius", offsetof(R, hull_radius), Element::f8, "m",
       "the structure's larger radius in the ice (by_floe 0): the ice short of it is crushed"},
      {"broken_area", offsetof(R, broken_area), Element::f8, "m2", "ice that left the sheet"},
      {"crushed_area", offsetof(R, crushed_area), Element::f8, "m2",
       "of it, crushed: in the structure's section, or in pieces smaller than the thickness squared or narrower "
       "than the thickness"},
  };
  return fields;
}

const std::vector<AttributeEntry>& file_attributes() {
  static const std::vector<AttributeEntry> entries{
      {"/meta", "format_version", Element::i4, "1", "version of this layout"},
      {"/meta", "scenario", Element::text, "", "the resolved scenario: every key with its value, as TOML"},
      {"/meta", "scenario_path", Element::text, "", "scenario file as given"},
      {"/meta", "command_line", Element::text, "", "the full command line"},
      {"/meta", "version", Element::text, "", "icedem version"},
      {"/meta", "build", Element::text, "",
       "the build that made the run: its source's git commit (\"(modified)\" when tracked sources differed from "
       "it), the build type and the compiler"},
      {"/meta", "resumed_build", Element::text, "",
       "the build that last resumed the run, as build (absent if never resumed); another build than the one "
       "that started it continues the run bit for bit only if no change between them moved results"},
      {"/meta", "bullet_version", Element::text, "", "Bullet version"},
      {"/meta", "precision", Element::text, "", "Bullet's scalar: double or float"},
      {"/meta", "seed", Element::i8, "1", "random seed of the layout (unsigned)"},
      {"/meta", "started_utc", Element::text, "", "start, ISO 8601"},
      {"/meta", "finished_utc", Element::text, "", "end, ISO 8601 (absent if the run did not finish)"},
      {"/meta", "resumed_utc", Element::text, "",
       "when `icedem resume` last continued the run from its checkpoint, ISO 8601 (absent if never)"},
      {"/meta", "wall_time_s", Element::f8, "s", "wall time so far (updated at every flush)"},
      {"/meta", "status", Element::text, "",
       "running while running (a file left running was killed), then complete, interrupted, failed or "
       "incomplete (the run ended without closing the file normally)"},
      {"/meta", "message", Element::text, "", "the error or note of the run (also which rows did not fit a full disk)"},
      {"/layout", "floes", Element::f8, "1", "floes in the layout"},
      {"/layout", "achieved_concentration", Element::f8, "1", "ice area over channel area"},
      {"/layout", "target_concentration", Element::f8, "1", "ice.concentration"},
      {"/layout", "channel_area_m2", Element::f8, "m2", "channel area the concentration refers to"},
      {"/layout", "source", Element::text, "", "\"generated\" or the layout file"},
      {"/stats", "note", Element::text, "", "why there are no load statistics (only then)"},
      {"/fracture/events", "mode_names", Element::text, "", "failure mode code -> name: \"0 compression, 1 shear, ...\""},
      {"/fracture/events", "mechanism_names", Element::text, "", "mechanism code -> name, the same way"},
  };
  return entries;
}

namespace {

std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace

std::string output_markdown() {
  std::string md =
      "# Outputs\n\n"
      "Generated by `icedem schema` from dem/output/schema.cpp and dem/output/summary.cpp; do not edit by hand.\n\n"
      "A run writes an HDF5 file (`-o OUT.h5`) and, with `--summary-json FILE`, a JSON summary; the\n"
      "summary's table is also printed. Paths and keys are added over time, none renamed or removed,\n"
      "with one exception: until 2026-11 /snapshots/position, orientation and awake held every body\n"
      "at every snapshot (k x nb x ...); they are now rows of the bodies that changed (below).\n\n"
      "## HDF5 file\n\n"
      "Every dataset has `units` (\"1\" for counts, flags and ratios) and `description` attributes.\n"
      "Shapes: n = steps, nb = bodies (rigid floes and ice elements), nv = outline vertices,\n"
      "nj = joints of breakable floes, k = snapshots, m = snapshot rows, e = breaks, f = layout floes.\n"
      "A snapshot stores only the bodies whose pose or awake flag changed since the snapshot before\n"
      "(the first stores every body), so that a field of resting floes costs nothing per snapshot:\n"
      "snapshot i is rows end_row[i-1] (0 for the first) to end_row[i] of /snapshots/rows/*, and the\n"
      "full field at snapshot i is every row up to end_row[i], each body at its latest row.\n"
      "`tools/icedem_tools/runs/results.py` (`load_run(path, snapshots=True)`, `snapshot_field`) gives it\n"
      "as k x nb arrays. The file is\n"
      "written in the HDF5 1.8 format and flushed every few seconds of wall time, so it stays\n"
      "readable after a crash or a kill. `scripts/xdmf_snapshots.py OUT.h5` makes a view of the\n"
      "snapshots for ParaView, with the joints' faces, broken or not, beside the floes\n"
      "(docs/user/sweeps.md); `scripts/movie OUT.h5` makes a movie of them without ParaView (an\n"
      "animated GIF, or an MP4 with `-o NAME.mp4` where ffmpeg is installed): the floes from above and\n"
      "from the side around the structure, the broken joints in red, the surge load beside them.\n\n"
      "### Per-step series\n\n"
      "| path | shape | type | unit | meaning |\n|---|---|---|---|---|\n";
  for (const SeriesColumn& c : series_columns())
    md += fmt::format("| `{}` | {} | {} | {} | {} |\n", c.path,
                      c.per_line ? "n x lines" : c.width == 1 ? "n" : fmt::format("n x {}", c.width),
                      element_name(c.element), c.unit, cell(c.description));
  md += "\n### Bodies, joints, snapshots and breaks\n\n| path | shape | type | unit | meaning |\n|---|---|---|---|---|\n";
  for (const DatasetEntry& e : other_datasets())
    md += fmt::format("| `{}` | {} | {} | {} | {} |\n", e.path, e.shape, element_name(e.element), e.unit,
                      cell(e.description));
  md += "\n### Fields of `/fracture/events`\n\n| field | type | unit | meaning |\n|---|---|---|---|\n";
  for (const EventField& f : event_fields())
    md += fmt::format("| `{}` | {} | {} | {} |\n", f.name, element_name(f.element), f.unit, cell(f.description));
  md += "\n### Fields of `/sheet/breaks`\n\n| field | type | unit | meaning |\n|---|---|---|---|\n";
  for (const EventField& f : sheet_break_fields())
    md += fmt::format("| `{}` | {} | {} | {} |\n", f.name, element_name(f.element), f.unit, cell(f.description));
  md += "\n### Attributes\n\n| object | attribute | type | unit | meaning |\n|---|---|---|---|---|\n";
  for (const AttributeEntry& a : file_attributes())
    md += fmt::format("| `{}` | `{}` | {} | {} | {} |\n", a.object, a.name, element_name(a.element), a.unit,
                      cell(a.description));
  for (const SummaryField& f : summary_fields())
    if (f.stats)
      md += fmt::format("| `/stats` | `{}` | f8 | {} | as the summary key (below), when not null |\n", f.key, f.unit);
  md += "\n## Checkpoint (`OUT.h5.checkpoint`)\n\n"
        "Every `output.checkpoint_interval` of simulated time (30 s by default; not for validation cases, runs\n"
        "exchanging drag with OpenFOAM or exporting contact problems) a run writes `OUT.h5.checkpoint` beside\n"
        "its output: a copy of the output as it stands, with a group `/checkpoint` holding everything the run\n"
        "needs to go on (every body's pose, velocities and sleep, the lattices and broken joints, the level\n"
        "sheet's breaks, every contact point with its warm-start impulses, the run's clock, break counts and load\n"
        "history). It is written to\n"
        "`OUT.h5.checkpoint.tmp` and renamed into place, so a kill during the write leaves the previous one\n"
        "whole. `icedem info OUT.h5` says whether a run is complete, being written, or was killed and from\n"
        "when it can be resumed; `icedem resume OUT.h5` puts the checkpoint's copy in place of the output\n"
        "(a file torn by the kill is no loss) and continues the run to its end, appending to it. The resumed\n"
        "run ends bit for bit as the uninterrupted one. A complete run's checkpoint is deleted, and a complete\n"
        "file is never resumed. `/checkpoint` holds this build's records as bytes: only the icedem version\n"
        "that wrote it reads it. Its attribute `digest` holds a SHA-256 of everything else in the file, one\n"
        "line per part (`/meta`, `/load`, ..., `/checkpoint/world`): `resume` and `info` refuse a checkpoint\n"
        "whose contents no longer match it, naming the parts that differ.\n";
  md += "\n## Summary (`--summary-json FILE`)\n\n"
        "Statistics are `null` when the analysis window holds no data (`statistics_note` says why).\n\n"
        "| key | unit | meaning |\n|---|---|---|\n";
  for (const SummaryField& f : summary_fields())
    md += fmt::format("| `{}` | {} | {} |\n", f.key, f.unit, cell(f.description));
  return md;
}

}  // namespace icedem
