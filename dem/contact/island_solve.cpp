#include "dem/contact/island_solve.hpp"

#include <cmath>
#include <utility>

#include "dem/contact/refinement.hpp"
#include "dem/contact/registry.hpp"

namespace icedem {

IslandSolve::IslandSolve(const SolverSettings& settings)
    : settings_(settings),
      merit_(merit_kind(settings.merit)),
      // the Newton method finishes the breaking solves when nothing is handed over
      finishing_method_(settings.handover_method == "none" ? "newton" : settings.handover_method) {
  if (settings_.method != kBulletSweeps) {
    method_ = make_contact_method(settings_.method);
    handover_ = make_contact_method(finishing_method_);
    // an island with crushing contacts goes on with Newton where the hand-over method does not take them (the
    // default, the interior-point method): left at the cap, the crushing islands of the analytic level tow
    // stopped there unconverged (3.5 % of a tow's window steps), where Newton finished them
    if (!takes_crushing(finishing_method_) && takes_crushing("newton"))
      crushing_finisher_ = make_contact_method("newton");
  }
}

ContactMethod* IslandSolve::finisher(const ContactProblem& problem) const {
  const bool soft = std::all_of(problem.joints.begin(), problem.joints.end(),
                                [](const ProblemJointRow& j) { return j.compliance > 0; });
  if (!soft) return nullptr;
  if (has_crushing(problem) && !takes_crushing(finishing_method_))
    return settings_.method != "newton" ? crushing_finisher_.get() : nullptr;
  return settings_.method != finishing_method_ ? handover_.get() : nullptr;
}

double IslandSolve::tolerance(const ContactProblem& problem) const {
  double tolerance = settings_.merit_tolerance;
  if (!problem.joints.empty()) tolerance = std::min(tolerance, settings_.joint_merit_tolerance);
  if (touches_structure(problem)) tolerance = std::min(tolerance, settings_.structure_merit_tolerance);
  return tolerance;
}

SolverAnswer IslandSolve::solve(const ContactProblem& problem, SolverReport& report) {
  MethodOptions options;
  options.tolerance = tolerance(problem);
  options.max_iterations = settings_.method_iterations;
  options.merit = merit_;
  options.warm_start = true;  // from the rows' warm start (solver.warm_start of the last step's)
  SolverAnswer answer = method_->solve(problem, options);
  // the gradient method's count of steps grows with the island's stiffness (a lattice's
  // joints, a level sheet's above all), the interior-point method's hardly: an island left at
  // the cap goes on from that answer (docs/model/contact_problems.md, "The interior-point method")
  // (which method goes on is asked only there: it reads every joint row and contact of the island)
  ContactMethod* finishing = nullptr;
  if (settings_.handover_method != "none" && answer.residual > options.tolerance &&
      answer.sweeps >= options.max_iterations && (finishing = finisher(problem))) {
    MethodOptions more = options;
    more.max_iterations = settings_.handover_iterations;
    SolverAnswer next = finishing->solve(started_from(problem, answer), more);
    next.sweeps += answer.sweeps;
    const double floor = weight_impulse(problem);
    if (refines(answer, next, floor))
      answer = std::move(next);
    else
      report.counts.runaways += runs_off(answer, next, floor);
    answer.capped = answer.residual > options.tolerance;
    ++report.counts.handovers;
  }
  // A joint breaks when its load reaches its capacity, and at the joints' merit its load is
  // uncertain by a few per cent of the capacity (docs/model/contact_problems.md, "What the
  // merit leaves in the joints' loads"): an island whose answer puts a joint's failure ratio
  // that near 1 is solved on, from that answer, until the break is decided on a tight answer
  if (joint_ratio_ && !problem.joints.empty() && settings_.breaking_merit_tolerance < options.tolerance &&
      std::abs(joint_ratio_(problem, answer.l) - 1) <= 1 - settings_.breaking_ratio) {
    const double tolerance = options.tolerance;
    // each stage starts from the best answer so far (a copy: the observer sees the run's own warm start)
    options.max_iterations = settings_.breaking_iterations;
    const double floor = weight_impulse(problem);
    const auto keep_better = [&report, &answer, floor](SolverAnswer next) {
      if (refines(answer, next, floor)) {
        next.sweeps += answer.sweeps;
        answer = std::move(next);
      } else {
        report.counts.runaways += runs_off(answer, next, floor);
        answer.sweeps += next.sweeps;
      }
    };
    // first to the check's merit: where every joint's ratio is then clear of 1 by the band, each
    // break is decided (at 1e-5 the loads were within 2 % of the bending capacity on the
    // lattices' breaking steps) and the solve stops there; a level sheet's crack front holds
    // joints near capacity most steps, and the tight merit cost it 11,000 gradient steps each
    const double check = settings_.breaking_check_tolerance;
    bool decided = false;
    if (check > settings_.breaking_merit_tolerance && check < tolerance) {
      options.tolerance = check;
      keep_better(method_->solve(started_from(problem, answer), options));
      decided = answer.residual <= check &&
                std::abs(joint_ratio_(problem, answer.l) - 1) > settings_.breaking_check_band;
    }
    if (!decided) {
      options.tolerance = settings_.breaking_merit_tolerance;
      keep_better(method_->solve(started_from(problem, answer), options));
      // the gradient method's tail can be long where a second-order method's is not (on the
      // lattices' breaking steps one island in 17 stayed at 2e-5 after 20,000 gradient steps,
      // where Newton reached 3e-6 in 327 of its steps): what the first method leaves above the
      // tolerance, the hand-over method (else Newton) finishes from its best answer
      if (answer.residual > settings_.breaking_merit_tolerance && (finishing = finisher(problem))) {
        options.max_iterations = kBreakingFinishIterations;
        keep_better(finishing->solve(started_from(problem, answer), options));
      }
    }
    answer.capped = answer.residual > tolerance;  // the step's own tolerance: a tighter one is extra
    ++report.counts.breaking_solves;
    report.counts.breaking_decided += decided;
    report.counts.breaking_capped += !decided && answer.residual > settings_.breaking_merit_tolerance;
  }
  report.add_island(answer.sweeps, answer.residual, answer.capped);
  return answer;
}

}  // namespace icedem
