#include "dem/run/simulation.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <sys/resource.h>

#include <LinearMath/btScalar.h>
#include <fmt/format.h>

#include "dem/contact/registry.hpp"
#include "dem/core/build_id.hpp"
#include "dem/core/errors.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/input/setting_warnings.hpp"
#include "dem/input/step_size_advice.hpp"
#include "dem/input/structure_path.hpp"
#include "dem/output/checkpoint.hpp"
#include "dem/output/progress.hpp"
#include "dem/output/recorder.hpp"
#include "dem/output/schema.hpp"
#include "dem/output/statistics.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/validation/case.hpp"
#include "dem/validation/plate_deflection.hpp"

namespace icedem {
namespace {

std::atomic<int> g_interrupted{0};  // the signal that asked the run to stop, 0: none
std::atomic<int> g_signals{0};      // how many such signals came
extern "C" void on_interrupt(int signal) {
  g_interrupted = signal;
  ++g_signals;
}

// Ctrl-C ends the step loop cleanly instead of killing the process mid-write
class InterruptGuard {
 public:
  InterruptGuard() {
    g_interrupted = 0;
    g_signals = 0;
    previous_ = std::signal(SIGINT, on_interrupt);
    previous_term_ = std::signal(SIGTERM, on_interrupt);
  }
  ~InterruptGuard() {
    std::signal(SIGINT, previous_);
    std::signal(SIGTERM, previous_term_);
  }

