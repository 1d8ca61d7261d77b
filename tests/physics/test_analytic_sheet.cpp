// Level ice cut by closed forms (ice.cover = "level", fracture.mode = "analytic": dem/fracture/analytic_sheet.hpp),
// in the world: the sheet built as fixed prisms that tile it, its crushing load on the structure through the load
// cell, and its breaks, which keep the ice (the sheet before = the sheet after + the pieces + the crushed ice)
// and make floes clear of the hull.
//
// The scene: a 3 m x 1.2 m sheet of the paper's ice, the paper's cone towed into it at the paper's 0.07 m/s from 0.09 m short
// of its edge, still water.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/fracture/analytic_sheet.hpp"
#include "dem/fracture/sheet_breaking.hpp"
#include "dem/layout/polygon_set.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

namespace {

Scene sheet_scene() {
  return scene_from("", {"ice.cover=\"level\"", "fracture.mode=\"analytic\"", "channel.start_x=1.0", "channel.length=3.0",
                         "channel.width=1.2", "structure.start_x=0.3", "structure.speed=0.07", "flow.model=\"still\""});
}

State start(const Scene& scene) { return initial_state(scene, scene_layout(scene).floes); }

double total_area(const std::vector<Polygon>& parts) {
  double a = 0;
  for (const Polygon& p : parts) a += area(p);
  return a;
}

}  // namespace

// The build: the layout's one floe is the sheet, no floe of the world; its fixed prisms are convex and tile it
// (their areas sum to its area to round-off)
TEST(AnalyticSheet, TheSheetIsBuiltAsFixedPrisms) {
  const Scene scene = sheet_scene();
  const State state = start(scene);
  ASSERT_TRUE(state.sheet);
  EXPECT_TRUE(state.world->floes().empty());
  const double sheet = area(state.sheet->outline());
  EXPECT_NEAR(sheet, 3.0 * (1.2 - 2 * scene.layout.min_gap), 1e-12);
  const std::vector<Polygon> prisms = state.sheet->prisms();
  EXPECT_EQ(prisms.size(), 3u * 2u) << "1 m squares over 3 m x 1.2 m";
  for (const Polygon& p : prisms) EXPECT_TRUE(is_convex(p));
  EXPECT_NEAR(total_area(prisms), sheet, 1e-12 * sheet);
}

// Before the first break the only load on the structure is the crushed zones': the load cell's force is theirs
// on the hull, to round-off (one Bullet step a time step)
TEST(AnalyticSheet, TheCrushingLoadIsTheStructures) {
  const Scene scene = sheet_scene();
  State state = start(scene);
  const CrushingLaw law{scene.ice.compressive_strength, scene.contact.pressure_area_exponent,
                        scene.ice.thickness * scene.ice.thickness};
  int loaded = 0;
  while (state.sheet->breaks().empty() && state.time < 3.0) {
    step(scene, state);
    if (!state.sheet->breaks().empty()) break;
    const HullInIce hull = hull_in_ice(scene, state.structure_position);
    Eigen::Vector3d on_hull = Eigen::Vector3d::Zero();
    for (const SheetContact& c : sheet_contacts(state.sheet->outline(), hull, law, scene.friction.ice_structure))
      on_hull -= c.force_on_ice(hull);
    EXPECT_NEAR((state.load.force - on_hull).norm(), 0.0, 1e-9 * (1 + on_hull.norm())) << "t " << state.time;
    loaded += on_hull.norm() > 0;
  }
  EXPECT_GE(loaded, 2) << "the cone crushed the edge for more than a step before it broke";
  EXPECT_FALSE(state.sheet->breaks().empty()) << "the edge broke";
}

