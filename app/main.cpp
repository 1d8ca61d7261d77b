// The `icedem` command (docs/user/commands.md):
//   icedem run SCENARIO.toml [-o OUT.h5] [--set key.path=value ...] [--summary-json FILE] [--restart]
//   icedem resume OUT.h5 [--summary-json FILE]  continue a killed run from its checkpoint
//   icedem info OUT.h5                          complete, killed, torn or resumable (or OUT.h5.checkpoint)
//   icedem check SCENARIO.toml [--set ...]     validate only
//   icedem keys                                 every scenario key (markdown)
//   icedem schema                               every output: datasets, attributes, summary keys
//   icedem stl SCENARIO.toml -o hull.stl        the structure's surface
//   icedem cone-load SCENARIO.toml             the ISO 19906 and Ralston loads of level ice on the structure
//   icedem calibrate PLATE.toml [--target-modulus PA] [--write OUT.toml]
//                                               joint CFM for a target elastic modulus
//   icedem foam-case SCENARIO.toml -o DIR       a runnable OpenFOAM case (DIR/Allrun)
//   icedem foam-solve SCENARIO.toml             solve it into the cache (flow.model = "coupled")
//   icedem flow SCENARIO.toml -o OUT.csv        the flow model's water velocity at sample points
// Exit codes (dem/core/errors.hpp): 0 success, 2 bad input, 3 numerical failure, 4 OpenFOAM coupling
// failure, 5 output not written (disk full), 130 interrupted by SIGINT, 143 by SIGTERM, 1 other.
#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "coupling/coupled_flow.hpp"
#include "coupling/foam_case.hpp"
#include "coupling/foam_runner.hpp"
#include "dem/core/build_id.hpp"
#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/input/scenario.hpp"
#include "dem/input/scene_builder.hpp"
#include "dem/mooring/floating_structure.hpp"
#include "dem/output/checkpoint.hpp"
#include "dem/output/lock.hpp"
#include "dem/output/output_guard.hpp"
#include "dem/output/recorder.hpp"
#include "dem/output/run_files.hpp"
#include "dem/output/schema.hpp"
#include "dem/run/simulation.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/validation/calibration.hpp"
#include "dem/validation/iso19906.hpp"
#include "dem/validation/ralston.hpp"
#include "dem/world/cone_geometry.hpp"

using namespace icedem;

