// One break of the analytic level sheet (dem/fracture/analytic_sheet.hpp) as plain data: a row of the output's
// /sheet/breaks (dem/output/schema.cpp declares its fields) and what a checkpoint keeps to cut the sheet again
// the same way (the cut is made from the load's centre, axis and patch, the plan and, for a hull's zone, the hull).
#pragma once

#include <cstdint>

namespace icedem {

struct SheetBreakRecord {
  double time = 0;                // s
  int32_t by_floe = 0;            // 1: a floe's push on the edge (sheet_floe_load.hpp); 0: the hull's crushed zone
  int32_t crack = 0;              // how the edge broke: a SheetCrack (sheet_breaking.hpp)
  int32_t pieces = 0;             // floes made
  int32_t splits_before = 0;      // floes' splits (World::splits()) before it: a checkpoint replays both in order
  double x = 0, z = 0;            // m, the load's centre (tank frame)
  double axis_x = 1, axis_z = 0;  // the load's direction into the sheet, the wedges' axis (unit)
  double half_width = 0;          // m, the load's patch a
  double load = 0;                // N, normal to the sheet
  double breaking_load = 0;       // N, the closed form's
  double opening_angle = 0;       // rad, theta
  double crack_distance = 0;      // m, x*
  double hull_x = 0, hull_z = 0;  // m, a hull's zone: the hull's axis ...
  double hull_radius = 0;         // m, ... and its larger radius in the ice (the crushed ice short of it is cut away)
  double broken_area = 0;         // m^2, ice that left the sheet
  double crushed_area = 0;        // m^2, of it, crushed (in the hull's section, or in pieces too small)
};

}  // namespace icedem
