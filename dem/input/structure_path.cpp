#include "dem/input/structure_path.hpp"

#include <algorithm>
#include <cmath>

namespace icedem {

std::optional<EndWallMeeting> end_wall_meeting(const Scene& scene) {
  if (!scene.channel.end_wall || scene.structure.speed <= 0 || scene.validation.kind != ValidationKind::kNone)
    return std::nullopt;
  const std::vector<ProfileStation>& hull = scene.structure.profile;
  // the widest part of the whole hull: ice rides up the slope and under the keel, and the
  // deck's rim reached the wall first on the bench field
  const double r = hull_radius_over(hull, hull.front().y, hull.back().y);
  const double wall = scene.channel.start_x + scene.channel.length;
  const double reach = wall - r - scene.ice.thickness;  // the axis's x when the squeeze begins
  if (scene.structure.start_x - r > wall) return std::nullopt;  // past the wall, towed away from it
  const double t = (reach - scene.structure.start_x) / scene.structure.speed;
  return EndWallMeeting{std::max(0.0, t), wall, r};
}

std::optional<EndWallMeeting> end_wall_meeting_in_run(const Scene& scene) {
  const auto meeting = end_wall_meeting(scene);
  if (!meeting || meeting->time >= scene.time.duration) return std::nullopt;
  return meeting;
}

bool hull_through_side_edges(const Scene& scene) {
  if (scene.validation.kind != ValidationKind::kNone) return false;
  return std::abs(scene.structure.start_z) + hull_radius_in_ice(scene) > 0.5 * scene.channel.width;
}

}  // namespace icedem
