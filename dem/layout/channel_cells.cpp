#include "dem/layout/channel_cells.hpp"

#include <fmt/format.h>

#include "dem/core/errors.hpp"

namespace icedem {

bool inside(const Polygon& world, const Channel& ch, double tolerance) {
  for (const auto& v : world) {
    if (v.x() < ch.x_min - tolerance || v.x() > ch.x_max + tolerance ||
        v.y() < ch.z_min - tolerance || v.y() > ch.z_max + tolerance) {
      return false;
    }
  }
  return true;
}

double channel_area(const Channel& ch) { return (ch.x_max - ch.x_min) * (ch.z_max - ch.z_min); }

std::string channel_text(const Channel& ch) {
  return fmt::format("x in [{}, {}] m, z in [{}, {}] m", ch.x_min, ch.x_max, ch.z_min, ch.z_max);
}

void check_channel(const Channel& ch, const std::string& context) {
  const bool finite = std::isfinite(ch.x_min) && std::isfinite(ch.x_max) &&
                      std::isfinite(ch.z_min) && std::isfinite(ch.z_max);
  if (!finite || !(ch.x_max > ch.x_min)) {
    throw InputError(fmt::format(
        "{}: channel.length = {} m (x from {} to {} m): expected a finite length > 0", context,
        ch.x_max - ch.x_min, ch.x_min, ch.x_max));
  }
  if (!(ch.z_max > ch.z_min)) {
    throw InputError(fmt::format(
        "{}: channel.width = {} m (z from {} to {} m): expected a finite width > 0", context,
        ch.z_max - ch.z_min, ch.z_min, ch.z_max));
  }
}

}  // namespace icedem
