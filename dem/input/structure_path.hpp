// Where the structure's path meets a fixed boundary: the channel's end wall (mother ice closing
// the channel, channel.end_wall) or the mother-ice edges along its sides.
//
// A structure towed into the end wall squeezes the ice ahead of it against the wall: the load is
// the rig's, not the ice's, and it grows without bound as the solve tightens (the 0.20 m lattices'
// bench field, scenarios/bench/large_breakable_short.toml, towed to 90 s: 13-15 N until 89.7 s,
// then 698 N and 1469 N within 0.2 s on seeds 1 and 2; 63,771 N with the step halved and the solve
// at 1e-6). `icedem check` warns when the run gets there, and the run's statistics end where the
// squeeze begins (stats.include_squeeze keeps those steps).
#pragma once

#include <optional>
#include <string>

#include "dem/input/scene.hpp"

namespace icedem {

/// The structure reaching the channel's end wall.
struct EndWallMeeting {
  double time;        // s, when the squeeze begins: the hull's widest part one ice thickness from the wall
  double wall_x;      // m, the wall's face: channel.start_x + channel.length
  double hull_radius; // m, the hull's largest radius (the part that meets the wall first)
};

/// When the structure's path meets the channel's end wall, if the channel has one and the
/// structure is towed towards it (not from beyond it); none otherwise (whether or not it happens within the run).
/// The squeeze is taken to begin when the gap between the hull's widest part and the wall is one
/// ice thickness: no floe passes between them then, and on the bench field above the load left its
/// level 0.1-0.2 s later.
std::optional<EndWallMeeting> end_wall_meeting(const Scene& scene);

/// The same, only if it happens within the run (before time.duration).
std::optional<EndWallMeeting> end_wall_meeting_in_run(const Scene& scene);

/// Whether the hull, where it meets the ice, runs through the mother-ice edges along the
/// channel's sides (|structure.start_z| + its radius there beyond channel.width / 2).
bool hull_through_side_edges(const Scene& scene);

}  // namespace icedem
