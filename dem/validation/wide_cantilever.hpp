// The wide cantilever (validation.case = "wide_cantilever"): a lattice's bending strength across
// its grid, in any direction. A plate of validation.beam_length (x) by beam_width (z), cut
// from elements of any shape with the grid turned by fracture.lattice_angle, is held in air
// with the elements within one element size of its x = 0 edge clamped, each free element's
// weight carried (as in the cantilever in air), and a load growing at validation.load_rate
// spread over the elements within one element size of its far edge, in proportion to their
// mass. At the first break the root section carries the moment M = P l (l from the line of
// the joints between clamped and free elements to the load's centre), and the plate's
// bending strength in that direction is sigma = 6 M / (B T^2), B the plate's width: the
// seed paper's eq. 6 with the whole width for one element's. For squares along the grid the
// root line's joints hold B T^2 sigma_b / 6 between them (eq. 3 summed), so sigma is the
// bending strength; a hexagonal grid's root line zig-zags, and sigma / sigma_b is how much of
// the squares' strength it keeps in that direction (docs/model/breakage.md).
//
// With validation.plate_load = "along" the far edge's load pushes the plate towards its clamped
// edge in its plane instead: every section across the plate carries the load P, and the plate's
// compressive strength in that direction is sigma = P / (B T) at the first break, wherever it is.
// For squares along the grid each face of a section holds L_e T_e sigma_c (eq. 1), so sigma is
// the compressive strength; a hexagonal grid's faces lie at 30 degrees to the load or along it,
// and carry the load partly in shear (eq. 2).
#pragma once

#include <vector>

#include "dem/fracture/fracture_state.hpp"
#include "dem/validation/case.hpp"

namespace icedem {

class WideCantilever : public ValidationCase {
 public:
  /// Lifts the plate 1 m into the air, clamps its root elements and sets the first loads.
  WideCantilever(const Scene& scene, State& state);
  void after_step(const Scene& scene, State& state) override;
  ValidationResult result(const Scene& scene) const override;

 private:
  void set_loads(const Scene& scene);

  std::vector<int> free_;              // World::floes() indices of the free elements
  std::vector<double> free_mass_;      // kg, their masses
  std::vector<int> tip_;               // the loaded elements
  std::vector<double> tip_share_;      // each one's share of the load (by mass)
  std::vector<char> clamped_;          // per World::floes() index
  double root_x_ = 0;                  // m, mean x of the joints between clamped and free elements
  double load_x_ = 0;                  // m, the load's centre (mass-weighted)
  int root_joints_ = 0;
  double root_face_length_ = 0;        // m, their faces' total length
  double tip_load_ = 0;                // N, applied in the step just taken
  bool broken_ = false;
  FractureEvent first_break_{};
  bool first_at_root_ = false;
  double load_at_break_ = 0;           // N
};

}  // namespace icedem
