// Scenes `icedem check` refuses because they cannot run as built (a hull that meets no ice or goes
// through the tank's side), and settings it warns about because
// they cannot be meant (dem/input/setting_warnings.hpp): each named with its key.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dem/core/errors.hpp"
#include "dem/input/scene_builder.hpp"
#include "dem/input/setting_warnings.hpp"
#include "dem/step/initial_state.hpp"
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
  EXPECT_EQ(refusal({"structure.start_z=2.2", "channel.width=6.0"}), "") << "the deck's rim, 0.736 m, is inside";
  EXPECT_NE(refusal({"structure.start_z=2.3", "channel.width=6.0"}).find("widest part (radius 0.736 m)"),
            std::string::npos)
      << "in the ice the hull is inside, its deck's rim is not";
}

TEST(SceneChecks, AHullWiderThanTheTankIsRefused) {
  // a deck rim of 3.5 m radius above the ice: the 6 m tank's walls stand above the water too
  const std::string e = refusal({"structure.profile=[[-0.443, 0.171], [0.0, 0.614], [0.3, 3.5]]"});
  EXPECT_NE(e.find("widest part (radius 3.500 m)"), std::string::npos) << e;
  EXPECT_NE(e.find("does not fit in the tank"), std::string::npos) << e;
  EXPECT_EQ(refusal({"structure.profile=[[-0.443, 0.171], [0.0, 0.614], [0.3, 2.9]]"}), "") << "2.9 m < 3 m: it fits";
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

// the warning of the scene's floes (layout_warnings) that contains `needle`, "" if none does
std::string layout_warning(const std::vector<std::string>& sets, const std::string& needle) {
  const Scene scene = load_scene(kTow, sets);
  for (const std::string& w : layout_warnings(scene, scene_layout(scene)))
    if (w.find(needle) != std::string::npos) return w;
  return "";
}

// the short tow: the cone (0.616 m in radius at the ice) from x = 5 m at 0.07 m/s, floes from x = 6 m
TEST(LayoutWarnings, AStructureThatMeetsNoIceWithinTheRun) {
  EXPECT_EQ(layout_warning({}, "meets no ice"), "");
  EXPECT_EQ(layout_warning({}, "does not reach the ice"), "");
  const std::string still = layout_warning({"structure.speed=0"}, "records no ice load");
  EXPECT_NE(still.find("structure.speed = 0"), std::string::npos) << still;
  // from x = -50 m it needs (6.00 - 0.616 + 50) / 0.07 = 791 s to reach the first floe (x = 6.001 m)
  const std::string far = layout_warning({"structure.start_x=-50"}, "does not reach the ice");
  EXPECT_NE(far.find("at t = 791"), std::string::npos) << far;
  EXPECT_EQ(layout_warning({"structure.start_x=-50", "time.duration=800"}, "does not reach the ice"), "");
  EXPECT_NE(layout_warning({"structure.start_x=30"}, "starts past every floe"), "");
}

TEST(LayoutWarnings, BreakableFloesNoWiderThanAnElement) {
  EXPECT_EQ(layout_warning({"fracture.mode=on", "fracture.element_size=0.15"}, "fracture.element_size"), "")
      << "0.3 m floes of 0.15 m elements: the paper's";
  const std::string one = layout_warning({"fracture.mode=on", "fracture.element_size=0.3"}, "no wider than");
  EXPECT_NE(one.find("100 breakable floe(s)"), std::string::npos) << one;
  EXPECT_NE(one.find("100 of them a single element"), std::string::npos) << one;
  const std::string hexagons = layout_warning(
      {"fracture.mode=on", "fracture.element_shape=hexagon", "fracture.element_size=0.5"}, "no wider than");
  EXPECT_NE(hexagons.find("parts of cells"), std::string::npos) << hexagons;
}

TEST(LayoutWarnings, AConcentrationAWholeNumberOfFloesCannotMake) {
  // four 1 m floes (sides 1 +- 0.1 m) in 2 m x 2.1 m: 92 % where 90 % was asked
  const std::string w = layout_warning(
      {"ice.floe_size=1", "channel.length=2", "channel.width=2.1", "ice.concentration=0.9", "layout.size_spread=0.1"},
      "ice.concentration = 0.9 asked");
  EXPECT_NE(w.find("4 floes"), std::string::npos) << w;
  EXPECT_EQ(layout_warning({}, "asked"), "") << "the short tow's 100 floes make its 75 % exactly";
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
