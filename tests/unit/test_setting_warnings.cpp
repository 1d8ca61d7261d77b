// Scenes `icedem check` refuses because they cannot run as built (a hull that meets no ice or goes
// through the tank's side), and settings it warns about because
// they cannot be meant (dem/input/setting_warnings.hpp): each named with its key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dem/core/errors.hpp"
#include "dem/input/scene_builder.hpp"
#include "dem/input/setting_warnings.hpp"
#include "dem/validation/plate_deflection.hpp"

namespace icedem {
namespace {

const std::string kTow = std::string(ICEDEM_SOURCE_DIR) + "/scenarios/examples/short_tow.toml";

std::string refusal(const std::vector<std::string>& sets, const std::string& path = kTow) {
  try {
    load_scene(path, sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// the warning that contains `needle`, "" if none does
std::string warning(const std::vector<std::string>& sets, const std::string& needle, const std::string& path = kTow) {
  for (const std::string& w : setting_warnings(load_scene(path, sets)))
    if (w.find(needle) != std::string::npos) return w;
  return "";
}

TEST(SceneChecks, AHullThatMeetsNoIceIsRefused) {
  EXPECT_NE(refusal({"structure.profile=[[0.1, 0.2], [0.5, 0.6]]"}).find("pass above the ice"), std::string::npos);
  EXPECT_NE(refusal({"structure.profile=[[-0.6, 0.2], [-0.1, 0.6]]"}).find("pass under the ice"), std::string::npos);
}

TEST(SceneChecks, AHullThroughTheTanksSideIsRefused) {
  // the paper's cone is 0.616 m in radius where it meets the ice; the tank is 6 m wide
  const std::string e = refusal({"structure.start_z=2.5"});
  EXPECT_NE(e.find("structure.start_z = 2.5"), std::string::npos) << e;
  EXPECT_NE(e.find("beyond the tank's side"), std::string::npos) << e;
  EXPECT_EQ(refusal({"structure.start_z=2.3", "channel.width=6.0"}), "") << "0.616 m from the side is inside";
}

TEST(SceneChecks, TheShippedScenariosPass) {
  EXPECT_EQ(refusal({}), "");
  EXPECT_EQ(refusal({}, std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_deflection_27_015.toml"), "")
      << "a validation case parks its structure away from the plate: not checked";
}

TEST(SettingWarnings, TheStructureReachingTheEndWallWithinTheRun) {
  // the short tow's 4 m channel ends at x = 10 m: the rim comes within one ice thickness of it at 60.4 s
  EXPECT_EQ(warning({}, "end wall"), "") << "the 40 s tow stops 20 s short of it";
  const std::string w = warning({"time.duration=70"}, "end wall");
  EXPECT_NE(w.find("at t = 60.4 s"), std::string::npos) << w;
  EXPECT_NE(w.find("stats.include_squeeze"), std::string::npos) << w;
  EXPECT_EQ(warning({"time.duration=70", "channel.end_wall=false"}, "end wall"), "");
}

// a towed structure cannot be there; one standing on the floor can (the flow case's cylinder
// through the whole depth), so it is a warning
TEST(SettingWarnings, AKeelBelowTheTanksBottom) {
  const std::string w = warning({"structure.profile=[[-2.0, 0.2], [0.0, 0.6]]"}, "below the tank's bottom");
  EXPECT_NE(w.find("tank.depth = 1.8 m"), std::string::npos) << w;
  EXPECT_EQ(warning({}, "below the tank's bottom"), "");
}

TEST(SettingWarnings, TheHullThroughTheMotherIceEdges) {
  EXPECT_NE(warning({"structure.start_z=1.0"}, "mother-ice edges"), "") << "1.0 + 0.616 m beyond the 1.5 m half-width";
  EXPECT_EQ(warning({"structure.start_z=0.8"}, "mother-ice edges"), "");
}

TEST(SettingWarnings, UnreachedFloesOutOfTheWorldWhereTheKeyDoesNothing) {
  EXPECT_NE(warning({"activation.sleeping=false"}, "unreached_out_of_world = true does nothing"), "");
  EXPECT_EQ(warning({"activation.sleeping=false", "activation.unreached_out_of_world=false"}, "unreached"), "");
  EXPECT_EQ(warning({}, "unreached"), "") << "the default: it acts";
}

TEST(SettingWarnings, IntervalsShorterThanTheStep) {
  EXPECT_NE(warning({"output.snapshot_interval=0.001"}, "output.snapshot_interval = 0.001 s is shorter"), "");
  EXPECT_NE(warning({"output.checkpoint_interval=0.01"}, "output.checkpoint_interval = 0.01 s is shorter"), "");
  EXPECT_EQ(warning({"output.snapshot_interval=0.02"}, "shorter than the step"), "");
  EXPECT_EQ(warning({"output.snapshot_interval=0"}, "shorter than the step"), "") << "0: none";
}

// 10,000 N on the 2.7 m plate of 0.15 m elements threw the loaded elements about at the first step
// (23 rad/s at t = 0.02 s): its reference deflection, 0.92 m, is far beyond the 3 mm freeboard
TEST(SettingWarnings, APlateLoadThatSinksThePlatesCentre) {
  const std::string plate = std::string(ICEDEM_SOURCE_DIR) + "/scenarios/validation/plate_deflection_27_015.toml";
  EXPECT_EQ(plate_load_warning(load_scene(plate)), "") << "the paper's 10 N: 0.9 mm";
  const std::string w = plate_load_warning(load_scene(plate, {"validation.load=10000"}));
  EXPECT_NE(w.find("beyond its freeboard"), std::string::npos) << w;
}

}  // namespace
}  // namespace icedem
