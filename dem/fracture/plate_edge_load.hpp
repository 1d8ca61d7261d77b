// A semi-infinite floating plate loaded at its straight edge: where and at what load the intact level
// sheet cracks first under a structure's load (docs/model/breakage.md, "The edge and the wedges of level ice").
//
// A Kirchhoff plate on a Winkler foundation (the water, rho_w g per unit area) in x >= 0, its edge x = 0 free,
// loaded at the edge by P spread uniformly over |y| < a:
//   D (d^4/dx^4 + 2 d^4/dx^2dy^2 + d^4/dy^4) w + rho_w g w = 0,   D = E h^3 / (12 (1 - nu^2)),
//   at x = 0: M_x = 0 and the Kirchhoff shear V_x = the edge load.
// Solved by a Fourier transform along the edge: for each wavenumber k the plate's two decaying modes
// exp(-lambda x), lambda^2 = k^2 +- i / l^2, meet the two edge conditions, and the moments are the inverse
// transform's integrals over k (Gauss-Kronrod, panel by panel until the load's spectrum has died out). The
// sheet cracks first radially under the load, where the bottom's tension from M_y is largest (M_y =
// (1 - nu^2) D k^2 W at the free edge), at P_r = sigma_b h^2 / (6 m_y(a/l)); a circumferential crack would
// need P_c = sigma_b h^2 / (6 m_x), m_x the largest |M_x| / P along the axis (at about 0.8 l), the wedges'
// case once radial cracks have formed (wedge_bending.hpp).
#pragma once

namespace icedem {

/// The plate's response to a unit edge load spread over |y| < a, in units of the characteristic length
/// l = (D / (rho_w g))^(1/4).
struct PlateEdgeResponse {
  double deflection = 0;              // w D / (P l^2) at the load's centre
  double radial_moment = 0;           // m_y = M_y / P there (N m/m per N)
  double circumferential_moment = 0;  // m_x = the largest |M_x| / P along the axis
  double circumferential_distance = 0;  // its distance from the edge over l
};

/// The response to a load spread over a / l = `patch` (0: a point load, whose deflection is finite but whose
/// radial moment is not: it is returned as infinity) of a plate of Poisson ratio `poisson`. Throws
/// std::invalid_argument for a patch below 0 or a Poisson ratio outside [0, 0.5).
PlateEdgeResponse plate_edge_response(double patch, double poisson);

/// The loads at which the plate cracks first radially (under the load) and, were it to stay intact, across the
/// axis, for a load spread over |y| < `half_width` (m) at the edge of ice of thickness h (m), modulus E (Pa),
/// Poisson ratio nu, bending strength sigma_b (Pa) on water of density rho_w (kg/m^3) under gravity g (m/s^2).
struct PlateEdgeBreak {
  double radial_load = 0;            // N, P_r
  double circumferential_load = 0;   // N, P_c
  double circumferential_distance = 0;  // m, where the circumferential crack would be
};
PlateEdgeBreak plate_edge_breaking_load(double half_width, double thickness, double elastic_modulus,
                                        double poisson_ratio, double bending_strength, double water_density,
                                        double gravity);

}  // namespace icedem