 private:
  void (*previous_)(int);
  void (*previous_term_)(int);
};

// a moored structure's motion and its mooring's load at the step's end, into the step's sample and
// the history its statistics are taken from
void record_moored(const Scene& scene, const State& state, LoadSample& sample, RunHistory& history) {
  const StructureMotionState& m = state.structure_motion;
  const MooringLoad mooring = mooring_load_at(scene, *state.floating, state.structure_position, m, state.time);
  sample.structure_rotation = m.rotation;
  sample.structure_velocity = state.structure_velocity;
  sample.structure_angular_velocity = m.angular_velocity;
  sample.mooring_force = mooring.force;
  sample.mooring_moment = mooring.moment;
  sample.mooring_tension = mooring.tensions;
  const double travel = scene.structure.speed < 0 ? -1.0 : 1.0;
  history.mooring_surge.push_back(mooring.force.x() * travel);  // holding the structure against the ice
  history.surge_offset.push_back((state.structure_position.x() - structure_position_at(scene, state.time).x()) * travel);
  history.max_tension.push_back(mooring.tensions.empty() ? 0.0
                                                         : *std::max_element(mooring.tensions.begin(), mooring.tensions.end()));
}

// a moored structure's lines as a snapshot keeps them (none when towed): each line's points in turn
std::vector<Eigen::Vector3d> mooring_points(const Scene& scene, const State& state) {
  std::vector<Eigen::Vector3d> out;
  if (!state.floating) return out;
  const auto lines = state.floating->mooring->shape(state.structure_position, rotation_matrix(state.structure_motion),
                                                    scene.structure.speed * state.time, kMooringShapePoints);
  for (const auto& line : lines) out.insert(out.end(), line.begin(), line.end());
  return out;
}

RunMeta run_meta(const Scene& scene, const RunOptions& options) {
  RunMeta m;
  m.scenario_text = scene.resolved_text;
  m.scenario_path = scene.source_path;
  m.command_line = options.command_line;
  m.version = ICEDEM_VERSION;
  m.build = build_id().text();
  m.bullet_version = fmt::format("{}.{:02d}", BT_BULLET_VERSION / 100, BT_BULLET_VERSION % 100);
  m.precision = sizeof(btScalar) == 8 ? "double" : "float";
  m.seed = scene.seed;
  m.mooring_lines = mooring_line_count(scene);
  m.level_sheet = analytic_level_ice(scene);
  return m;
}

// the output index of every body of World::floes() (the stand-ins have none: their elements are
// the output bodies), -1 for a stand-in
std::vector<int> output_indices(const World& world) {
  std::vector<int> index(world.floes().size(), -1);
  int next = 0;
  for (std::size_t i = 0; i < world.floes().size(); ++i)
    if (!world.floes()[i].stand_in) index[i] = next++;
  return index;
}

// the output bodies from output index `first` on, born at `time` (the pieces of floes that split
// come at the end of World::floes(), so a file's bodies keep their indices)
std::vector<BodyOutline> body_outlines(const Scene& scene, const World& world, std::size_t first = 0,
                                       double time = 0.0) {
  const std::vector<int> index = output_indices(world);
  std::vector<BodyOutline> out;
  for (std::size_t i = 0; i < world.floes().size(); ++i) {
    const FloeBody& f = world.floes()[i];
    if (f.stand_in || static_cast<std::size_t>(index[i]) < first) continue;
    out.push_back(BodyOutline{f.floe_id, f.shape->outline, scene.ice.thickness, f.parent >= 0 ? index[f.parent] : -1,
                              f.parent >= 0 ? time : 0.0});
  }
  return out;
}

// every joint of a breakable floe, its bodies as output body indices
std::vector<JointRecord> joint_records(const World& world) {
  const std::vector<int> output_index = output_indices(world);
  std::vector<JointRecord> out;
  out.reserve(world.joints().size());
  for (const IceJoint& j : world.joints())
    out.push_back(JointRecord{output_index[j.body_a], output_index[j.body_b], j.floe, j.index, j.midpoint_a});
  return out;
}

std::vector<BodyPose> body_poses(const World& world) {
  std::vector<BodyPose> poses;
  poses.reserve(world.floes().size());
  for (const FloeBody& f : world.floes()) {
    if (f.stand_in) continue;  // its elements are the output bodies
    const Eigen::Isometry3d pose = output_pose(world, f);
    const uint8_t activity = f.gone   ? kBodyGone
                             : f.left ? kBodyLeft
                             : output_awake(world, f) ? kBodyAwake
                                                      : kBodyAsleep;
    poses.push_back(BodyPose{pose.translation(), Eigen::Quaterniond(pose.linear()), activity});
  }
  return poses;
}

// sweeps and residuals over the run; capped steps also as a fraction of the analysis
// window, where the statistics come from
SolverSummary solver_summary(const Scene& scene, const RunHistory& h, const RunSummary& s) {
  SolverSummary v;
  v.method = scene.solver.method;
  const bool sweeps = scene.solver.method == kBulletSweeps;
  v.cap = sweeps ? scene.solver.iterations : scene.solver.method_iterations;
  v.handover_method = sweeps ? "none" : scene.solver.handover_method;
  v.tolerance = sweeps ? scene.solver.tolerance : scene.solver.merit_tolerance;
  v.joint_tolerance = sweeps ? 0.0 : std::min(scene.solver.merit_tolerance, scene.solver.joint_merit_tolerance);
  v.structure_tolerance = sweeps ? 0.0 : std::min(scene.solver.merit_tolerance, scene.solver.structure_merit_tolerance);
  v.breaking_tolerance = sweeps || scene.fracture.mode != FractureMode::kOn ||
                                 scene.solver.breaking_merit_tolerance >= v.joint_tolerance
                             ? 0.0
                             : scene.solver.breaking_merit_tolerance;
  long window_steps = 0, window_capped = 0;
  for (std::size_t i = 0; i < h.diagnostics.size(); ++i) {
    const StepDiagnostics& d = h.diagnostics[i];
    v.iterations_mean += d.solver_iterations;
    v.iterations_max = std::max(v.iterations_max, static_cast<int>(d.solver_iterations));
    v.residual_max = std::max(v.residual_max, d.solver_residual);
    v.capped_steps += d.solver_capped > 0;
    for (const DiagnosticColumn& c : kDiagnosticColumns)
      if (c.reduction == Reduction::kCount) v.totals.*c.field += d.*c.field;
    const bool in_window = !s.has_statistics || (h.time[i] >= s.surge.window_start && h.time[i] <= s.surge.window_end);
    window_steps += in_window;
    window_capped += in_window && d.solver_capped > 0;
  }
  if (!h.diagnostics.empty()) v.iterations_mean /= static_cast<double>(h.diagnostics.size());
  v.capped_window_fraction = window_steps ? double(window_capped) / double(window_steps) : 0.0;
  return v;
}

// what the fixed boundaries carried over the analysis window (dem/world/boundary_load.hpp)
void boundary_summary(const RunHistory& h, RunSummary& s) {
  if (!s.has_statistics) return;
  double boundary = 0, surge = 0;
  long steps = 0, locked_steps = 0;
  for (std::size_t i = 0; i < h.diagnostics.size(); ++i) {
    if (h.time[i] < s.surge.window_start || h.time[i] > s.surge.window_end) continue;
    boundary += h.diagnostics[i].boundary_load;
    surge += h.surge[i];
    ++steps;
    locked_steps += h.diagnostics[i].locked > 0;
  }
  s.boundary_share = surge > 0 ? boundary / surge : 0.0;
  s.locked_window_fraction = steps ? double(locked_steps) / double(steps) : 0.0;
}

// The squeeze of the ice against the channel's end wall, if the run got there (dem/input/structure_path.hpp):
// when it began and the largest surge load from then on
void find_squeeze(const Scene& scene, const RunHistory& h, RunSummary& s) {
  const auto meeting = end_wall_meeting(scene);
  if (!meeting || h.time.empty() || h.time.back() < meeting->time) return;
  s.squeeze_start_s = meeting->time;
  s.squeeze_wall_x = meeting->wall_x;
  for (std::size_t i = 0; i < h.time.size(); ++i)
    if (h.time[i] >= meeting->time) s.squeeze_max_fx_N = std::max(s.squeeze_max_fx_N, h.surge[i]);
}

// The analysis window starts a stated travel distance after the first ice
// contact (stats.window_start_travel; default 2 waterline breadths, cf. the
// paper's window after the structure has advanced into the ice, Fig. 9), and
// ends where a squeeze against the end wall begins unless stats.include_squeeze.
void compute_statistics(const Scene& scene, const RunHistory& h, RunSummary& s) {
  find_squeeze(scene, h, s);
  if (s.first_contact_s < 0) {
    s.statistics_note = "the structure never touched the ice";
    return;
  }
  const double v = scene.structure.speed;
  const double t0 = v > 0 ? s.first_contact_s + scene.stats.window_start_travel / v : s.first_contact_s;
  double t1 = scene.stats.window_end_travel > 0 && v > 0 ? s.first_contact_s + scene.stats.window_end_travel / v
                                                         : 0.0;  // 0: to the end of the record
  // the window ends where the squeeze against the end wall begins: its load is the rig's
  if (s.squeeze_start_s >= 0 && !scene.stats.include_squeeze) {
    s.squeeze_excluded = true;
    if (s.squeeze_start_s <= t0) {
      s.statistics_note = fmt::format("the structure squeezes the ice against the channel's end wall from t = {:.1f} "
                                      "s, before the analysis window begins ({:.1f} s); stats.include_squeeze = true "
                                      "keeps those steps",
                                      s.squeeze_start_s, t0);
      return;
    }
    // the last step before the squeeze (the window's end is inclusive)
    const double before = s.squeeze_start_s - 0.5 * scene.time.dt;
    t1 = t1 > 0 ? std::min(t1, before) : before;
  }
  // peaks at least half a floe passage apart (docs/model/validation_targets.md §7)
  const double separation = v > 0 ? 0.5 * scene.ice.floe_size / v : 1.0;
  try {
    s.surge = load_statistics(h.time, h.surge, t0, t1, scene.stats.lowpass_hz, separation);
  } catch (const InputError& e) {
    s.statistics_note = fmt::format("the analysis window ({:.1f} s onwards) holds no data: {}", t0, e.what());
    return;
  }
  s.has_statistics = true;
  double fy = 0, fz = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < h.time.size(); ++i)
    if (h.time[i] >= s.surge.window_start && h.time[i] <= s.surge.window_end) fy += h.heave[i], fz += h.sway[i], ++n;
  s.mean_fy_N = n ? fy / n : 0.0;
  s.mean_fz_N = n ? fz / n : 0.0;
  if (!h.mooring_surge.empty()) {
    // the mooring's force over the ice load's window, filtered as it is; the offset and tensions as they are
    MooringSummary& m = s.mooring;
    m.present = true;
    m.force = load_statistics(h.time, h.mooring_surge, s.surge.window_start, s.surge.window_end, scene.stats.lowpass_hz,
                              separation);
    double sum = 0, sum2 = 0;
    m.offset_min_m = std::numeric_limits<double>::infinity();
    std::size_t k = 0;
    for (std::size_t i = 0; i < h.time.size(); ++i) {
      if (h.time[i] < s.surge.window_start || h.time[i] > s.surge.window_end) continue;
      sum += h.surge_offset[i], sum2 += h.surge_offset[i] * h.surge_offset[i], ++k;
      m.offset_min_m = std::min(m.offset_min_m, h.surge_offset[i]);
      m.tension_max_N = std::max(m.tension_max_N, h.max_tension[i]);
    }
    m.offset_mean_m = sum / k;
    m.offset_std_m = std::sqrt(std::max(sum2 / k - m.offset_mean_m * m.offset_mean_m, 0.0));
  }
}

// the summary's numbers marked for /stats (dem/output/summary.hpp), so the file carries its statistics
void write_statistics(Recorder& rec, const RunSummary& s) {
  std::map<std::string, double> a;
  for (const SummaryField& f : summary_fields()) {
    if (!f.stats) continue;
    const nlohmann::json value = f.value(s);
    if (value.is_number()) a[f.key] = value.get<double>();
  }
  rec.set_attributes("/stats", a);
  if (!s.has_statistics) rec.set_attribute("/stats", "note", s.statistics_note);
}

// user + system CPU seconds of this process so far
double process_cpu_time() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  auto seconds = [](const timeval& t) { return t.tv_sec + 1e-6 * t.tv_usec; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// "0 compression, 1 shear, ...": the code -> name attributes of /fracture/events, for an enum
// of `count` codes named by `name`
template <typename Code>
std::string code_names(int count, const char* (*name)(Code)) {
  std::string out;
  for (int m = 0; m < count; ++m) out += fmt::format("{}{} {}", m ? ", " : "", m, name(static_cast<Code>(m)));
  return out;
}

// how close every floe's joints came to failing: all floes in the file, the ones that came
// near the structure in the summary (runs with breakable floes only)
void record_floe_margins(const State& state, Recorder& recorder, RunSummary& summary) {
  if (state.fracture.floe_margins.empty()) return;
  std::vector<FloeFailureMargin> margins = state.fracture.floe_margins;  // floes without joints (yet) at the end
  margins.resize(std::max<std::size_t>(margins.size(), summary.floes));
  std::vector<double> ratio, distance;
  for (const FloeFailureMargin& m : margins) {
    ratio.push_back(m.max_ratio);
    distance.push_back(m.min_distance);
    if (m.min_distance <= kNearStructureDistance) summary.near_structure_max_ratio.push_back(m.max_ratio);
  }
  recorder.write_floe_margins(ratio, distance);
}

// what a new output says of the scene's layout and of its codes
void describe_output(const Scene& scene, const Layout& layout, Recorder& recorder) {
  recorder.set_attributes("/layout", {{"floes", double(layout.floes.size())},
                                      {"achieved_concentration", layout.achieved_concentration},
                                      {"target_concentration", scene.ice.concentration},
                                      {"channel_area_m2", layout.channel_area}});
  recorder.set_attribute("/fracture/events", "mode_names", code_names(kFailureModes, failure_mode_name));
  recorder.set_attribute("/fracture/events", "mechanism_names", code_names(kBreakMechanisms, break_mechanism_name));
  recorder.set_attribute("/layout", "source", scene.layout.file.empty() ? "generated" : scene.layout.file);
}

// steps between two checkpoints; 0: none. Runs whose state lives partly outside icedem (an
// OpenFOAM partner exchanging drag, a validation case's loads) or that export contact problems
// do not checkpoint
long checkpoint_steps(const Scene& scene, const RunOptions& options) {
  const bool partner = scene.flow.model == FlowModel::kCoupled && scene.coupling.mode == CouplingMode::kProbe;
  if (scene.output.checkpoint_interval <= 0 || scene.validation.kind != ValidationKind::kNone || partner ||
      !options.problems.directory.empty())
    return 0;
  return std::max(1L, std::lround(scene.output.checkpoint_interval / scene.time.dt));
}

}  // namespace

std::vector<std::string> scene_warnings(const Scene& scene, const Layout& layout) {
  std::vector<std::string> out = step_size_warnings(scene);
  for (const std::string& w : setting_warnings(scene)) out.push_back(w);
  if (const std::string w = plate_load_warning(scene); !w.empty()) out.push_back(w);
  for (const std::string& w : layout_warnings(scene, layout)) out.push_back(w);
  return out;
}

RunSummary run_simulation(const Scene& scene, const RunOptions& options) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  auto wall = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  RunSummary summary;
  summary.scenario = scene.source_path;
  summary.output = options.output;

