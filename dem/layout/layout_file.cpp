// Floe layout files: reading (the CSV and JSON readers are layout_csv.cpp and
// layout_json.cpp; here every floe is checked, named by file, line or index, and field) and
// writing. Format and conventions: floe_layout.hpp.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/layout/channel_cells.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/layout/layout_file_rows.hpp"

namespace icedem {
namespace {

using layout_file::RawFloe;
using layout_file::kMaxLayoutBytes;
using layout_file::lower;
using layout_file::shorten;

// tolerance for floes read from files, m: touching floes and floes flush with
// the channel edge must not fail because of rounding in the file's decimals or
// in re-centring; 1 nm is far below any physical size yet far above rounding
constexpr double kFileTolerance = 1e-9;

// how one file names its floes and fields in messages
struct FileNaming {
  std::string path;
  bool csv;

  // "file.csv:7: field 'polygon'" or "file.json: floes[3].polygon"
  std::string field(const RawFloe& r, const std::string& csv_field,
                    const std::string& json_field) const {
    if (csv) return fmt::format("{}:{}: field '{}'", path, r.line, csv_field);
    return fmt::format("{}: floes[{}].{}", path, r.index, json_field);
  }
  // "the floe on line 7" or "floes[3]"
  std::string name(const RawFloe& r) const {
    if (csv) return fmt::format("the floe on line {}", r.line);
    return fmt::format("floes[{}]", r.index);
  }
};

// ".csv" or ".json" (lower case), or InputError
std::string layout_extension(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  if (ext != ".csv" && ext != ".json") {
    throw InputError(fmt::format("{}: unknown layout file extension '{}'; expected .csv or .json",
                                 path, ext));
  }
  return ext;
}

Floe finish_floe(const RawFloe& r, const FileNaming& naming, const Channel& ch) {
  // a usable outline: convex, >= 3 vertices, positive area
  const std::string poly_field = naming.field(r, "polygon", "polygon");
  if (r.polygon.size() < 3) {
    throw InputError(fmt::format("{} = {}: {} vertices; expected a convex polygon with at least "
                                 "3 vertices",
                                 poly_field, shorten(r.polygon_text), r.polygon.size()));
  }
  if (!is_convex(r.polygon)) {
    throw InputError(fmt::format(
        "{} = {}: the polygon is not convex (it has a reflex corner, crosses itself, repeats a "
        "vertex or has zero area); expected a convex polygon with >= 3 distinct vertices and "
        "positive area",
        poly_field, shorten(r.polygon_text)));
  }

  // a yaw is an angle of a turn or less: beyond, sin and cos lose every digit
  if (!(std::abs(r.yaw_deg) <= 360.0))
    throw InputError(fmt::format("{} = {}: expected an angle in [-360, 360] degrees", naming.field(r, "yaw_deg", "yaw_deg"),
                                 r.yaw_deg));

  // re-centre on the area centroid, moving the centre so the outline stays put
  Floe f;
  f.yaw = r.yaw_deg * kPi / 180.0;
  const Eigen::Vector2d c = centroid(r.polygon);
  f.centre = r.centre + rotate(c, f.yaw);
  f.shape.reserve(r.polygon.size());
  for (const auto& v : r.polygon) f.shape.push_back(v - c);
  f.shape = make_ccw(std::move(f.shape));

  // the whole floe inside the channel
  const Polygon world = transformed(f.shape, f.centre, f.yaw);
  if (!inside(world, ch, kFileTolerance)) {
    Eigen::Vector2d worst = world.front();
    for (const auto& v : world) {
      const double out = std::max({ch.x_min - v.x(), v.x() - ch.x_max, ch.z_min - v.y(),
                                   v.y() - ch.z_max});
      const double worst_out = std::max({ch.x_min - worst.x(), worst.x() - ch.x_max,
                                         ch.z_min - worst.y(), worst.y() - ch.z_max});
      if (out > worst_out) worst = v;
    }
    const std::string where = naming.csv
                                  ? fmt::format("{}:{}: fields 'x', 'z'", naming.path, r.line)
                                  : naming.field(r, "", "centre");
    throw InputError(fmt::format(
        "{} = {} (yaw_deg {}): the floe reaches ({:.6g}, {:.6g}), outside the channel {}; "
        "expected the whole floe inside the channel",
        where, r.centre_text, r.yaw_deg, worst.x(), worst.y(), channel_text(ch)));
  }
  return f;
}

}  // namespace

Layout read_layout_file(const std::string& path, const Channel& channel) {
  check_channel(channel, path);

  // format by extension
  const std::string ext = layout_extension(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(fmt::format("{}: cannot open the layout file; expected a readable .csv or "
                                 ".json file",
                                 path));
  }
  // a layout is a few hundred kB at most: refuse what would exhaust the parser
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0);
  if (size > kMaxLayoutBytes)
    throw InputError(fmt::format("{}: {} MB; a layout file of a tank's floes is under a MB (at most {} MB)", path,
                                 size / 1e6, kMaxLayoutBytes / 1e6));
  const FileNaming naming{path, ext == ".csv"};
  const std::vector<RawFloe> raw = naming.csv ? layout_file::read_csv(path, in) : layout_file::read_json(path, in);

