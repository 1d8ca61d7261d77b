#include "dem/output/summary.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "dem/contact/registry.hpp"
#include "dem/core/constants.hpp"
#include "dem/fracture/joint_loads.hpp"

namespace icedem {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// the tighter merits of islands with joints and of islands touching the structure, if any
std::string tighter_islands(const SolverSummary& v) {
  std::vector<std::string> parts;
  if (v.joint_tolerance > 0 && v.joint_tolerance < v.tolerance) parts.push_back(fmt::format("{:g} with joints", v.joint_tolerance));
  if (v.structure_tolerance > 0 && v.structure_tolerance < v.tolerance)
    parts.push_back(fmt::format("{:g} on the structure", v.structure_tolerance));
  if (parts.empty()) return "";
  return " (" + fmt::format("{}", fmt::join(parts, ", ")) + ")";
}

// sweeps per step, and a warning when the cap, not the tolerance, ended the sweeps
// of many steps: the loads of those steps are not converged (docs/model/convergence.md)
std::string solver_line(const SolverSummary& v) {
  const bool sweeps = v.method == kBulletSweeps;
  std::string out =
      sweeps ? fmt::format("  contact solver: {:.1f} sweeps per step on average, at most {:d} (cap {:d}), "
                           "tolerance {:g}, largest residual {:.2g}\n",
                           v.iterations_mean, v.iterations_max, v.cap, v.tolerance, v.residual_max)
             : fmt::format("  contact solver ({}): {:.1f} iterations per step on average, at most {:d} (cap {:d}), "
                           "merit tolerance {:g}{}, largest merit {:.2g}\n",
                           v.method, v.iterations_mean, v.iterations_max, v.cap, v.tolerance,
                           tighter_islands(v),
                           v.residual_max);
  const StepDiagnostics& n = v.totals;
  if (n.breaking_solves > 0)
    out += fmt::format("  {} islands solved again to a merit of {:g} for a joint near its capacity (their "
                       "iterations count above, beyond the cap), {} of them decided at solver.breaking_check_tolerance "
                       "and {} stopped at solver.breaking_iterations above it (/diagnostics/breaking_solves, "
                       "breaking_decided, breaking_capped)\n",
                       long(n.breaking_solves), v.breaking_tolerance, long(n.breaking_decided), long(n.breaking_capped));
  if (n.handovers > 0)
    out += fmt::format("  {} islands left at the cap above their merit went on with {} from that answer, or with "
                       "newton where they held crushing contacts {} does not take (their iterations count above; "
                       "/diagnostics/handovers)\n",
                       long(n.handovers), v.handover_method, v.handover_method);
  if (n.runaways > 0)
    out += fmt::format("  {} answers of a later stage (hand-over, breaking solves) not taken: they lowered the merit by "
                       "growing the island's impulses over tenfold, the answer before kept (/diagnostics/runaways)\n",
                       long(n.runaways));
  if (v.tolerance > 0 && v.capped_window_fraction > SolverSummary::kCappedWarning)
    out += fmt::format("  warning: {:.1f} % of the analysis window's steps reached {} = {:d} before "
                       "{} = {:g}: their loads are not converged; raise the cap "
                       "(/diagnostics/solver_capped has the steps)\n",
                       100 * v.capped_window_fraction, sweeps ? "solver.iterations" : "solver.method_iterations", v.cap,
                       sweeps ? "solver.tolerance" : "solver.merit_tolerance", v.tolerance);
  if (v.tolerance == 0)
    out += "  note: solver.tolerance = 0 runs every island to the cap and nothing checks that the loads "
           "converged (docs/model/convergence.md)\n";
  return out;
}

}  // namespace

