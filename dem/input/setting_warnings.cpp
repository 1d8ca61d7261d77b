#include "dem/input/setting_warnings.hpp"

#include <fmt/format.h>

#include "dem/input/structure_path.hpp"

namespace icedem {

std::vector<std::string> setting_warnings(const Scene& scene) {
  std::vector<std::string> out;
  if (const auto meeting = end_wall_meeting_in_run(scene))
    out.push_back(fmt::format(
        "the structure reaches the channel's end wall within the run: its widest part (radius {:.3f} m) comes "
        "within one ice thickness of the wall at x = {} m (channel.start_x + channel.length) at t = {:.1f} s, and "
        "time.duration is {} s. From then on it squeezes the ice against the wall, a load of the rig, not of the "
        "ice: the statistics end there (stats.include_squeeze = true keeps those steps). End the run by then, "
        "start the structure further back or lengthen the channel",
        meeting->hull_radius, meeting->wall_x, meeting->time, scene.time.duration));
  const double keel = scene.structure.profile.front().y;
  if (scene.validation.kind == ValidationKind::kNone && keel < -scene.channel.tank_depth)
    out.push_back(fmt::format(
        "the keel at y = {} m (structure.profile) is below the tank's bottom (tank.depth = {} m): a towed structure "
        "cannot be there; the flow around it is cut at the bottom, as for a structure standing on the floor",
        keel, scene.channel.tank_depth));
  if (hull_through_side_edges(scene))
    out.push_back(fmt::format(
        "the structure's hull at z = {} m runs through the mother-ice edges of the channel (channel.width = {} m): "
        "it presses the ice against a fixed edge the whole run",
        scene.structure.start_z, scene.channel.width));
  // keeping unreached floes out needs the sleeping islands it hands them back to (World::keeps_unreached);
  // without them the key does nothing. Validation cases have no field to keep out
  const ActivationSettings& a = scene.activation;
  if (a.unreached_out_of_world && scene.validation.kind == ValidationKind::kNone &&
      (!a.sleeping || !a.skip_asleep || a.islands != IslandMode::kContact || a.freeze_outside_region))
    out.push_back(
        "activation.unreached_out_of_world = true does nothing here: floes are kept out of the world until reached "
        "only with activation.sleeping = true, activation.skip_asleep = true, activation.islands = \"contact\" and "
        "activation.freeze_outside_region = false; every floe is simulated from the start (set it false to say so)");
  const double dt = scene.time.dt;
  for (const auto& [key, interval] :
       {std::pair<const char*, double>{"output.snapshot_interval", scene.output.snapshot_interval},
        {"output.checkpoint_interval", scene.output.checkpoint_interval}})
    if (interval > 0 && interval < dt * (1 - 1e-9))
      out.push_back(fmt::format("{} = {} s is shorter than the step (time.dt = {} s): one is written every step",
                                key, interval, dt));
  return out;
}

}  // namespace icedem
