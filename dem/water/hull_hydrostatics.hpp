// The hydrostatics of an axisymmetric hull floating upright (the structure's profile of stations,
// structure.profile), for a moored structure that floats: its displaced volume and centre of buoyancy,
// its waterplane's area and second moment, and the restoring stiffnesses they give,
//   C33 = rho g A_wp (heave),  C44 = C55 = rho g V GM, GM = KB + BM - KG, BM = I_wp / V (roll, pitch),
// the small-angle linearisation of a floating body's hydrostatics (e.g. Faltinsen, "Sea Loads on Ships
// and Offshore Structures", 1990, ch. 2). The hull between two stations is a frustum.
#pragma once

#include <vector>

#include "dem/input/scene.hpp"

namespace icedem {

struct HullHydrostatics {
  double volume = 0;              // m^3, below the waterline
  double buoyancy_centre_y = 0;   // m, height of the centre of buoyancy (tank frame, the stations' y)
  double waterplane_area = 0;     // m^2, the hull's section at the waterline
  double waterplane_inertia = 0;  // m^4, its second moment about a diameter, pi r^4 / 4
  double metacentric_radius = 0;  // m, BM = I_wp / V
};

/// The hull's hydrostatics floating upright with the water at height `waterline_y` (0: the stations'
/// still-water line). Throws std::invalid_argument if the waterline is below the keel or above the deck.
HullHydrostatics hull_hydrostatics(const std::vector<ProfileStation>& profile, double waterline_y = 0);

/// C33, N/m: heave's restoring stiffness, rho g A_wp.
double heave_stiffness(const HullHydrostatics& h, double water_density, double gravity);

/// C44 = C55, N m/rad: roll's and pitch's, rho g V GM, for a centre of gravity at height `gravity_centre_y`.
double tilt_stiffness(const HullHydrostatics& h, double gravity_centre_y, double water_density, double gravity);

}  // namespace icedem