std::string summary_table(const RunSummary& s) {
  const double rtf = s.wall_time_s > 0 ? s.sim_time_s / s.wall_time_s : 0.0;
  std::string out;
  out += fmt::format("icedem run: {}  ->  {}  [{}]\n", s.scenario, s.output, s.status);
  if (!s.message.empty()) out += fmt::format("  {}\n", s.message);
  for (const std::string& w : s.warnings) out += fmt::format("  warning: {}\n", w);
  out += fmt::format("  floes {:d} (concentration {:.2f} %), steps {:d}, simulated {:.1f} s in {:.1f} s wall "
                     "({:.1f}x real time, {:.0f} steps/s), awake bodies {:.1f} on average\n",
                     s.floes, 100 * s.achieved_concentration, s.steps, s.sim_time_s, s.wall_time_s, rtf,
                     s.wall_time_s > 0 ? s.steps / s.wall_time_s : 0.0, s.mean_awake);
  const StageTimes& t = s.stage_times;
  out += fmt::format("  wall time by stage: contact solve {:.1f} s, collision {:.1f} s, islands {:.1f} s, "
                     "integration {:.1f} s, water {:.1f} s, activation {:.1f} s, load cell {:.1f} s, "
                     "{}other {:.1f} s\n", t.solve, t.collision, t.islands, t.integrate, t.water, t.activation,
                     t.load_cell, t.coupling > 0 ? fmt::format("OpenFOAM exchanges {:.1f} s, ", t.coupling) : "",
                     s.wall_time_s - t.bullet() - t.water - t.activation - t.load_cell - t.coupling);
  if (!s.validation.is_null()) {
    const nlohmann::json& v = s.validation;
    // a case without a result (the beam did not break) has null value and error, and a note
    if (v["value"].is_number() && v["rel_error"].is_number())
      out += fmt::format("  validation {}: {} = {:.4f} (reference {:.4f}), error {:+.1f} % (tolerance {:.0f} %): {}\n",
                         v["case"].get<std::string>(), v["metric"].get<std::string>(), v["value"].get<double>(),
                         v["reference"].get<double>(), 100 * v["rel_error"].get<double>(),
                         100 * v["tolerance"].get<double>(), v["passed"].get<bool>() ? "passed" : "FAILED");
    else
      out += fmt::format("  validation {}: no result, FAILED: {}\n", v["case"].get<std::string>(),
                         v.value("note", std::string("no value")));
    if (v.contains("elastic_modulus_MPa"))
      out += fmt::format("  inferred elastic modulus {:.1f} MPa (target {:.1f} MPa)\n",
                         v["elastic_modulus_MPa"].get<double>(), v["elastic_modulus_target_MPa"].get<double>());
  }
  // an element turning this fast is rocking unstably, not moving with the ice (docs/model/physics.md,
  // "Breakable ice": at ERP 0.8 elements rock with a growing period-2 oscillation)
  if (s.health.max.max_angular_speed > kRockingAngularSpeed)
    out += fmt::format("  warning: a floe or element turned at {:.1f} rad/s (t = {:.2f} s): unstable joints? "
                       "/diagnostics/max_angular_speed has the history; docs/model/physics.md, \"Breakable ice\"\n",
                       s.health.max.max_angular_speed, s.health.max_time[0]);
  out += solver_line(s.solver);
  if (s.squeeze_start_s >= 0)
    out += fmt::format("  the structure squeezes the ice against the channel's end wall (x = {} m) from t = {:.1f} s: "
                       "max {:.2f} N from then on, the rig's load, not the ice's; {}\n",
                       s.squeeze_wall_x, s.squeeze_start_s, s.squeeze_max_fx_N,
                       s.squeeze_excluded ? "left out of the statistics (stats.include_squeeze = true keeps it)"
                                          : "kept in the statistics (stats.include_squeeze)");
  if (!s.has_statistics) {
    out += fmt::format("  no load statistics: {}\n", s.statistics_note);
    return out;
  }
  const LoadStatistics& st = s.surge;
  out += fmt::format("  first ice contact at {:.1f} s; analysis window {:.1f} - {:.1f} s ({:.1f} s{})\n",
                     s.first_contact_s, st.window_start, st.window_end, st.window_s,
                     st.lowpass_hz > 0 ? fmt::format(", low-pass {} Hz", st.lowpass_hz) : "");
  out += fmt::format("  surge load (resisting towing): mean {:.2f} N   max {:.2f} N   std {:.2f} N\n",
                     st.mean, st.max, st.std);
  if (s.mooring.present)
    out += fmt::format("  mooring force (holding it): mean {:.2f} N   max {:.2f} N   std {:.2f} N; surge offset mean {:.1f} mm, "
                       "std {:.1f} mm, farthest back {:.1f} mm; largest line tension {:.2f} N\n",
                       s.mooring.force.mean, s.mooring.force.max, s.mooring.force.std, 1e3 * s.mooring.offset_mean_m,
                       1e3 * s.mooring.offset_std_m, 1e3 * s.mooring.offset_min_m, s.mooring.tension_max_N);
  // the paper's "load network to the sides and end of the channel" (its Fig. 14)
  if (s.locked_window_fraction > 0)
    out += fmt::format("  fixed boundaries (mother ice, walls) carry {:.0f} % of the surge load over the window; "
                       "{:.0f} % of its steps are locked (half or more; /diagnostics/boundary_load, locked)\n",
                       100 * s.boundary_share, 100 * s.locked_window_fraction);
  out += fmt::format("  load peaks {:d}, mean spacing {} s; breaks {:d} (compression {}, shear {}, bending {})\n",
                     st.peaks, std::isfinite(st.peak_interval_s) ? fmt::format("{:.2f}", st.peak_interval_s) : "n/a",
                     s.breaks, s.breaks_by_mode[0], s.breaks_by_mode[1], s.breaks_by_mode[2]);
  if (s.breaks > 0)
    for (int m = 0; m < kBreakMechanisms; ++m)
      out += fmt::format("{}{} {}{}", m ? ", " : "  breaks by mechanism: ",
                         break_mechanism_name(static_cast<BreakMechanism>(m)), s.breaks_by_mechanism[m],
                         m + 1 == kBreakMechanisms ? "\n" : "");
  if (s.held_edge_overloads > 0)
    out += fmt::format("  level ice: {:d} times a joint at the held edge reached its capacity (not broken: the held sheet's "
                       "clamp; many say fracture.lattice_radius is too small; /diagnostics/held_edge_overloads)\n",
                       s.held_edge_overloads);
  if (s.sheet_holds > 0)
    out += fmt::format("  level ice: {:d} times a zone of the sheet at its breaking load was not cut (the cut would have "
                       "parted the held sheet or left a hole in it, or could not be made): it crushed on "
                       "(/diagnostics/sheet_holds)\n",
                       s.sheet_holds);
  if (!s.near_structure_max_ratio.empty()) {
    const auto& r = s.near_structure_max_ratio;
    const long over_half = std::count_if(r.begin(), r.end(), [](double x) { return x >= 0.5; });
    out += fmt::format("  floes near the structure: {:d}; their largest load ratio (a joint's, or a rigid floe's load "
                       "over its breaking load): median {:.2f}, "
                       "max {:.2f}; {:d} reached half their capacity\n",
                       r.size(), median(r), *std::max_element(r.begin(), r.end()), over_half);
  }
  return out;
}