  // initial conditions, or the state of the checkpoint the run resumes from
  SetupProgress setup(options.progress);
  const Layout layout = scene_layout(scene, [&setup](double f) { setup.update("floe layout", f); });
  setup.done();
  State state = initial_state(scene, layout.floes, options.coupling);
  if (options.resume) restore_state(*options.resume, state);
  // a new run: a checkpoint left by an earlier run of this output is not its
  std::error_code no_checkpoint;
  if (!options.resume) std::filesystem::remove(checkpoint_path(options.output), no_checkpoint);
  // the contact problems of chosen steps, written to files (runs that export do not checkpoint)
  std::unique_ptr<ProblemExport> problems;
  if (!options.problems.directory.empty()) {
    problems = std::make_unique<ProblemExport>(options.problems, scene.source_path);
    state.world->set_problem_observer(problems.get());
  }
  summary.floes = static_cast<int>(layout.floes.size());
  summary.warnings = scene_warnings(scene, layout);
  summary.achieved_concentration = layout.achieved_concentration;

  // From here on a signal stops the run at the loop's next check, with the file closed and
  // marked "interrupted": the output lock's handler, which ends set-up at once, would end the
  // process while the recorder writes the file's layout and leave a file without a status
  InterruptGuard interrupt_guard;
  // a resumed run appends to its output as the checkpoint left it (its layout attributes too)
  std::unique_ptr<Recorder> record_to =
      options.resume ? std::make_unique<Recorder>(options.output, Recorder::Reopen{})
                     : std::make_unique<Recorder>(options.output, run_meta(scene, options), body_outlines(scene, *state.world),
                                                 joint_records(*state.world));
  Recorder& recorder = *record_to;
  if (!options.resume) describe_output(scene, layout, recorder);