namespace {

std::string joined_command_line(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

// HDF5 1.10 crashes at exit cleaning up a file it could not close (a full disk mid-close):
// then end here, after the messages, without the library's exit-time cleanup
int leave(int code) {
  if (Recorder::left_a_file_open()) {
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}

void write_json(const std::string& path, const nlohmann::json& j) {
  std::ofstream out(path);
  if (!out) throw OutputError(fmt::format("{}: cannot write the summary JSON", path));
  out << j.dump(2) << "\n";
  out.close();  // a full disk shows here, not at the write
  if (!out) throw OutputError(fmt::format("{}: the summary JSON could not be written in full", path));
}

// the optional outputs that were given
std::vector<PlannedOutput> given(std::vector<PlannedOutput> outputs) {
  outputs.erase(std::remove_if(outputs.begin(), outputs.end(), [](const PlannedOutput& o) { return o.path.empty(); }),
                outputs.end());
  return outputs;
}

// 0, or 128 + the signal that interrupted the run (130 for Ctrl-C, 143 for SIGTERM)
int exit_code(const RunSummary& summary) {
  if (summary.status != "interrupted") return kExitOk;
  return summary.signal == SIGTERM ? kExitTerminated : kExitInterrupted;
}

// The options that export contact problems of chosen steps (run and resume).
void add_export_options(CLI::App& command, ProblemExportSettings& problems) {
  command.add_option("--export-problems", problems.directory,
                     "write contact problems of chosen steps to this directory (FCLIB files; "
                     "docs/model/contact_problems.md)");
  command.add_option("--export-at", problems.times, "s: export the islands of the steps holding these times")
      ->delimiter(',');
  command.add_option("--export-capped", problems.capped, "export up to this many islands that stopped at the sweep cap");
  command.add_option("--export-spacing", problems.capped_spacing,
                     "s, least time between two capped exports (default 1)");
  command.add_option("--export-min-contacts", problems.min_contacts, "leave out islands with fewer contacts (default 1)");
  command.add_option("--export-name", problems.name, "file name prefix (default: problem)");
}

// What run and resume print and write once the run ends, and their exit code.
int finish_run(const RunSummary& summary, const std::string& summary_path, const ProblemExportSettings& problems) {
  std::cout << summary_table(summary) << std::flush;
  if (!problems.directory.empty())
    std::cout << fmt::format("{} contact problems written to {}\n", summary.problem_files.size(), problems.directory);
  if (!summary_path.empty()) write_json(summary_path, summary_json(summary));
  return exit_code(summary);
}

int run_command(const std::string& scenario_path, std::string output, const std::vector<std::string>& sets,
                const std::string& summary_path, bool quiet, bool restart, const std::string& command_line,
                const ProblemExportSettings& problems) {
  const Scene scene = load_scene(scenario_path, sets);
  const std::string option = output.empty() ? "the output" : "-o";
  if (output.empty()) output = std::filesystem::path(scenario_path).stem().string() + ".h5";
  // a killed run's output is continued by resume; starting it over loses its progress, so only
  // on request (a finished or failed run's output is replaced, as a re-run is meant to)
  // (only a checkpoint makes a run resumable: without one, the output is not read here)
  const RunFiles before = std::filesystem::exists(checkpoint_path(output)) ? look_at_run(output) : RunFiles{};
  if (before.resumable() && !restart)
    throw InputError(fmt::format(
        "{} {}: a killed run's output ({}), resumable from its checkpoint {}: `icedem resume {}` continues it; "
        "`icedem run ... --restart` starts it over and replaces both",
        option, output,
        before.damaged() ? "torn"
                         : before.meta ? fmt::format("status {}, to t = {:.2f} s", before.meta->status, before.meta->last_time)
                                       : "lost",
        before.checkpoint, output));
  const bool torn = restart && before.checkpoint_exists && before.damaged();
  guard_outputs(
      given({{option, output, OutputKind::kRun, true, torn}, {"--summary-json", summary_path, OutputKind::kFile}}),
      {scenario_path, scene.layout.file});
  const OutputLock lock(output);  // one run per output file
  if (torn) std::cerr << fmt::format("{}: torn; kept as {}\n", output, keep_aside(output));
  RunOptions options{output, !quiet, command_line, openfoam_coupling(), problems};
  const RunSummary summary = run_simulation(scene, options);
  return finish_run(summary, summary_path, problems);
}

// Continue a killed or interrupted run from its checkpoint (dem/output/checkpoint.hpp): the output
// becomes the checkpoint's copy of it, and the run appends to it from there. An output torn or
// lost by the kill is rebuilt from the checkpoint (a torn one kept aside first: run_files.hpp).
int resume_command(const std::string& output, const std::string& summary_path, bool quiet,
                   const std::string& command_line, const ProblemExportSettings& problems) {
  const RunFiles files = look_at_run(output);
  const std::string& saved = files.checkpoint;
  if (!std::filesystem::exists(output) && !files.checkpoint_exists)
    throw InputError(fmt::format("{}: no such output file, and no checkpoint of it ({})", output, saved));
  // a finished run is never touched
  if (files.meta && files.meta->status == "complete")
    throw InputError(fmt::format("{}: the run is complete (status complete): nothing to resume", output));
  if (!files.checkpoint_exists) {
    if (files.damaged()) throw InputError(files.damage + "; and it has no checkpoint to rebuild it from");
    throw InputError(fmt::format("{}: no checkpoint ({}): the run stopped before its first checkpoint "
                                 "(output.checkpoint_interval) or does not write them; run it again",
                                 output, saved));
  }
  const Checkpoint checkpoint = read_checkpoint(saved);  // refused (damaged, changed): nothing is touched
  const OutputMeta origin = read_output_meta(saved);
  const std::filesystem::path base = std::filesystem::path(origin.scenario_path).parent_path();
  // the scenario as the checkpoint stores it (resolved: its lines are not the original file's)
  Scene scene = make_scene(parse_scenario(origin.scenario_text, saved + ":/meta/scenario", base.string(), {}));
  scene.source_path = origin.scenario_path;
  guard_outputs(given({{"the output", output, OutputKind::kRun, false, files.damaged()},
                       {"--summary-json", summary_path, OutputKind::kFile}}),
                {saved, origin.scenario_path, scene.layout.file});
  const OutputLock lock(output);  // one run per output file
  if (files.damaged())
    std::cerr << fmt::format("{}: torn ({}); kept as {}, and rebuilt from its checkpoint\n", output, files.damage,
                             keep_aside(output));
  // the output as it stood at the checkpoint, copied into the locked file itself (a rename
  // would put an unlocked file in its place); a kill during the copy leaves the checkpoint whole
  std::filesystem::copy_file(saved, output, std::filesystem::copy_options::overwrite_existing);
  remove_checkpoint_group(output);
  std::cerr << fmt::format("resuming {} from its checkpoint at t = {:.2f} s\n", output, checkpoint.values.time);
  RunOptions options{output, !quiet, command_line, openfoam_coupling(), problems, &checkpoint};
  const RunSummary summary = run_simulation(scene, options);
  return finish_run(summary, summary_path, problems);
}

// Whether the checkpoint `saved` can be resumed: its time, or why it is refused.
struct CheckpointVerdict {
  std::optional<double> time;  // s, where a resume starts
  std::string refused;         // why not (changed or damaged since it was written)
};
CheckpointVerdict verdict_of(const std::string& saved) {
  CheckpointVerdict v;
  try {
    v.time = read_checkpoint(saved).values.time;
  } catch (const InputError& e) {
    v.refused = e.what();
  }
  return v;
}

// `icedem info` on a checkpoint file named as checkpoints are: what it holds and how to resume it.
int checkpoint_info(const std::string& saved, const std::string& output) {
  const OutputMeta meta = read_output_meta(saved);
  std::cout << fmt::format("{}: the checkpoint of {}: {} steps recorded, to t = {:.2f} s\n", saved, output, meta.rows,
                           meta.last_time);
  const CheckpointVerdict v = verdict_of(saved);
  if (!v.refused.empty()) {
    std::cout << "  not resumable: the checkpoint is refused\n" << std::flush;
    throw InputError(v.refused);
  }
  std::cout << fmt::format("  resumable from t = {:.2f} s: icedem resume {}\n", *v.time, output);
  return kExitOk;
}

// What state a run's output is in, and whether (and from when) it can be resumed.
int info_command(const std::string& output) {
  if (const std::optional<std::string> of = output_of_checkpoint(output); of && std::filesystem::exists(output))
    return checkpoint_info(output, *of);
  const RunFiles files = look_at_run(output);
  const std::string& saved = files.checkpoint;
  // an output lost or torn after its run was killed: its checkpoint says what there is (resume rebuilds it)
  const bool lost = !files.output_exists && files.checkpoint_exists;  // missing, or empty
  if (!files.checkpoint_exists && !files.damage.empty()) throw InputError(files.damage);
  const OutputMeta meta = files.meta ? *files.meta : read_output_meta(lost || files.damaged() ? saved : output);
  const CheckpointVerdict v = files.checkpoint_exists ? verdict_of(saved) : CheckpointVerdict{};
  if (lost)
    std::cout << fmt::format("{}: {}; its checkpoint {} holds {} steps, to t = {:.2f} s\n", output,
                             std::filesystem::exists(output) ? "empty" : "no such file", saved, meta.rows,
                             meta.last_time);
  else if (files.damaged())
    std::cout << fmt::format("{}: torn, it cannot be read ({}); its checkpoint {} holds {} steps, to t = {:.2f} s\n",
                             output, files.damage, saved, meta.rows, meta.last_time);
  else
    std::cout << fmt::format("{}: {}, {} steps recorded, to t = {:.2f} s\n", output, meta.status, meta.rows,
                             meta.last_time);
  if (!meta.message.empty()) std::cout << "  " << meta.message << "\n";
  if (meta.status == "running" && !lost && !files.damaged()) {
    // a live run holds the file's lock (dem/output/lock.hpp): if we can take it, the writer died
    bool alive = false;
    try {
      const OutputLock probe(output);
    } catch (const InputError&) {
      alive = true;
    }
    std::cout << (alive ? "  a run is writing it now\n"
                        : fmt::format("  its writer was killed at t = {:.2f} s or up to one block of rows (10 s) "
                                      "later\n",
                                      meta.last_time));
  }
  if (!v.refused.empty()) {
    std::cout << "  not resumable: its checkpoint is refused\n" << std::flush;
    throw InputError(v.refused);
  }
  if (files.damaged())
    std::cout << fmt::format("  resumable from t = {:.2f} s: icedem resume {} rebuilds it from the checkpoint (the "
                             "torn file kept as {}.damaged)\n",
                             *v.time, output, output);
  else if (meta.status != "complete")
    std::cout << (v.time ? fmt::format("  resumable from t = {:.2f} s: icedem resume {}\n", *v.time, output)
                         : std::string("  not resumable: it has no checkpoint\n"));
  return kExitOk;
}

int check_command(const std::string& scenario_path, const std::vector<std::string>& sets) {
  const Scene scene = load_scene(scenario_path, sets);
  // also validates layout files, concentration, and that breakable floes cut into elements
  const Layout layout = scene_layout(scene);
  const std::string moored =
      scene.structure.motion == StructureMotion::kMoored ? describe(checked_floating_structure(scene)) : "";
  const std::string ice = scene.ice.cover == IceCover::kLevel
                              ? fmt::format("level ice over {:.2f} % of the channel", 100 * layout.achieved_concentration)
                              : fmt::format("{} floes, concentration {:.2f} %", layout.floes.size(),
                                            100 * layout.achieved_concentration);
  std::cout << fmt::format("{}: ok ({}, {:.0f} s at dt {} s)\n", scenario_path, ice, scene.time.duration,
                           scene.time.dt);
  std::cout << moored;
  for (const std::string& w : scene_warnings(scene, layout)) std::cout << "warning: " << w << "\n";
  return kExitOk;
}

int stl_command(const std::string& scenario_path, const std::vector<std::string>& sets, const std::string& output) {
  const Scene scene = load_scene(scenario_path, sets);
  guard_outputs({{"-o", output, OutputKind::kFile}}, {scenario_path, scene.layout.file});
  const TriangleMesh mesh = hull_surface(scene.structure.profile, scene.structure.segments);
  write_stl(mesh, output, "structure");
  std::cout << fmt::format("{}: {} triangles, enclosed volume {:.6f} m^3 (structure frame: axis = y, "
                           "waterline y = 0)\n", output, mesh.triangles.size(), mesh_volume(mesh));
  return kExitOk;
}

int cone_load_command(const std::string& scenario_path, const std::vector<std::string>& sets, const RubblePile& pile,
                      bool json) {
  const Scene scene = load_scene(scenario_path, sets);
  ConeLoadInputs in = cone_load_inputs(scene);
  in.rubble = pile;
  const ConeLoad r = iso19906_cone_load(in);
  const RalstonLoad ralston = ralston_cone_load(in);  // no pile in its method
  if (json) {  // for the report's comparison of fracture models (tools/icedem_tools/reports/report_fracture_models.py)
    const nlohmann::json j{{"friction", in.friction},
                           {"ice_friction", in.ice_friction},
                           {"ride_height_m", r.ride_height},
                           {"rubble_height_m", pile.height},
                           {"breaking_N", r.breaking},
                           {"pile_push_N", r.pile_push},
                           {"ride_N", r.ride},
                           {"pile_lift_N", r.pile_lift},
                           {"turning_N", r.turning},
                           {"total_N", r.total},
                           {"breaking_only_N", r.breaking_only},
                           {"crack_width_m", r.crack_width},
                           {"characteristic_length_m", r.characteristic_length},
                           {"ralston_breaking_N", ralston.breaking},
                           {"ralston_ride_N", ralston.ride},
                           {"ralston_total_N", ralston.total}};
    std::cout << j.dump(2) << "\n";
    return kExitOk;
  }
  const std::string pile_text =
      pile.height > 0 ? fmt::format("rubble pile h_R {:.3f} m, e {:.2f}, face {:.1f} deg, phi {:.1f} deg, c {:.0f} Pa, "
                                    "mu_i {:.2f}",
                                    pile.height, pile.porosity, pile.angle * 180.0 / M_PI,
                                    pile.friction_angle * 180.0 / M_PI, pile.cohesion, in.ice_friction)
                      : std::string("no rubble pile (--rubble-height)");
  std::cout << fmt::format(
      "ISO 19906 (Croasdale and Cammaert) load of level ice on the {} slope, dem/validation/iso19906.hpp:\n"
      "  inputs: D {:.3f} m, slope {:.1f} deg, ride height {:.3f} m, h {:.4f} m, sigma_f {:.0f} Pa, E {:.3g} Pa, "
      "nu {:.2f}, rho_i {:.0f}, rho_w {:.0f} kg/m^3, mu {:.2f}\n"
      "  {}\n"
      "  L_c {:.3f} m, crack width {:.3f} m, xi {:.3f}\n"
      "  breaking H_B {:.1f} N, rubble push H_P {:.1f} N, ride H_R {:.1f} N, rubble lift H_L {:.1f} N, "
      "turning H_T {:.1f} N\n"
      "  total H {:.1f} N (breaking alone {:.1f} N)\n",
      in.downward ? "downward-breaking" : "upward-breaking", in.waterline_diameter, in.slope * 180.0 / M_PI,
      r.ride_height, in.thickness, in.flexural_strength, in.elastic_modulus, in.poisson_ratio, in.ice_density,
      in.water_density, in.friction, pile_text, r.characteristic_length, r.crack_width, r.slope_factor, r.breaking,
      r.pile_push, r.ride, r.pile_lift, r.turning, r.total, r.breaking_only);
  std::cout << fmt::format(
      "Ralston (IEC 61400-3) load of level ice on the same slope, dem/validation/ralston.hpp{}:\n"
      "  slope ends at D_T {:.3f} m, G {:.3f}\n"
      "  breaking H_B {:.1f} N, ride H_R {:.1f} N, total H {:.1f} N\n",
      pile.height > 0 ? " (no rubble pile in its method)" : "", in.end_diameter, ralston.weight_ratio,
      ralston.breaking, ralston.ride, ralston.total);
  return kExitOk;
}

int foam_case_command(const std::string& scenario_path, const std::vector<std::string>& sets, const std::string& output) {
  const Scene scene = load_scene(scenario_path, sets);
  guard_outputs({{"-o", output, OutputKind::kDirectory}}, {scenario_path, scene.layout.file});
  const FoamCaseSpec spec = foam_case_spec(scene);
  write_foam_case(spec, foam_template_dir(), output);
  const GridAxes g = foam_grid_axes(spec);
  std::cout << fmt::format("{}: OpenFOAM case ({} mesh, hash {}), {} grid points; run {}/Allrun\n", output, spec.mesh,
                           foam_case_hash(spec), g.count(), output);
  return kExitOk;
}

int foam_solve_command(const std::string& scenario_path, const std::vector<std::string>& sets) {
  const Scene scene = load_scene(scenario_path, sets);
  const FlowGrid grid = solved_flow_grid(scene, std::cout);
  std::cout << fmt::format("{}/flow_grid.h5: {} x {} x {} points\n", foam_case_dir(foam_case_spec(scene), scene.coupling.cache_dir),
                           grid.axes().nx, grid.axes().ny, grid.axes().nz);
  return kExitOk;
}

// The scene's flow model (flow.model) sampled around the structure at its start
// position, moving at its speed: radial lines at the waterline (1 mm below it)
// and at half the keel depth, at 0 (bow), 45, 90 (shoulder), 135 and 180 degrees
// from +x, from 1 cm outside the hull to 3 m; a CSV of (line, angle_deg, r, x, y,
// z, ux, uy, uz), tank frame, m and m/s.
int flow_command(const std::string& scenario_path, const std::vector<std::string>& sets, const std::string& output) {
  const Scene scene = load_scene(scenario_path, sets);
  guard_outputs({{"-o", output, OutputKind::kFile}}, {scenario_path, scene.layout.file});
  const std::unique_ptr<FlowField> flow = make_flow(scene, openfoam_coupling());
  const Eigen::Vector3d axis(scene.structure.start_x, 0.0, scene.structure.start_z);
  flow->set_structure(axis, Eigen::Vector3d(scene.structure.speed, 0.0, 0.0));
  std::ofstream out(output);
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write", output));
  out << "depth,angle_deg,r,x,y,z,ux,uy,uz\n";
  const double keel = scene.structure.profile.front().y;
  for (double y : {-0.001, keel / 2})
    for (double angle : {0.0, 45.0, 90.0, 135.0, 180.0}) {
      const double a = angle * kPi / 180, r0 = profile_radius(scene.structure.profile, y) + 0.01;
      for (double r = r0; r <= 3.0 + 1e-9; r += 0.01) {
        const Eigen::Vector3d p = axis + Eigen::Vector3d(r * std::cos(a), y, r * std::sin(a));
        const Eigen::Vector3d u = flow->velocity(p);
        out << fmt::format("{:.4g},{:.0f},{:.4f},{:.6f},{:.6f},{:.6f},{:.9g},{:.9g},{:.9g}\n", -y, angle, r, p.x(), p.y(),
                           p.z(), u.x(), u.y(), u.z());
      }
    }
  std::cout << fmt::format("{}: flow.model {} sampled on 10 radial lines\n", output, scene.flow.model == FlowModel::kCoupled ? "coupled" : "analytic");
  return kExitOk;
}

int calibrate_command(const std::string& scenario_path, const std::vector<std::string>& sets, double target,
                      const std::string& write_path) {
  const Scene scene = load_scene(scenario_path, sets);
  guard_outputs(given({{"--write", write_path, OutputKind::kFile}}), {scenario_path, scene.layout.file});
  if (target <= 0) target = scene.ice.elastic_modulus;
  const std::string key = scene.fracture.elastic_joints ? "fracture.stiffness_scale" : "fracture.cfm";
  std::cout << fmt::format("calibrating {} for E = {:.1f} MPa: {} m plate of {} m elements, "
                           "time.dt = {} s, {} substeps\n",
                           key, target / 1e6, scene.validation.plate_size, scene.fracture.element_size, scene.time.dt,
                           scene.time.substeps);
  const CalibrationResult r = calibrate_joints(scene, target);
  std::cout << fmt::format("  {:>24}  {:>10}  {:>8}\n", key, "w0/P mm/N", "E MPa");
  for (const CalibrationPoint& p : r.points)
    std::cout << fmt::format("  {:24.4g}  {:10.4f}  {:8.2f}\n", p.value, p.compliance * 1e3, p.modulus / 1e6);
  if (!r.reached) {
    std::cerr << "calibration not reached: " << r.note << "\n";
    return kExitRuntime;
  }
  std::cout << fmt::format("{} = {:.6g} gives E = {:.2f} MPa\n", r.key, r.value, r.modulus / 1e6);
  if (!write_path.empty()) {
    std::vector<std::string> with_value = sets;
    with_value.push_back(fmt::format("{}={:.6g}", r.key, r.value));
    std::ofstream out(write_path);
    if (!out) throw std::runtime_error(fmt::format("{}: cannot write the calibrated scenario", write_path));
    out << "# calibrated by: icedem calibrate " << scenario_path << "\n"
        << read_scenario(scenario_path, with_value).resolved_text();
    std::cout << "wrote " << write_path << "\n";
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"icedem: a conical structure towed through managed ice floes (non-smooth DEM on Bullet)"};
  app.require_subcommand(1);
  // the version and the build (its commit): what a bug report or a sweep's record needs to name
  app.set_version_flag("--version", std::string("icedem ") + ICEDEM_VERSION + " (" + icedem::build_id().text() + ")");
  std::string scenario, output, summary_path;
  std::vector<std::string> sets;
  bool quiet = false;

  CLI::App* run = app.add_subcommand("run", "simulate a scenario and write the HDF5 results");
  run->add_option("scenario", scenario, "scenario TOML file")->required();
  run->add_option("-o,--output", output, "HDF5 output file (default: <scenario name>.h5)");
  run->add_option("--set", sets, "override a scenario key, e.g. --set friction.ice_ice=0.3")->take_all();
  run->add_option("--summary-json", summary_path, "write the run summary as JSON to this file");
  run->add_flag("-q,--quiet", quiet, "no progress line");
  bool restart = false;
  run->add_flag("--restart", restart,
                "start over a killed run whose output is named (its checkpoint and output replaced); without it "
                "such a run is refused: `icedem resume` continues it");
  ProblemExportSettings problems;
  add_export_options(*run, problems);

  CLI::App* resume = app.add_subcommand("resume", "continue a killed or interrupted run from its checkpoint");
  resume->add_option("output", output, "the run's HDF5 output file (its checkpoint is OUTPUT.checkpoint)")->required();
  resume->add_option("--summary-json", summary_path, "write the run summary as JSON to this file");
  resume->add_flag("-q,--quiet", quiet, "no progress line");
  // a run that failed late (a blow-up after hours) is looked into from its last checkpoint: the
  // islands of the failing step are exported without running it from the start again
  add_export_options(*resume, problems);

  CLI::App* info = app.add_subcommand("info", "say whether a run's output is complete, killed or resumable");
  info->add_option("output", output, "a run's HDF5 output file")->required();

  CLI::App* check = app.add_subcommand("check", "validate a scenario (and its floe layout) only");
  check->add_option("scenario", scenario, "scenario TOML file")->required();
  check->add_option("--set", sets, "override a scenario key")->take_all();

  CLI::App* keys = app.add_subcommand("keys", "print every scenario key with unit, default, range and meaning");
  CLI::App* schema = app.add_subcommand("schema", "print every output (HDF5 datasets, attributes, summary keys)");

  CLI::App* stl = app.add_subcommand("stl", "write the structure's surface as an ASCII STL");
  stl->add_option("scenario", scenario, "scenario TOML file")->required();
  stl->add_option("--set", sets, "override a scenario key")->take_all();
  stl->add_option("-o,--output", output, "STL file")->required();

  CLI::App* cone_load = app.add_subcommand(
      "cone-load", "the ISO 19906 (Croasdale) and Ralston loads of level ice on the scenario's structure, term by term");
  cone_load->add_option("scenario", scenario, "scenario TOML file")->required();
  cone_load->add_option("--set", sets, "override a scenario key")->take_all();
  bool cone_load_json = false;
  cone_load->add_flag("--json", cone_load_json, "print the terms as JSON (N, m)");
  // a rubble pile is not in a scenario (the paper's managed floes clear the cone): options here
  RubblePile pile;
  double pile_angle_deg = 0, pile_friction_deg = 0;
  CLI::Option* pile_height = cone_load->add_option(
      "--rubble-height", pile.height, "m, the rubble pile's height h_R from the waterline (default 0: no pile)");
  cone_load->add_option("--rubble-porosity", pile.porosity, "-, the pile's porosity e")->needs(pile_height);
  cone_load->add_option("--rubble-angle", pile_angle_deg, "deg, the pile's face from the horizontal, at most the slope")
      ->needs(pile_height);
  cone_load->add_option("--rubble-friction-angle", pile_friction_deg, "deg, the rubble's internal friction angle")
      ->needs(pile_height);
  cone_load->add_option("--rubble-cohesion", pile.cohesion, "Pa, the rubble's cohesion")->needs(pile_height);

  CLI::App* foam_case = app.add_subcommand("foam-case", "write the OpenFOAM potential-flow case of a scenario");
  foam_case->add_option("scenario", scenario, "scenario TOML file")->required();
  foam_case->add_option("--set", sets, "override a scenario key")->take_all();
  foam_case->add_option("-o,--output", output, "case directory")->required();

  CLI::App* foam_solve = app.add_subcommand(
      "foam-solve", "mesh and solve the scenario's OpenFOAM case into the cache (coupling.cache_dir)");
  foam_solve->add_option("scenario", scenario, "scenario TOML file")->required();
  foam_solve->add_option("--set", sets, "override a scenario key")->take_all();

  CLI::App* flow_cmd = app.add_subcommand("flow", "sample the scenario's flow model around the structure (CSV)");
  flow_cmd->add_option("scenario", scenario, "scenario TOML file")->required();
  flow_cmd->add_option("--set", sets, "override a scenario key")->take_all();
  flow_cmd->add_option("-o,--output", output, "CSV file")->required();

  double target_modulus = 0;
  std::string write_path;
  CLI::App* calibrate = app.add_subcommand(
      "calibrate", "find the joints' stiffness scale (elastic joints) or CFM (Bullet's) that gives a plate-deflection "
                   "scenario its target elastic modulus");
  calibrate->add_option("scenario", scenario, "plate-deflection validation scenario")->required();
  calibrate->add_option("--set", sets, "override a scenario key")->take_all();
  calibrate->add_option("--target-modulus", target_modulus, "Pa (default: ice.elastic_modulus)");
  calibrate->add_option("--write", write_path, "write the scenario with the calibrated key");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }

  try {
    if (*run) {
      if (run->count("-o") && output.empty())
        throw InputError("-o '': give a file name (or leave -o out: <scenario>.h5)");
      return run_command(scenario, output, sets, summary_path, quiet, restart, joined_command_line(argc, argv),
                         problems);
    }
    if (*resume) return resume_command(output, summary_path, quiet, joined_command_line(argc, argv), problems);
    if (*info) return info_command(output);
    if (*check) return check_command(scenario, sets);
    if (*stl) return stl_command(scenario, sets, output);
    if (*cone_load) {
      pile.angle = pile_angle_deg * M_PI / 180.0;
      pile.friction_angle = pile_friction_deg * M_PI / 180.0;
      return cone_load_command(scenario, sets, pile, cone_load_json);
    }
    if (*calibrate) return calibrate_command(scenario, sets, target_modulus, write_path);
    if (*foam_case) return foam_case_command(scenario, sets, output);
    if (*foam_solve) return foam_solve_command(scenario, sets);
    if (*flow_cmd) return flow_command(scenario, sets, output);
    if (*keys) std::cout << keys_markdown();
    if (*schema) std::cout << output_markdown();
    return kExitOk;
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const CouplingError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitCoupling;
  } catch (const NumericalError& e) {
    std::cerr << "\nerror: " << e.what() << "\n(the output file keeps every step before the failure, "
              << "marked status = failed)\n";
    return leave(kExitNumerical);
  } catch (const OutputError& e) {
    std::cerr << "\nerror: " << e.what() << "\n";
    return leave(kExitOutput);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return leave(kExitRuntime);
  }
}
