#include "dem/step/step.hpp"

#include <chrono>

#include "dem/activation/activation.hpp"
#include "dem/activation/left_behind.hpp"
#include "dem/activation/reach.hpp"
#include "dem/fracture/fracture.hpp"
#include "dem/fracture/fracture_split.hpp"
#include "dem/fracture/lattice_region.hpp"
#include "dem/fracture/level_ice.hpp"
#include "dem/step/health_check.hpp"
#include "dem/water/water_forces.hpp"
#include "dem/world/boundary_load.hpp"
#include "dem/world/load_cell.hpp"

namespace icedem {
namespace {

// adds the wall time of its scope to a StageTimes field (MuJoCo's TM_START/TM_END)
class StageTimer {
 public:
  explicit StageTimer(double& total) : total_(total), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

// the kinematic structure reaches its place at t + h at the end of the coming Bullet step, and the
// flow model follows it: towed, the carriage's prescribed motion; moored, a step of its own motion
// under the ice's impulses of the step before, the water and its mooring (dem/mooring/structure_motion.hpp)
void move_structure(const Scene& scene, State& state, double t_next, double h) {
  if (scene.structure.motion == StructureMotion::kTowed) {
    state.structure_position = structure_position_at(scene, t_next);
    state.structure_velocity = Eigen::Vector3d(scene.structure.speed, 0.0, 0.0);
    state.world->set_structure_target(state.structure_position);
  } else {
    StructureMotionState& m = state.structure_motion;
    advance_structure(scene, *state.floating, h, scene.structure.speed * (t_next - h), state.structure_position, m);
    const Eigen::Matrix3d r = rotation_matrix(m);
    // the reference point's velocity: G's and the turn about G
    state.structure_velocity = m.velocity + m.angular_velocity.cross(-r * Eigen::Vector3d(0, state.floating->gravity_centre_y, 0));
    state.world->set_structure_target(state.structure_position, r);
  }
  state.flow->set_structure(state.structure_position, state.structure_velocity);
}

}  // namespace

// buoyancy, drag and damping on awake floes (sleeping ones are at rest and get
// neither gravity nor water forces from Bullet's integration, so forces on them
// are wasted work; activation.skip_asleep = false does it anyway, to measure that)
void apply_water_forces(const Scene& scene, State& state) {
  WaterParams water = water_params(scene.water);
  // exchanged drag replaces the DEM's own (dem/water/drag_exchange.hpp)
  if (state.drag_exchange) water.drag_coefficient = water.skin_friction_coefficient = 0.0;
  std::vector<FloeBody*> bodies;  // the floes that get them
  if (scene.activation.skip_asleep) {
    for (int i : state.world->awake_floe_indices()) bodies.push_back(&state.world->floes()[i]);
  } else {
    for (FloeBody& floe : state.world->floes())
      if (liveness(*floe.body) != Liveness::kOutside) bodies.push_back(&floe);
  }
  for (FloeBody* f : bodies) {
    FloeBody& floe = *f;
    btRigidBody& body = *floe.body;
    const Liveness life = liveness(body);
    BodyMotion motion{body_pose(body), to_eigen(body.getLinearVelocity()), to_eigen(body.getAngularVelocity())};
    const Wrench w = water_wrench(floe.shape->prism, motion, *state.flow, water, floe.shape->damping);
    body.applyCentralForce(btVector3(w.force.x(), w.force.y(), w.force.z()));
    body.applyTorque(btVector3(w.torque.x(), w.torque.y(), w.torque.z()));
    if (state.drag_exchange) {
      const Eigen::Vector3d d = state.drag_exchange->drag(static_cast<int>(&floe - state.world->floes().data()));
      body.applyCentralForce(btVector3(d.x(), d.y(), d.z()));
    }
    // Bullet adds gravity to awake bodies only, but a sleeping body touching an
    // awake one enters the contact solve with its applied forces: without its
    // weight the buoyancy alone would lift it there
    if (life == Liveness::kAsleep && body.getInvMass() > 0) body.applyCentralForce(body.getGravity() / body.getInvMass());
  }
}

namespace {

// +1 when the structure travels along +x, -1 along -x
double travel(const Scene& scene) { return scene.structure.speed < 0 ? -1.0 : 1.0; }

// contact impulses on the structure of the Bullet step just taken, and what the fixed
// boundaries take off it
void read_load_cell(const Scene& scene, State& state, LoadCell& cell, BoundaryLoad& boundary) {
  const btDispatcher& dispatcher = *state.world->dynamics().getDispatcher();
  const auto [impulse, angular] = cell.accumulate(dispatcher, state.world->structure(), state.structure_position);
  state.structure_motion.ice_impulse = impulse;  // drives a moored structure's next step
  state.structure_motion.ice_angular_impulse = angular;
  boundary.accumulate(dispatcher, state.world->structure(), travel(scene));
}

// the boundary load of the step and whether the pack is locked against a boundary
void record_boundary_load(const Scene& scene, double boundary_load, const LoadReading& load, StepDiagnostics& d) {
  const double surge = -load.force.x() * travel(scene);  // resisting the travel
  d.boundary_load = boundary_load;
  d.locked = locked(boundary_load, surge) ? 1.0 : 0.0;
}

// what the contact solver did this step, for /diagnostics and the summary
void record_solver_report(const SolverReport& report, StepDiagnostics& d) {
  d.solver_iterations = report.iterations;
  d.solver_residual = report.residual;
  d.solver_capped = report.capped ? 1.0 : 0.0;
  for (const DiagnosticColumn& c : kDiagnosticColumns)
    if (c.reduction == Reduction::kCount) d.*c.field = report.counts.*c.field;
}

}  // namespace

Eigen::Vector3d structure_position_at(const Scene& scene, double t) {
  return {scene.structure.start_x + scene.structure.speed * t, 0.0, scene.structure.start_z};
}

void step(const Scene& scene, State& state, const PointLoads* loads) {
  const double h = scene.time.dt / scene.time.substeps;
  const double t0 = state.time;
  StageTimes& times = state.stage_times;
  state.fracture.events.clear();
  {
    StageTimer t(times.activation);
    // the lattices the structure reaches first: their elements wake, and reach the floes
    // around them before this step's collision detection, as any awake body does; so does
    // the level sheet near it
    update_level_sheet(scene, state.structure_position, *state.world);
    update_lattice_region(scene, state.structure_position, *state.world, state.fracture);
    enter_reached_floes(scene, *state.world);
  }
  if (state.drag_exchange) { StageTimer t(times.coupling); state.drag_exchange->update(scene, state); }
  LoadCell cell;
  BoundaryLoad boundary;
  int held_edge_overloads = 0;  // a level sheet's joints at its held edge over their capacity
  int sheet_holds = 0;          // the analytic sheet's zones at their breaking load it held
  state.world->solver_report().clear();
  // the fracture stage's measure of how near a joint is to breaking, for the contact solver's
  // second, tighter solve of such islands (solver.breaking_ratio)
  if (scene.fracture.mode == FractureMode::kOn)
    state.world->contact_solver().set_joint_ratio(
        [&scene, world = state.world.get()](const ContactProblem& p, const Eigen::VectorXd& l) {
          return joint_ratios(scene, *world, p, l).nearest;
        });
  for (int k = 1; k <= scene.time.substeps; ++k) {
    const double t_next = t0 + k * h;
    { StageTimer t(times.structure); move_structure(scene, state, t_next, h); }
    { StageTimer t(times.water); apply_water_forces(scene, state); }
    if (loads) loads->apply(*state.world);
    // Bullet's step of h, stage by stage (dem/world/dynamics_world.hpp)
    DynamicsWorld& bullet = state.world->dynamics();
    { StageTimer t(times.collision); bullet.detect_collisions(h); }
    { StageTimer t(times.islands); bullet.find_islands(); }
    {
      StageTimer t(times.solve);
      state.world->contact_solver().begin_step(state.step, t_next, h);
      bullet.solve_contacts(h);
    }
    { StageTimer t(times.integrate); bullet.integrate(h); }
    { StageTimer t(times.load_cell); read_load_cell(scene, state, cell, boundary); }
    state.time = t_next;
    {
      StageTimer t(times.fracture);
      if (state.sheet) {  // the analytic level sheet: its crushing load on the structure, its breaks
        const auto [impulse, angular] =
            state.sheet->step(scene, *state.world, state.structure_position, state.time, h, state.fracture);
        cell.add(impulse, angular);
        state.structure_motion.ice_impulse += impulse;
        state.structure_motion.ice_angular_impulse += angular;
        sheet_holds += state.sheet->holds();
      }
      held_edge_overloads += check_fracture(scene, *state.world, state.time, state.structure_position, h, state.fracture);
      if (floes_split(scene))
        check_splits(scene, *state.world, state.time, state.structure_position, h, state.fracture);
    }
  }
  state.load = cell.finish(scene.time.dt);
  const double boundary_load = boundary.finish(scene.time.dt);
  {
    StageTimer t(times.activation);
    update_activation(scene, state.structure_position, *state.world);
    leave_behind(scene, state.structure_position, *state.world);
  }
  state.awake_floes = state.world->awake_floes();
  state.contact_points = state.world->contact_points();
  if (!state.first_contact_time && state.load.contacts > 0) state.first_contact_time = state.time;
  ++state.step;
  { StageTimer t(times.health); state.diagnostics = check_health(scene, state); }
  record_solver_report(state.world->solver_report(), state.diagnostics);
  record_boundary_load(scene, boundary_load, state.load, state.diagnostics);
  state.diagnostics.held_edge_overloads = held_edge_overloads;
  state.diagnostics.sheet_holds = sheet_holds;
}

void advance(const Scene& scene, State& state, StepCase* attached) {
  step(scene, state, attached ? &attached->loads() : nullptr);
  if (attached) attached->after_step(scene, state);
}

}  // namespace icedem