  const long total_steps = step_count(scene);
  const long snapshot_every =
      scene.output.snapshot_interval > 0 ? std::max(1L, std::lround(scene.output.snapshot_interval / scene.time.dt)) : 0;
  if (snapshot_every && !options.resume) recorder.append_snapshot(0.0, body_poses(*state.world), mooring_points(scene, state));
  // the analytic sheet's outline at the start; its breaks (a resumed run's file holds those before the checkpoint)
  if (state.sheet && !options.resume) recorder.append_sheet_outline(state.sheet->outline());
  std::size_t recorded_sheet_breaks = state.sheet ? state.sheet->breaks().size() : 0;
  const long checkpoint_every = checkpoint_steps(scene, options);

  const std::unique_ptr<ValidationCase> validation = make_validation_case(scene, state);
  RunHistory history = options.resume ? options.resume->history : RunHistory{};
  history.time.reserve(total_steps);
  history.surge.reserve(total_steps);
  Progress progress(total_steps * scene.time.dt, options.progress);
  double last_flush = 0.0;
  summary.status = "complete";

  // a failure mid-run: the file keeps every step so far, marked failed
  auto fail = [&](const std::string& message) {
    if (state.drag_exchange) state.drag_exchange->finish(false);
    progress.done();
    summary.wall_time_s = history.earlier_wall_s + wall();
    recorder.finish("failed", message, summary.wall_time_s);
  };
  // asked to stop: at once, or (if the run can reach it within output.stop_grace) at the next
  // checkpoint, so that the resumed run loses nothing; a checkpoint is not taken at the
  // signal's step itself, since a run rebuilds its world at each checkpoint and the resumed
  // run would then differ from the uninterrupted one (dem/output/checkpoint.hpp)
  bool heading_for_checkpoint = false;
  const long first_step = state.step;
  const double loop_start = wall();
  auto stop_now = [&] {
    if (!g_interrupted) return false;
    if (g_signals > 1 || !checkpoint_every) return true;
    if (state.step > first_step && state.step % checkpoint_every == 0) return true;  // just written
    if (!heading_for_checkpoint) {
      const long next = (state.step / checkpoint_every + 1) * checkpoint_every;
      const long done = state.step - first_step;
      const double estimate = done ? (wall() - loop_start) / done * (next - state.step) : 0.0;
      if (!done || next >= total_steps || estimate > scene.output.stop_grace) return true;
      heading_for_checkpoint = true;
      fmt::print(stderr, "icedem: {} at t = {:.2f} s: going on to the checkpoint at t = {:.2f} s (about {:.0f} s), "
                 "then stopping; signal again to stop at once\n",
                 g_interrupted == SIGTERM ? "SIGTERM" : "SIGINT", state.time, next * scene.time.dt, estimate);
    }
    return false;  // the next checkpoint is written, then the call after it stops
  };
  try {
    while (state.step < total_steps) {
      if (stop_now()) {
        summary.status = "interrupted";
        summary.signal = g_interrupted;
        const bool at_checkpoint = checkpoint_every && state.step > 0 && state.step % checkpoint_every == 0;
        summary.message = fmt::format("interrupted ({}) at t = {:.2f} s; the file holds the run so far{}",
                                      g_interrupted == SIGTERM ? "SIGTERM" : "SIGINT", state.time,
                                      at_checkpoint ? "; icedem resume continues it from here (its checkpoint)"
                                      : checkpoint_every && state.time >= scene.output.checkpoint_interval
                                          ? "; icedem resume continues it from its last checkpoint"
                                          : "");
        break;
      }
      advance(scene, state, validation.get());

      // record
      const LoadReading& load = state.load;
      LoadSample sample{state.time,     load.force,         load.moment,          state.structure_position,
                        load.contacts,  state.awake_floes,  state.contact_points, state.diagnostics};
      if (state.floating) record_moored(scene, state, sample, history);
      recorder.append(sample);
      history.time.push_back(state.time);
      history.surge.push_back(sample.surge());
      history.heave.push_back(load.force.y());
      history.sway.push_back(load.force.z());
      history.diagnostics.push_back(state.diagnostics);
      history.awake_sum += state.awake_floes;
      history.health.add(state.time, state.diagnostics);
      for (const FractureEvent& e : state.fracture.events) recorder.append_fracture(e);
      // the pieces of floes that split this step (floes that split have no lattices, so no
      // stand-ins: World::floes() are the output bodies)
      if (floes_split(scene) && state.world->floes().size() > recorder.body_count())
        recorder.add_bodies(body_outlines(scene, *state.world, recorder.body_count(), state.time));
      for (; state.sheet && recorded_sheet_breaks < state.sheet->breaks().size(); ++recorded_sheet_breaks)
        recorder.append_sheet_break(state.sheet->breaks()[recorded_sheet_breaks],
                                    state.sheet->outline_after(recorded_sheet_breaks));
      if (snapshot_every && state.step % snapshot_every == 0)
        recorder.append_snapshot(state.time, body_poses(*state.world), mooring_points(scene, state));

      // report, and keep the file readable every few seconds
      progress.update(state.time, sample.surge(), state.awake_floes);
      if (wall() - last_flush > 5.0) {
        recorder.flush();
        last_flush = wall();
      }

      // a checkpoint, and the world rebuilt from it as a resumed run rebuilds it, so that the
      // two go on from the same world (dem/output/checkpoint.hpp)
      if (checkpoint_every && state.step % checkpoint_every == 0 && state.step < total_steps) {
        recorder.flush();
        Checkpoint checkpoint = take_checkpoint(state, history);
        checkpoint.history.earlier_wall_s += wall();  // what a run resumed from here has spent before
        checkpoint.history.earlier_cpu_s += process_cpu_time();
        write_checkpoint(options.output, checkpoint);
        State rebuilt = initial_state(scene, layout.floes, options.coupling);
        restore_state(checkpoint, rebuilt);
        state = std::move(rebuilt);
      }
    }
  } catch (const NumericalError& e) {
    fail(e.what());
    throw;
  } catch (const CouplingError& e) {  // the OpenFOAM partner failed or timed out: keep the run so far
    fail(e.what());
    throw;
  } catch (const OutputError& e) {  // the disk is full: close the file with what fitted, marked failed
    try {
      fail(fmt::format("stopped at t = {:.2f} s", state.time));
    } catch (const OutputError&) {
      // could not even close it; the first error is the one to report
    }
    throw OutputError(fmt::format("{} (at t = {:.2f} s); the output file is closed and marked failed, its /meta "
                                  "message says which rows did not fit",
                                  e.what(), state.time));
  } catch (const std::exception& e) {  // a fault of the model's own (a geometry it cannot cut, ...): say when, keep the run
    const std::string message = fmt::format("{} (in the step from t = {:.2f} s)", e.what(), state.time);
    fail(message);
    throw std::runtime_error(message);
  }
  if (state.drag_exchange) state.drag_exchange->finish(summary.status == "complete");
  progress.done();