// Over 5 s of tow (the cone 0.26 m into the sheet): breaks, each at or above its closed-form load; the ice kept
// to round-off (the sheet's area lost is what broke off, which is the pieces' floes and the crushed ice); the
// pieces floes in the world, clear of the hull: a floe born inside it would show the depth crushed, a centimetre
// or more; a contact sits within Bullet's margin (1 mm) and a step's approach (1.4 mm at 0.07 m/s), so 3 mm
TEST(AnalyticSheet, BreaksKeepTheIce) {
  const Scene scene = sheet_scene();
  State state = start(scene);
  const double before = area(state.sheet->outline());
  double deepest = 0;
  while (state.time < 5.0) {
    step(scene, state);
    deepest = std::max(deepest, state.diagnostics.max_cone_penetration);
  }
  const std::vector<SheetBreakRecord>& breaks = state.sheet->breaks();
  ASSERT_GE(breaks.size(), 3u);
  double broken = 0, crushed = 0;
  for (const SheetBreakRecord& b : breaks) {
    EXPECT_GE(b.load, b.breaking_load) << "t " << b.time;
    EXPECT_GT(b.pieces, 0) << "t " << b.time;
    broken += b.broken_area;
    crushed += b.crushed_area;
  }
  EXPECT_NEAR(area(state.sheet->outline()) + broken, before, 1e-9 * before);
  EXPECT_NEAR(total_area(state.sheet->prisms()), area(state.sheet->outline()), 1e-9 * before);
  double pieces = 0;
  for (const FloeBody& f : state.world->floes()) pieces += area(f.shape->outline);
  EXPECT_NEAR(pieces + crushed, broken, 1e-9 * before);
  EXPECT_LT(crushed, 0.2 * broken) << "most of the broken ice is pieces";
  EXPECT_LT(deepest, 3e-3);
}

// A sheet whose front is a neck 5 cm deep before a slot that runs from its back (the neck 0.16 m wide across the
// load), every edge but the front held: a cut at the front takes the neck whole (its wedges' chords reach 0.16 m
// either side of the axis 5 cm in: x* is 0.148 m or more) and would part the sheet into two held halves, so it is
// not made. The sheet holds every zone at its breaking load, and the step counts each one (holds(),
// /diagnostics/sheet_holds): the count equals the zones at or over their closed-form load found here afresh from
// the outline and the hull, over 50 such steps of the cone crushing on into the neck (the world's own sheet lies
// clear of it, 10 m away)
TEST(AnalyticSheet, ACutThatWouldPartTheHeldSheetIsHeldAndCounted) {
  const Scene scene = sheet_scene();
  State state = start(scene);
  const Polygon slotted = make_ccw({{13.0, -1.5}, {14.0, -1.5}, {14.0, -0.08}, {13.05, -0.08}, {13.05, 0.08},
                                    {14.0, 0.08}, {14.0, 1.5}, {13.0, 1.5}});
  Scene here = scene;
  here.structure.start_x = 12.3;  // the front, x = 13 m, is the edge the structure comes in from
  AnalyticSheet sheet(here, *state.world, slotted, 1000);
  const double before = area(sheet.outline());
  const CrushingLaw law{scene.ice.compressive_strength, scene.contact.pressure_area_exponent,
                        scene.ice.thickness * scene.ice.thickness};
  const SheetIce ice = sheet_ice(scene);
  const double h = scene.time.dt;
  int held_steps = 0;
  for (int k = 1; k <= 200 && held_steps < 50; ++k) {
    const Eigen::Vector3d structure(12.3 + scene.structure.speed * h * k, state.structure_position.y(),
                                    state.structure_position.z());
    sheet.step(here, *state.world, structure, k * h, h, state.fracture);
    int over = 0;
    for (const SheetContact& c : sheet_contacts(sheet.outline(), hull_in_ice(here, structure), law,
                                                scene.friction.ice_structure))
      over += c.bending_force >= plan_sheet_break(sheet.outline(), c, ice).breaking_load;
    EXPECT_EQ(sheet.holds(), over) << "step " << k;
    held_steps += over > 0;
  }
  EXPECT_EQ(held_steps, 50) << "the cone's zone reached its breaking load";
  EXPECT_TRUE(sheet.breaks().empty()) << "the held sheet was never parted";
  EXPECT_EQ(area(sheet.outline()), before);
}