namespace {

using json = nlohmann::json;

// a number, or null when it is not finite (JSON has no NaN or infinity)
json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// a statistic of the analysis window: null when the window held no data
json window_stat(const RunSummary& s, double v) { return s.has_statistics ? num(v) : json(nullptr); }

}  // namespace

const std::vector<SummaryField>& summary_fields() {
  using S = const RunSummary&;
  static const std::vector<SummaryField> fields{
      {"scenario", "", false, false, "scenario file as given", [](S s) { return json(s.scenario); }},
      {"output", "", false, false, "HDF5 output file", [](S s) { return json(s.output); }},
      {"status", "", false, false, "complete, interrupted or failed", [](S s) { return json(s.status); }},
      {"message", "", false, false, "the error or note of the run, empty if none", [](S s) { return json(s.message); }},
      {"warnings", "", false, false, "scene warnings (step size), printed first",
       [](S s) { return json(s.warnings); }},
      {"statistics_note", "", false, false, "why the load statistics are null, empty if they are not",
       [](S s) { return json(s.statistics_note); }},
      {"mean_fx_N", "N", true, false, "mean surge load (the load resisting towing, positive) over the analysis window",
       [](S s) { return window_stat(s, s.surge.mean); }},
      {"max_fx_N", "N", true, false, "largest surge load in the window", [](S s) { return window_stat(s, s.surge.max); }},
      {"min_fx_N", "N", true, false, "smallest surge load in the window", [](S s) { return window_stat(s, s.surge.min); }},
      {"std_fx_N", "N", true, false, "standard deviation of the surge load in the window",
       [](S s) { return window_stat(s, s.surge.std); }},
      {"mean_fy_N", "N", true, false, "mean heave load in the window (ice on structure, + up)",
       [](S s) { return window_stat(s, s.mean_fy_N); }},
      {"mean_fz_N", "N", true, false, "mean sway load in the window", [](S s) { return window_stat(s, s.mean_fz_N); }},
      {"window_s", "s", true, false, "length of the analysis window (0 without one)",
       [](S s) { return s.has_statistics ? num(s.surge.window_s) : json(0.0); }},
      {"window_start_s", "s", true, false, "start of the analysis window (stats.window_start_travel beyond first contact)",
       [](S s) { return window_stat(s, s.surge.window_start); }},
      {"window_end_s", "s", true, false, "end of the analysis window", [](S s) { return window_stat(s, s.surge.window_end); }},
      {"lowpass_hz", "Hz", true, false, "low-pass applied before the statistics (0: none)",
       [](S s) { return window_stat(s, s.surge.lowpass_hz); }},
      {"peaks", "1", true, false, "load peaks in the window: local maxima with a prominence of one standard deviation, "
       "at least half a floe passage apart", [](S s) { return s.has_statistics ? json(s.surge.peaks) : json(0); }},
      {"peak_interval_s", "s", true, false, "mean spacing of those peaks",
       [](S s) { return window_stat(s, s.surge.peak_interval_s); }},
      {"first_contact_s", "s", true, false, "first ice contact with the structure (null: none)",
       [](S s) { return s.first_contact_s >= 0 ? num(s.first_contact_s) : json(nullptr); }},
      {"breaks", "1", true, false, "joint failures (0 with rigid floes)", [](S s) { return json(s.breaks); }},
      {"breaks_by_mode", "1", false, false, "breaks per failure mode, by name (the names of /fracture/events mode_names)",
       [](S s) {
         json j = json::object();
         for (int m = 0; m < kFailureModes; ++m) j[failure_mode_name(static_cast<FailureMode>(m))] = s.breaks_by_mode[m];
         return j;
       }},
      {"breaks_by_mechanism", "1", false, false,
       "breaks per mechanism, by name (the names of /fracture/events mechanism_names; docs/model/breakage.md)",
       [](S s) {
         json j = json::object();
         for (int m = 0; m < kBreakMechanisms; ++m)
           j[break_mechanism_name(static_cast<BreakMechanism>(m))] = s.breaks_by_mechanism[m];
         return j;
       }},
      {"near_structure_max_ratio", "1", false, false,
       "for every breakable floe that came within 1 m of the structure: the largest load / capacity ratio of its "
       "joints over the run (fracture.mode = \"analytic\": every floe the structure touched, its load over its "
       "breaking load)", [](S s) { return json(s.near_structure_max_ratio); }},
      {"held_edge_overloads", "1", true, false,
       "level ice: over the run, the sheet's joints at its held edge that reached their capacity, counted each step "
       "(/diagnostics/held_edge_overloads); they do not break. Many: fracture.lattice_radius too small",
       [](S s) { return json(s.held_edge_overloads); }},
      {"sheet_holds", "1", true, false,
       "level ice cut by closed forms: over the run, the sheet's zones at their breaking load that were not cut, "
       "counted each step (/diagnostics/sheet_holds); they crush on",
       [](S s) { return json(s.sheet_holds); }},
      {"steps", "1", true, false, "solver steps", [](S s) { return json(s.steps); }},
      {"sim_time_s", "s", true, false, "simulated time", [](S s) { return json(s.sim_time_s); }},
      {"bullet_step_s", "s", false, false,
       "the dynamics' step, time.dt / time.substeps: breakage and the loads of the 0.15 m lattices move with it "
       "(docs/model/convergence.md), so runs at two steps are not one sample", [](S s) { return json(s.bullet_step_s); }},
      {"build", "", false, false,
       "the build of the process that wrote the summary (a resumed run's: the resuming one): commit (the source's "
       "git commit, or unknown), modified (tracked sources differed from it), type, compiler. Runs of builds whose "
       "dynamics differ are not one sample (CHANGELOG.md says which changes moved results)",
       [](S s) {
         return json{{"commit", s.build.commit}, {"modified", s.build.modified}, {"type", s.build.type},
                     {"compiler", s.build.compiler}};
       }},
      {"wall_time_s", "s", true, false,
       "wall time of the run; a resumed run's adds what its earlier processes spent up to the checkpoint it was "
       "resumed from", [](S s) { return json(s.wall_time_s); }},
      {"cpu_time_s", "s", true, false,
       "user + system CPU time of the run's processes (the fair cost on a shared machine); a resumed run's adds "
       "its earlier processes' up to the checkpoint it was resumed from", [](S s) { return json(s.cpu_time_s); }},
      {"realtime_factor", "1", false, false, "simulated time over wall time",
       [](S s) { return s.wall_time_s > 0 ? num(s.sim_time_s / s.wall_time_s) : json(nullptr); }},
      {"steps_per_second", "1/s", false, false, "steps per second of wall time",
       [](S s) { return s.wall_time_s > 0 ? num(s.steps / s.wall_time_s) : json(nullptr); }},
      {"floes", "1", false, false, "floes in the layout", [](S s) { return json(s.floes); }},
      {"achieved_concentration", "1", false, false, "ice area over channel area of the layout",
       [](S s) { return json(s.achieved_concentration); }},
      {"mean_awake", "1", true, false, "bodies solved per step (not asleep), averaged over the run",
       [](S s) { return json(s.mean_awake); }},
      {"max_angular_speed_rad_s", "rad/s", false, false,
       "fastest turn of a floe or element in the run; above 15 rad/s the table warns of unstable joints",
       [](S s) { return json(s.health.max.max_angular_speed); }},
      {"health", "", false, false,
       "for each /diagnostics series its max, unit and time_s; plus ice_mass_initial_kg and "
       "ice_mass_max_relative_change (ice lost or created)",
       [](S s) {
         json j = json::object();
         for (std::size_t c = 0; c < kDiagnosticCount; ++c) {
           const DiagnosticColumn& col = kDiagnosticColumns[c];
           j[col.name] = {{"max", num(s.health.max.*col.field)}, {"unit", col.unit}, {"time_s", s.health.max_time[c]}};
         }
         j["ice_mass_initial_kg"] = num(s.health.initial_ice_mass);
         j["ice_mass_max_relative_change"] = num(s.health.max_ice_mass_change);
         return j;
       }},
      {"mooring", "", false, false,
       "a moored structure (structure.motion = \"moored\") over the analysis window, null for a towed one: "
       "mean_N, max_N, std_N of the mooring's force along the travel (N, holding the structure against the ice; "
       "low-passed as the ice load), offset_mean_m, offset_std_m and offset_min_m of the structure's surge offset "
       "from its attachment's rest (m, negative: pushed back), tension_max_N (the largest line tension)",
       [](S s) {
         if (!s.mooring.present || !s.has_statistics) return json(nullptr);
         const MooringSummary& m = s.mooring;
         return json{{"mean_N", num(m.force.mean)},         {"max_N", num(m.force.max)},
                     {"std_N", num(m.force.std)},           {"offset_mean_m", num(m.offset_mean_m)},
                     {"offset_std_m", num(m.offset_std_m)}, {"offset_min_m", num(m.offset_min_m)},
                     {"tension_max_N", num(m.tension_max_N)}};
       }},
      {"solver", "", false, false,
       "the contact solver over the run: method (solver.method), cap, tolerance, joint_tolerance (islands with "
       "joints; 0 for pgs), structure_tolerance (islands touching the structure; 0 for pgs), iterations_mean and "
       "iterations_max (sweeps per step, or the method's iterations), capped_steps, capped_window_fraction (share of "
       "the window's steps that hit the cap unconverged), residual_max (the sweeps' residual, or the method's merit), "
       "breaking_solves (islands solved again to breaking_tolerance, solver.breaking_merit_tolerance, for a joint "
       "near its capacity; 0 for pgs), breaking_decided (of those, the ones every break of which was decided at "
       "solver.breaking_check_tolerance), breaking_capped (of those, the ones stopped at solver.breaking_iterations above "
       "it), handovers (islands left at the cap above their merit that handover_method, solver.handover_method, went "
       "on with), runaways (answers of those later stages not taken for impulses grown over tenfold at a merit no "
       "higher)",
       [](S s) {
         json j{{"method", s.solver.method},
                {"cap", s.solver.cap},
                {"tolerance", s.solver.tolerance},
                {"joint_tolerance", s.solver.joint_tolerance},
                {"structure_tolerance", s.solver.structure_tolerance},
                {"iterations_mean", s.solver.iterations_mean},
                {"iterations_max", s.solver.iterations_max},
                {"capped_steps", s.solver.capped_steps},
                {"capped_window_fraction", s.solver.capped_window_fraction},
                {"residual_max", num(s.solver.residual_max)},
                {"breaking_tolerance", s.solver.breaking_tolerance},
                {"handover_method", s.solver.handover_method}};
         // the island solve's counts over the run, by the diagnostics' table
         for (const DiagnosticColumn& c : kDiagnosticColumns)
           if (c.reduction == Reduction::kCount) j[c.name] = static_cast<long>(s.solver.totals.*c.field);
         return j;
       }},
      {"boundary", "", false, false,
       "the fixed boundaries (mother ice, walls, frozen floes) over the analysis window: share_of_surge (their "
       "load along the structure's travel, summed, over the surge load summed; dem/world/boundary_load.hpp) and "
       "locked_window_fraction (share of the window's steps where they carry half the surge load or more)",
       [](S s) {
         return json{{"share_of_surge", s.boundary_share}, {"locked_window_fraction", s.locked_window_fraction}};
       }},
      {"squeeze", "", false, false,
       "the structure squeezing the ice against the channel's end wall, null if the run did not get there: "
       "start_s (when its widest part came within one ice thickness of the wall), wall_x_m, max_fx_N (the "
       "largest surge load from then on: the rig's, not the ice's) and excluded_from_statistics (true unless "
       "stats.include_squeeze)",
       [](S s) {
         if (s.squeeze_start_s < 0) return json(nullptr);
         return json{{"start_s", s.squeeze_start_s}, {"wall_x_m", s.squeeze_wall_x},
                     {"max_fx_N", s.squeeze_max_fx_N}, {"excluded_from_statistics", s.squeeze_excluded}};
       }},
      {"stage_time_s", "s", false, false,
       "wall time per stage of the step: structure, water, collision, islands, solve (the contact solve), "
       "integrate, load_cell, activation, health, fracture, coupling; bullet is the sum of collision, islands, "
       "solve and integrate (Bullet's step as a whole)",
       [](S s) {
         const StageTimes& t = s.stage_times;
         return json{{"structure", t.structure}, {"water", t.water},         {"collision", t.collision},
                     {"islands", t.islands},     {"solve", t.solve},         {"integrate", t.integrate},
                     {"bullet", t.bullet()},     {"load_cell", t.load_cell}, {"activation", t.activation},
                     {"health", t.health},       {"fracture", t.fracture},   {"coupling", t.coupling}};
       }},
      {"validation", "", false, true,
       "validation cases only: case, metric, value, reference, rel_error, tolerance, passed and the case's own "
       "figures", [](S s) { return s.validation; }},
  };
  return fields;
}

json summary_json(const RunSummary& s) {
  json j = json::object();
  for (const SummaryField& f : summary_fields()) {
    json value = f.value(s);
    if (!(f.omit_if_null && value.is_null())) j[f.key] = std::move(value);
  }
  return j;
}

}  // namespace icedem