  summary.steps = state.step;
  summary.sim_time_s = state.time;
  summary.bullet_step_s = scene.time.dt / scene.time.substeps;
  summary.build = build_id();
  summary.mean_awake = state.step ? history.awake_sum / state.step : 0.0;
  summary.health = history.health;
  summary.first_contact_s = state.first_contact_time ? *state.first_contact_time : -1.0;
  summary.stage_times = state.stage_times;
  summary.breaks_by_mode = state.fracture.breaks_by_mode;
  summary.breaks_by_mechanism = state.fracture.breaks_by_mechanism;
  record_floe_margins(state, recorder, summary);
  for (int n : state.fracture.breaks_by_mode) summary.breaks += n;
  for (const StepDiagnostics& d : history.diagnostics) {
    summary.held_edge_overloads += static_cast<long>(d.held_edge_overloads);
    summary.sheet_holds += static_cast<long>(d.sheet_holds);
  }
  compute_statistics(scene, history, summary);
  summary.solver = solver_summary(scene, history, summary);
  boundary_summary(history, summary);
  if (problems) summary.problem_files = problems->files();
  if (validation) summary.validation = validation->result(scene).to_json();
  // the whole run's, over every process that made it (up to the checkpoint each was resumed from)
  summary.wall_time_s = history.earlier_wall_s + wall();
  summary.cpu_time_s = history.earlier_cpu_s + process_cpu_time();
  write_statistics(recorder, summary);
  recorder.finish(summary.status, summary.message, summary.wall_time_s);
  // a finished run is never resumed: its checkpoint goes
  if (summary.status == "complete") {
    std::error_code ignored;
    std::filesystem::remove(checkpoint_path(options.output), ignored);
  }
  return summary;
}

}  // namespace icedem
