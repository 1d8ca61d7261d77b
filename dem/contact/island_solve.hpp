// The island solve: what a run does with one island's contact problem, whatever the
// method. The Bullet adapter (dem/world/contact_solver.hpp) reads the problem off
// Bullet's rows and writes the answer back; the contact-problem benchmark
// (bench/contact/contact_problems.cpp) calls the same solve on problem files.
//
// The policy, in order (docs/model/contact_problems.md says why each stage is there):
//  1. solver.method solves the island to its merit: solver.merit_tolerance, or the smaller
//     solver.joint_merit_tolerance where it has joint rows (a joint's load is its elements'
//     relative velocity over its compliance: the contacts' error reaches the failure ratios
//     magnified) and solver.structure_merit_tolerance where it touches the structure (the
//     load is read off its impulses, which a loose solve leaves low along force chains);
//  2. an island left at solver.method_iterations above its merit goes on with
//     solver.handover_method from that answer (solver.handover_iterations), or with Newton
//     where it has crushing contacts that method does not take;
//  3. an island whose answer puts a joint's failure ratio within 1 - solver.breaking_ratio
//     of 1 is solved on from its answer, first to solver.breaking_check_tolerance (where it
//     stops if every ratio is then clear of 1 by solver.breaking_check_band), else to
//     solver.breaking_merit_tolerance, the finishing method taking what the first leaves;
// a later stage's answer replaces the one it started from only if it refines it
// (dem/contact/refinement.hpp). The counters of what happened go to the step's report.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "dem/contact/method.hpp"
#include "dem/contact/problem.hpp"
#include "dem/contact/solver_settings.hpp"
#include "dem/core/diagnostics.hpp"

namespace icedem {

/// What the contact solve did during one time step (all islands, all substeps).
struct SolverReport {
  int iterations = 0;    // most sweeps or method iterations any island used
  double residual = 0;   // largest residual (sweeps) or merit (methods) an island ended with
  bool capped = false;   // an island reached the cap above its tolerance
  int islands = 0;       // solve groups with contacts
  // the counts of what the island solve did: the diagnostics' columns of Reduction::kCount
  // (dem/core/diagnostics.hpp says each one's meaning), copied into the step's diagnostics
  StepDiagnostics counts;

  void clear() { *this = SolverReport{}; }
  /// One island solved: its iterations, the residual it ended with, whether the cap stopped it.
  void add_island(int island_iterations, double island_residual, bool island_capped) {
    iterations = std::max(iterations, island_iterations);
    residual = std::max(residual, island_residual);
    capped = capped || island_capped;
    ++islands;
  }
};

class IslandSolve {
 public:
  /// The failure ratio (load over capacity) nearest to 1 that the joints of an island reach with
  /// its joint rows' impulses `l` (the fracture stage's measure, dem/fracture/fracture.hpp).
  using JointRatio = std::function<double(const ContactProblem& problem, const Eigen::VectorXd& l)>;

  explicit IslandSolve(const SolverSettings& settings);

  /// Whether islands are solved here: false for solver.method = "pgs", Bullet's sweeps, which
  /// the adapter runs on its rows itself.
  bool solves() const { return method_ != nullptr; }

  /// What decides whether an island is solved again to breaking_merit_tolerance (empty: never).
  void set_joint_ratio(JointRatio ratio) { joint_ratio_ = std::move(ratio); }

  /// The island's answer by the policy above, from the problem's warm start; `report` counts it.
  SolverAnswer solve(const ContactProblem& problem, SolverReport& report);

  /// The merit `problem` is solved to (stage 1).
  double tolerance(const ContactProblem& problem) const;

 private:
  // the second-order method that goes on with `problem` left at the cap and finishes its breaking solves: the
  // hand-over method, or Newton where the problem has crushing contacts the hand-over method does not take (the
  // registry's takes_crushing); null where none can (a rigid joint row, which they cannot fold into the mass
  // matrix) or where it would be the method itself
  ContactMethod* finisher(const ContactProblem& problem) const;

  SolverSettings settings_;
  JointRatio joint_ratio_;
  MeritKind merit_;                           // settings_.merit
  std::string finishing_method_;              // handover_'s: settings_.handover_method, or Newton with "none"
  std::unique_ptr<ContactMethod> method_;     // null: the sweeps
  std::unique_ptr<ContactMethod> handover_;   // goes on with what the method left at its cap; finishes breaking solves
  std::unique_ptr<ContactMethod> crushing_finisher_;  // Newton, for crushing islands handover_ does not take
  // the finishing method's iterations in a breaking solve: Newton needed at most 485 of its steps
  // to 3e-6 on the lattices' breaking steps, the interior-point method 26-571 on a level sheet's
  static constexpr int kBreakingFinishIterations = 1000;
};

}  // namespace icedem
