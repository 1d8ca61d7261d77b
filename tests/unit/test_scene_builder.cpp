// Scenario -> Scene (dem/input/scene_builder.cpp): every allowed name of every choice key reaches
// its own Scene value, and none falls through to a default.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "dem/core/errors.hpp"
#include "dem/input/scenario.hpp"

using namespace icedem;

namespace {

const std::string kScenario = std::string(ICEDEM_SOURCE_DIR) + "/scenarios/examples/short_tow.toml";

// a Scene field that shows which name a choice key took, as text
std::string chosen(const Scene& s, const std::string& key) {
  if (key == "solver.order") return std::to_string(static_cast<int>(s.solver.order));
  if (key == "solver.method") return s.solver.method;
  if (key == "solver.merit") return s.solver.merit;
  if (key == "solver.handover_method") return s.solver.handover_method;
  if (key == "fracture.joint_stiffness") return std::to_string(s.fracture.elastic_joints);
  if (key == "solver.broadphase") return std::to_string(static_cast<int>(s.solver.broadphase));
  if (key == "flow.model") return std::to_string(static_cast<int>(s.flow.model));
  if (key == "coupling.mode") return std::to_string(static_cast<int>(s.coupling.mode));
  if (key == "coupling.mesh") return s.coupling.mesh;
  if (key == "coupling.partner") return std::to_string(s.coupling.spawn_partner);
  if (key == "fracture.mode") return std::to_string(static_cast<int>(s.fracture.mode));
  if (key == "activation.islands") return std::to_string(static_cast<int>(s.activation.islands));
  if (key == "validation.case") return std::to_string(static_cast<int>(s.validation.kind));
  if (key == "validation.plate_load") return std::to_string(static_cast<int>(s.validation.plate_load));
  if (key == "water.buoyancy") return std::to_string(s.water.linear_buoyancy);
  if (key == "fracture.element_shape") return std::to_string(static_cast<int>(s.fracture.element_shape));
  if (key == "fracture.tiling") return std::to_string(static_cast<int>(s.fracture.tiling));
  if (key == "ice.cover") return std::to_string(static_cast<int>(s.ice.cover));
  if (key == "contact.model") return std::to_string(static_cast<int>(s.contact.model));
  if (key == "contact.crushing_contacts") return std::to_string(static_cast<int>(s.contact.crushing_contacts));
  if (key == "structure.motion") return std::to_string(static_cast<int>(s.structure.motion));
  if (key == "mooring.model") return std::to_string(static_cast<int>(s.mooring.model));
  return "";  // a choice key this test does not know: it fails below
}

}  // namespace

TEST(SceneBuilder, EveryChoiceOfEveryChoiceKeyGivesItsOwnSceneValue) {
  int keys = 0;
  for (const KeySpec& spec : scenario_keys()) {
    if (spec.type != KeyType::kChoice || spec.path == "solver.profile") continue;  // the profile sets other keys
    ++keys;
    std::set<std::string> values;
    for (const std::string& name : spec.choices) {
      // what other keys the choice needs (validation cases run on elements)
      std::vector<std::string> sets{spec.path + "=\"" + name + "\"", "fracture.mode=\"on\"", "ice.floe_size=0.6",
                                    "fracture.element_size=0.15", "validation.plate_size=0.6",
                                    "coupling.exchange_dir=\"/tmp\"", "fracture.lattice_radius=1.5"};
      if (spec.path == "fracture.mode") sets = {spec.path + "=\"" + name + "\""};
      // the sheet's edge crushes under the crushing law, on the level sheet cut by closed forms
      if (name == "structure_and_sheet")
        sets = {spec.path + "=\"" + name + "\"", "contact.model=\"crushing\"", "ice.cover=\"level\"",
                "fracture.mode=\"analytic\""};
      try {
        const Scene s = load_scene(kScenario, sets);
        values.insert(chosen(s, spec.path));
        EXPECT_NE(chosen(s, spec.path), "") << spec.path << ": not known to this test";
      } catch (const InputError& e) {
        ADD_FAILURE() << spec.path << " = " << name << " was refused: " << e.what();
      }
    }
    EXPECT_EQ(values.size(), spec.choices.size()) << spec.path << ": two names gave the same Scene value";
  }
  EXPECT_GE(keys, 9);
}
