// The OpenFOAM potential-flow case around the structure: what it is made of
// (FoamCaseSpec, from the scenario), the key it is cached under, and writing a
// runnable copy of the foam_case/ template (Allrun meshes, solves and samples).
//
// The case is in the structure frame: the structure is fixed with its axis on
// the y axis and the water flows past it along -x (a tow along +x), in a box
// of the tank's width and depth and coupling.domain_length, under a rigid lid
// at the still-water line (y = 0). The hull's STL comes from the same profile
// as the DEM's Bullet hull (dem/world/cone_geometry.hpp).
#pragma once

#include <string>
#include <vector>

#include "coupling/flow_grid.hpp"
#include "dem/input/scene.hpp"

namespace icedem {

struct FoamCaseSpec {
  std::vector<ProfileStation> profile;  // hull stations (y, radius), m
  int segments;                         // polygon sides of the hull's STL
  double length, width, depth;          // m, domain: x in [-length/2, length/2], z in [-width/2, width/2], y in [-depth, 0]
  std::string mesh;                     // "coarse" | "medium" | "fine"
  double cell;                          // m, background cell size
  int level;                            // refinement level at the hull (cell / 2^level there)
  double grid_spacing;                  // m, of the sampled grid
  double grid_depth;                    // m, the grid spans y in [-grid_depth, 0]
};

/// The case of a scene (structure, tank, coupling keys).
FoamCaseSpec foam_case_spec(const Scene& scene);

/// Every input of the case as canonical text (the cache key is its hash).
std::string foam_case_inputs(const FoamCaseSpec& spec);

/// 16 hex digits (FNV-1a 64) of foam_case_inputs: equal inputs, equal solution.
std::string foam_case_hash(const FoamCaseSpec& spec);

/// The grid the velocity is sampled on.
GridAxes foam_grid_axes(const FoamCaseSpec& spec);

/// The foam_case/ template of this source tree ($ICEDEM_FOAM_TEMPLATE overrides it).
std::string foam_template_dir();

/// Copies the template into case_dir (created if needed), fills in every @TOKEN@
/// of its *.in files, and writes the STL, the probe list, case.inputs (the inputs, one per
/// line) and case.hash (their hash; coupling/foam_partner.py reads both). Throws std::runtime_error naming the file on failure.
void write_foam_case(const FoamCaseSpec& spec, const std::string& template_dir, const std::string& case_dir);

}  // namespace icedem
