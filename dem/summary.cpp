#include "dem/summary.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "dem/constants.hpp"
#include "dem/joint_loads.hpp"

namespace icedem {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// sweeps per step, and a warning when the cap, not the tolerance, ended the sweeps
// of many steps: the loads of those steps are not converged (README, "Convergence")
std::string solver_line(const SolverSummary& v) {
  std::string out = fmt::format("  contact solver: {:.1f} sweeps per step on average, at most {:d} (cap {:d}), "
                                "tolerance {:g}, largest residual {:.2g}\n",
                                v.iterations_mean, v.iterations_max, v.cap, v.tolerance, v.residual_max);
  if (v.tolerance > 0 && v.capped_window_fraction > SolverSummary::kCappedWarning)
    out += fmt::format("  warning: {:.1f} % of the analysis window's steps reached solver.iterations = {:d} before "
                       "solver.tolerance = {:g}: their loads are not converged; raise the cap "
                       "(/diagnostics/solver_capped has the steps)\n",
                       100 * v.capped_window_fraction, v.cap, v.tolerance);
  if (v.tolerance == 0)
    out += "  note: solver.tolerance = 0 runs every island to the cap and nothing checks that the loads "
           "converged (README, \"Convergence\")\n";
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
  out += fmt::format("  wall time by stage: Bullet {:.1f} s, water {:.1f} s, activation {:.1f} s, load cell {:.1f} s, "
                     "{}other {:.1f} s\n", t.bullet, t.water, t.activation, t.load_cell,
                     t.coupling > 0 ? fmt::format("OpenFOAM exchanges {:.1f} s, ", t.coupling) : "",
                     s.wall_time_s - t.bullet - t.water - t.activation - t.load_cell - t.coupling);
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
  // an element turning this fast is rocking unstably, not moving with the ice (README,
  // "Breakable ice": at ERP 0.8 elements rock with a growing period-2 oscillation)
  if (s.health.max.max_angular_speed > kRockingAngularSpeed)
    out += fmt::format("  warning: a floe or element turned at {:.1f} rad/s (t = {:.2f} s): unstable joints? "
                       "/diagnostics/max_angular_speed has the history; README, \"Breakable ice\"\n",
                       s.health.max.max_angular_speed, s.health.max_time[0]);
  out += solver_line(s.solver);
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
  out += fmt::format("  load peaks {:d}, mean spacing {} s; breaks {:d} (compression {}, shear {}, bending {})\n",
                     st.peaks, std::isfinite(st.peak_interval_s) ? fmt::format("{:.2f}", st.peak_interval_s) : "n/a",
                     s.breaks, s.breaks_by_mode[0], s.breaks_by_mode[1], s.breaks_by_mode[2]);
  if (s.breaks > 0)
    for (int m = 0; m < kBreakMechanisms; ++m)
      out += fmt::format("{}{} {}{}", m ? ", " : "  breaks by mechanism: ",
                         break_mechanism_name(static_cast<BreakMechanism>(m)), s.breaks_by_mechanism[m],
                         m + 1 == kBreakMechanisms ? "\n" : "");
  if (!s.near_structure_max_ratio.empty()) {
    const auto& r = s.near_structure_max_ratio;
    const long over_half = std::count_if(r.begin(), r.end(), [](double x) { return x >= 0.5; });
    out += fmt::format("  floes near the structure: {:d}; their largest joint load ratio: median {:.2f}, "
                       "max {:.2f}; {:d} reached half their capacity\n",
                       r.size(), median(r), *std::max_element(r.begin(), r.end()), over_half);
  }
  return out;
}

nlohmann::json summary_json(const RunSummary& s) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  const bool ok = s.has_statistics;
  nlohmann::json j;
  j["scenario"] = s.scenario;
  j["output"] = s.output;
  j["status"] = s.status;
  j["message"] = s.message;
  j["statistics_note"] = s.statistics_note;
  j["mean_fx_N"] = ok ? num(s.surge.mean) : nullptr;
  j["max_fx_N"] = ok ? num(s.surge.max) : nullptr;
  j["std_fx_N"] = ok ? num(s.surge.std) : nullptr;
  j["mean_fy_N"] = ok ? num(s.mean_fy_N) : nullptr;
  j["mean_fz_N"] = ok ? num(s.mean_fz_N) : nullptr;
  j["window_s"] = ok ? num(s.surge.window_s) : nlohmann::json(0.0);
  j["window_start_s"] = ok ? num(s.surge.window_start) : nullptr;
  j["window_end_s"] = ok ? num(s.surge.window_end) : nullptr;
  j["lowpass_hz"] = ok ? num(s.surge.lowpass_hz) : nullptr;
  j["peaks"] = ok ? s.surge.peaks : 0;
  j["peak_interval_s"] = ok ? num(s.surge.peak_interval_s) : nullptr;
  j["first_contact_s"] = s.first_contact_s >= 0 ? num(s.first_contact_s) : nullptr;
  j["breaks"] = s.breaks;
  for (int m = 0; m < kFailureModes; ++m)
    j["breaks_by_mode"][failure_mode_name(static_cast<FailureMode>(m))] = s.breaks_by_mode[m];
  for (int m = 0; m < kBreakMechanisms; ++m)
    j["breaks_by_mechanism"][break_mechanism_name(static_cast<BreakMechanism>(m))] = s.breaks_by_mechanism[m];
  j["near_structure_max_ratio"] = s.near_structure_max_ratio;
  j["steps"] = s.steps;
  j["sim_time_s"] = s.sim_time_s;
  j["wall_time_s"] = s.wall_time_s;
  j["cpu_time_s"] = s.cpu_time_s;
  j["realtime_factor"] = s.wall_time_s > 0 ? num(s.sim_time_s / s.wall_time_s) : nullptr;
  j["steps_per_second"] = s.wall_time_s > 0 ? num(s.steps / s.wall_time_s) : nullptr;
  j["floes"] = s.floes;
  j["achieved_concentration"] = s.achieved_concentration;
  j["mean_awake"] = s.mean_awake;
  j["warnings"] = s.warnings;
  j["max_angular_speed_rad_s"] = s.health.max.max_angular_speed;
  // the largest value of each per-step diagnostic and when (scripts/stress bounds them)
  for (std::size_t c = 0; c < kDiagnosticCount; ++c) {
    const DiagnosticColumn& col = kDiagnosticColumns[c];
    j["health"][col.name] = {{"max", num(s.health.max.*col.field)}, {"unit", col.unit}, {"time_s", s.health.max_time[c]}};
  }
  j["health"]["ice_mass_initial_kg"] = num(s.health.initial_ice_mass);
  j["health"]["ice_mass_max_relative_change"] = num(s.health.max_ice_mass_change);
  if (!s.validation.is_null()) j["validation"] = s.validation;
  j["solver"] = {{"cap", s.solver.cap},
                 {"tolerance", s.solver.tolerance},
                 {"iterations_mean", s.solver.iterations_mean},
                 {"iterations_max", s.solver.iterations_max},
                 {"capped_steps", s.solver.capped_steps},
                 {"capped_window_fraction", s.solver.capped_window_fraction},
                 {"residual_max", num(s.solver.residual_max)}};
  const StageTimes& t = s.stage_times;
  j["stage_time_s"] = {{"structure", t.structure}, {"water", t.water},         {"bullet", t.bullet},
                       {"load_cell", t.load_cell}, {"activation", t.activation}, {"health", t.health},
                       {"fracture", t.fracture}, {"coupling", t.coupling}};
  return j;
}

}  // namespace icedem
