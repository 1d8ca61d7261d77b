// Initial arrangement of ice floes in the channel: generated at a target ice
// concentration (square floes, seeded and reproducible, no overlap) or read from
// a file of convex polygons (CSV or JSON).
//
// Generation (generate_square_layout): N = round(C A / L^2) squares of side L
// (with a size spread s > 0: sides drawn uniformly from L (1 +- s), as many as
// bring the floes' area nearest C A) start on the most regular grid that holds N of them (cell aspect closest to 1,
// surplus cells left empty at random) and are then relaxed by a seeded
// Monte-Carlo "hard polygon" procedure: in each sweep every floe in turn tries a
// random translation plus a random yaw change, accepted only if the floe stays
// inside the channel, |yaw| <= max_yaw and it keeps at least min_gap from every
// neighbour. The step size adapts towards ~40 % accepted moves. Random numbers
// come from std::mt19937_64 with a mapping written here, so a seed gives the
// same layout with any standard library.
//
// Layout files (read_layout_file, chosen by extension):
//   CSV (.csv): '#' starts a comment line; the first other line is the header
//     naming the columns x, z, yaw_deg, polygon (any order); then one floe per
//     line, e.g.
//       x,z,yaw_deg,polygon
//       6.2,-2.2,10,"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15"
//   JSON (.json):
//       {"floes": [{"centre": [6.2, -2.2], "yaw_deg": 10,
//                   "polygon": [[-0.15, -0.15], [0.15, -0.15], ...]}, ...]}
//   x, z / centre: position of the local origin in the tank frame, m; yaw_deg:
//   rotation about +y, degrees; polygon: local vertices (x, z), m. Polygons are
//   re-centred on their area centroid (the centre moves with them, so the world
//   outline is unchanged) and put in ccw order (polygon.hpp). Each polygon must
//   be convex with >= 3 vertices and positive area; floes must lie inside the
//   channel and must not overlap (touching is allowed). Errors throw InputError
//   naming the file, the CSV line ("file.csv:12:") or JSON floe index
//   ("floes[3]"), the field, its value and what was expected.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dem/layout/polygon.hpp"

namespace icedem {

/// Largest count of Monte-Carlo moves (layout.sweeps x floes) a generated layout may take:
/// at about 0.5 us a move, some 25 s of set-up.
constexpr double kMaxLayoutMoves = 5e7;

/// One rigid ice floe seen from above.
struct Floe {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // m, (x, z) of the area centroid, tank frame
  double yaw = 0.0;  // rad, rotation about +y (polygon.hpp convention)
  Polygon shape;     // m, local convex outline, ccw, area centroid at the origin
  int layer = 0;     // rafted ice: starts `layer` thicknesses (+ min gap) above the floating layer
};

/// The rectangle (in the horizontal plane) that floes must lie inside.
struct Channel {
  double x_min;  // m, surge start of the ice field
  double x_max;  // m, surge end of the ice field
  double z_min;  // m, sway of one edge (wall ice)
  double z_max;  // m, sway of the other edge
};

/// Parameters of a generated layout of square floes. Defaults are the design
/// scenario with the seed paper's small floes (Hasegawa et al., Figure 3(a)).
struct LayoutParams {
  Channel channel{6.0, 30.0, -2.4, 2.4};  // m
  double floe_size = 0.3;                // m, side L of the square floes (key ice.floe_size)
  double concentration = 0.75;           // fraction 0..1 of channel area covered (ice.concentration)
  uint64_t seed = 1;                     // random seed; same seed -> bitwise same layout
  double max_yaw = 0.2617993877991494;   // rad, largest |yaw| of a floe (15 degrees)
  int sweeps = 30;                       // Monte-Carlo passes over all floes (0 = grid only)
  double min_gap = 0.002;                // m, minimum clearance between floes
  double size_spread = 0.0;              // -, sides uniform in floe_size (1 +- size_spread); 0: all alike
  std::function<void(double)> on_sweep;  // told the share of the sweeps done, before each (optional)
};

/// A set of floes and how much of the channel they cover.
struct Layout {
  std::vector<Floe> floes;
  double channel_area = 0.0;            // m^2, (x_max - x_min) (z_max - z_min)
  double achieved_concentration = 0.0;  // total floe area / channel_area
  double acceptance_rate = 0.0;         // fraction of Monte-Carlo moves accepted (0 if none)
  // per floe, the elements its lattice is cut into if it is breakable (0: rigid, or not counted);
  // counted once where a scene's floes are checked (scene_layout), for its warnings
  std::vector<std::size_t> floe_elements;
};

/// Generates N = round(C A / L^2) non-overlapping square floes in the channel
/// (see the file comment). Throws InputError, naming ice.concentration and
/// ice.floe_size and their values, if the floes cannot fit (e.g. C above what a
/// grid of floes of that size allows, or a floe larger than the channel) or a
/// parameter is out of range.
Layout generate_square_layout(const LayoutParams& params);

/// Reads floes from a .csv or .json file (format in the file comment) and checks
/// them against the channel. Throws InputError on any problem.
Layout read_layout_file(const std::string& path, const Channel& channel);

/// Writes floes in the format read_layout_file() reads, chosen by the extension
/// (.csv or .json), with round-trip precision. Throws InputError for an unknown
/// extension and std::runtime_error if the file cannot be written.
void write_layout_file(const std::string& path, const std::vector<Floe>& floes);

/// Total floe area divided by the channel area.
double concentration(const std::vector<Floe>& floes, const Channel& channel);

}  // namespace icedem
