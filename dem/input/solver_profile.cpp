#include "dem/input/solver_profile.hpp"

#include "dem/input/scene_builder.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace icedem {
namespace {

using Settings = std::vector<std::pair<std::string, KeyValue>>;

// Each profile lists the keys it sets to other values than their defaults.
// "paper": the seed paper's numerics, 10 PGS sweeps a step (its Table 3), on Bullet
// 3.24's solver as it comes (warm start 0.85, friction from zero, its row order), with
// no early stop, no checkpoints: results of this profile are those of icedem before the
// convergence work, bit for bit.
// "converged" (the default): the keys' own defaults (dem/input/scenario_keys.cpp), so it sets
// nothing: every island solved whole (contacts with Coulomb's disc, joints as elastic
// springs of the ice) by the accelerated projected gradient to a merit of 1e-3, warm-started
// from the last step. Chosen by the work-precision benchmark on the contact problem library
// (docs/model/contact_problems.md) and checked on full runs (docs/model/convergence.md).
const std::map<std::string, Settings>& profiles() {
  static const std::map<std::string, Settings> table{
      {"paper",
       {{"solver.iterations", KeyValue{std::int64_t{10}}},
        {"solver.position_iterations", KeyValue{std::int64_t{10}}},
        {"solver.tolerance", KeyValue{0.0}},
        {"solver.warm_start", KeyValue{0.85}},
        {"solver.friction_warm_start", KeyValue{false}},
        {"solver.order", KeyValue{std::string("bullet")}},
        {"solver.sor", KeyValue{1.0}},
        {"solver.method", KeyValue{std::string("pgs")}},
        // the paper's joints: Bullet's CFM and ERP (their stiffness depends on the step)
        {"fracture.joint_stiffness", KeyValue{std::string("cfm")}},
        // a world rebuilt from a checkpoint holds Bullet's arrays in another order, and this
        // profile's rows follow that order: checkpoints would move its results
        {"output.checkpoint_interval", KeyValue{0.0}}}},
      {"converged", {}},
  };
  return table;
}

}  // namespace

void apply_solver_profile(Scenario& sc) {
  const std::string& name = std::get<std::string>(sc.keys.at("solver.profile").value);
  for (const auto& [path, value] : profiles().at(name)) {
    ResolvedKey& key = sc.keys.at(path);
    if (key.origin == "default") key = ResolvedKey{value, "solver.profile = \"" + name + "\""};
  }
}

SolverSettings solver_settings(const std::string& profile) {
  const std::string text = "[solver]\nprofile = \"" + profile + "\"\n";
  return make_scene(parse_scenario(text, "solver.profile = \"" + profile + "\"", ".")).solver;
}

}  // namespace icedem