  // each floe on its own
  Layout layout;
  layout.channel_area = channel_area(channel);
  layout.floes.reserve(raw.size());
  double radius = 0.0;
  for (const RawFloe& r : raw) {
    layout.floes.push_back(finish_floe(r, naming, channel));
    radius = std::max(radius, bounding_radius(layout.floes.back().shape));
  }

  // pairs: each floe against the earlier ones near it (cell list, O(N))
  const size_t n = layout.floes.size();
  std::vector<Polygon> world(n);
  CellList cells(channel, 2.0 * radius, n);
  for (size_t j = 0; j < n; ++j) {
    const Floe& f = layout.floes[j];
    world[j] = transformed(f.shape, f.centre, f.yaw);
    const double rj = bounding_radius(f.shape);
    int hit = -1;
    cells.any_near(f.centre, [&](int i) {
      const Floe& g = layout.floes[i];
      const double reach = rj + bounding_radius(g.shape);
      if ((g.centre - f.centre).squaredNorm() >= reach * reach) return false;
      // negative gap: penetration below the file tolerance is rounding
      if (!overlap(world[j], world[i], -kFileTolerance)) return false;
      hit = i;
      return true;
    });
    if (hit >= 0) {
      const RawFloe& a = raw[j];
      const RawFloe& b = raw[hit];
      throw InputError(fmt::format(
          "{} = {}: this floe (centre {}) overlaps {} (centre {}); expected floes that do not "
          "overlap (touching is allowed)",
          naming.field(a, "polygon", "polygon"), shorten(a.polygon_text), a.centre_text,
          naming.name(b), b.centre_text));
    }
    cells.insert(static_cast<int>(j), cells.cell_of(f.centre));
  }

  layout.achieved_concentration = concentration(layout.floes, channel);
  return layout;
}

void write_layout_file(const std::string& path, const std::vector<Floe>& floes) {
  const std::string ext = layout_extension(path);
  // "{}" prints the shortest decimal that reads back to the same double
  std::string out;
  if (ext == ".csv") {
    out += "# icedem floe layout. x, z: floe centre (area centroid), m, tank frame;\n";
    out += "# yaw_deg: rotation about +y, degrees; polygon: local vertices \"x z; ...\", m\n";
    out += "x,z,yaw_deg,polygon\n";
    for (const auto& f : floes) {
      out += fmt::format("{},{},{},\"", f.centre.x(), f.centre.y(), f.yaw * 180.0 / kPi);
      for (size_t k = 0; k < f.shape.size(); ++k) {
        out += fmt::format("{}{} {}", k ? "; " : "", f.shape[k].x(), f.shape[k].y());
      }
      out += "\"\n";
    }
  } else {
    out += "{\"floes\": [\n";
    for (size_t i = 0; i < floes.size(); ++i) {
      const Floe& f = floes[i];
      out += fmt::format("  {{\"centre\": [{}, {}], \"yaw_deg\": {}, \"polygon\": [", f.centre.x(),
                         f.centre.y(), f.yaw * 180.0 / kPi);
      for (size_t k = 0; k < f.shape.size(); ++k) {
        out += fmt::format("{}[{}, {}]", k ? ", " : "", f.shape[k].x(), f.shape[k].y());
      }
      out += i + 1 < floes.size() ? "]},\n" : "]}\n";
    }
    out += "]}\n";
  }
  std::ofstream file(path, std::ios::binary);
  file << out;
  if (!file) throw std::runtime_error("cannot write the layout file " + path);
}

}  // namespace icedem
