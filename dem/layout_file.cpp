// Floe layout files: reading (CSV and JSON, every problem named by file, line or
// index, and field) and writing. Format and conventions: floe_layout.hpp.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dem/channel_cells.hpp"
#include "dem/constants.hpp"
#include "dem/errors.hpp"
#include "dem/floe_layout.hpp"

namespace icedem {
namespace {

// tolerance for floes read from files, m: touching floes and floes flush with
// the channel edge must not fail because of rounding in the file's decimals or
// in re-centring; 1 nm is far below any physical size yet far above rounding
constexpr double kFileTolerance = 1e-9;

// a floe as read from a file, before the checks, with where it came from
struct RawFloe {
  Eigen::Vector2d centre;  // m, position of the local origin
  double yaw_deg;          // degrees
  Polygon polygon;         // m, local vertices as given
  std::string centre_text;   // the centre value as written in the file
  std::string polygon_text;  // the polygon value as written in the file
  int line = 0;              // CSV line number (1-based); 0 for JSON
  size_t index = 0;          // position in the file (0-based)
};

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

// limits on a layout file, far above a tank's (hundreds of floes, tens of kB)
constexpr std::streamoff kMaxLayoutBytes = 64 << 20;
constexpr int kMaxJsonDepth = 16;

std::string shorten(const std::string& s) {
  constexpr size_t kMax = 160;
  return s.size() <= kMax ? s : s.substr(0, kMax) + "...";
}

std::string trim(const std::string& s) {
  const char* ws = " \t\r\n";
  const size_t a = s.find_first_not_of(ws);
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(ws);
  return s.substr(a, b - a + 1);
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// a finite decimal number, the whole of `text` (locale independent)
bool parse_number(const std::string& text, double& value) {
  std::string t = trim(text);
  if (!t.empty() && t[0] == '+') t.erase(0, 1);
  if (t.empty()) return false;
  const char* end = t.data() + t.size();
  const auto result = std::from_chars(t.data(), end, value);
  return result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

// ---------------------------------------------------------------- CSV

// splits one CSV line into fields; double quotes protect commas, "" is a quote
bool split_csv(const std::string& line, std::vector<std::string>& fields) {
  fields.assign(1, "");
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return !quoted;
}

const std::vector<std::string> kCsvColumns = {"x", "z", "yaw_deg", "polygon"};

std::vector<RawFloe> read_csv(const std::string& path, std::istream& in) {
  std::vector<RawFloe> floes;
  std::vector<int> column;  // column[f] = position of kCsvColumns[f] in the line
  std::string line;
  std::vector<std::string> fields;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    // tolerate a UTF-8 byte order mark and Windows line ends
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    const std::string content = trim(line);
    if (content.empty() || content[0] == '#') continue;
    if (!split_csv(line, fields)) {
      throw InputError(fmt::format("{}:{}: unterminated double quote in \"{}\"; expected "
                                   "quoted fields to end with '\"'",
                                   path, number, shorten(content)));
    }

    // the first content line is the header
    if (column.empty()) {
      column.assign(kCsvColumns.size(), -1);
      for (size_t p = 0; p < fields.size(); ++p) {
        const std::string name = lower(trim(fields[p]));
        const auto it = std::find(kCsvColumns.begin(), kCsvColumns.end(), name);
        if (it == kCsvColumns.end() || column[it - kCsvColumns.begin()] >= 0) {
          throw InputError(fmt::format(
              "{}:{}: header column {} = '{}' is {}; expected the header x,z,yaw_deg,polygon "
              "(any order)",
              path, number, p + 1, trim(fields[p]),
              it == kCsvColumns.end() ? "unknown" : "repeated"));
        }
        column[it - kCsvColumns.begin()] = static_cast<int>(p);
      }
      for (size_t f = 0; f < kCsvColumns.size(); ++f) {
        if (column[f] < 0) {
          throw InputError(fmt::format(
              "{}:{}: header \"{}\" has no column '{}'; expected the header x,z,yaw_deg,polygon",
              path, number, shorten(content), kCsvColumns[f]));
        }
      }
      continue;
    }

    if (fields.size() != kCsvColumns.size()) {
      throw InputError(fmt::format(
          "{}:{}: {} fields in \"{}\"; expected {} (x, z, yaw_deg, polygon; quote the polygon)",
          path, number, fields.size(), shorten(content), kCsvColumns.size()));
    }
    RawFloe r;
    r.line = number;
    r.index = floes.size();
    const std::string& xs = fields[column[0]];
    const std::string& zs = fields[column[1]];
    const std::string& ys = fields[column[2]];
    const std::string& ps = fields[column[3]];
    auto number_field = [&](const std::string& name, const std::string& text) {
      double v;
      if (!parse_number(text, v)) {
        throw InputError(fmt::format("{}:{}: field '{}' = \"{}\": not a number; expected a "
                                     "finite decimal number",
                                     path, number, name, shorten(trim(text))));
      }
      return v;
    };
    r.centre = {number_field("x", xs), number_field("z", zs)};
    r.yaw_deg = number_field("yaw_deg", ys);
    r.centre_text = fmt::format("{}, {}", trim(xs), trim(zs));
    r.polygon_text = "\"" + trim(ps) + "\"";

    // polygon: "x1 z1; x2 z2; ..."
    std::stringstream vertices(ps);
    std::string vertex;
    int count = 0;
    while (std::getline(vertices, vertex, ';')) {
      if (trim(vertex).empty()) continue;
      ++count;
      std::istringstream tokens(vertex);
      std::string a, b, extra;
      double vx, vz;
      tokens >> a >> b;
      const bool two = !a.empty() && !b.empty() && !(tokens >> extra);
      if (!two || !parse_number(a, vx) || !parse_number(b, vz)) {
        throw InputError(fmt::format(
            "{}:{}: field 'polygon' = {}: vertex {} \"{}\" is not two numbers; expected "
            "\"x1 z1; x2 z2; ...\" in m",
            path, number, shorten(r.polygon_text), count, trim(vertex)));
      }
      r.polygon.emplace_back(vx, vz);
    }
    floes.push_back(std::move(r));
  }
  if (column.empty()) {
    throw InputError(fmt::format(
        "{}: no header line; expected the header x,z,yaw_deg,polygon then one floe per line",
        path));
  }
  return floes;
}

// ---------------------------------------------------------------- JSON

std::vector<RawFloe> read_json(const std::string& path, std::istream& in) {
  using nlohmann::json;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // nesting deeper than a layout's ({"floes": [{"polygon": [[x, z]]}]}: 4) is refused before
  // parsing: nlohmann's values are destroyed and printed recursively
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '[' || c == '{') deepest = std::max(deepest, ++depth);
    else if (c == ']' || c == '}') --depth;
  }
  if (deepest > kMaxJsonDepth)
    throw InputError(fmt::format("{}: nested {} levels deep; a layout is {{\"floes\": [{{\"centre\": [x, z], "
                                 "\"yaw_deg\": 0, \"polygon\": [[x, z], ...]}}]}}, 4 levels",
                                 path, deepest));
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {  // syntax, and numbers out of range (1e309)
    // the parser's own words, without its "[json.exception.parse_error.101] " tag
    std::string reason = e.what();
    if (reason.rfind("[json.exception.", 0) == 0 && reason.find("] ") != std::string::npos)
      reason = reason.substr(reason.find("] ") + 2);
    throw InputError(fmt::format("{}: invalid JSON ({}); expected {{\"floes\": [...]}}", path, shorten(reason)));
  }
  if (!root.is_object() || !root.contains("floes")) {
    throw InputError(fmt::format("{}: no key 'floes' at the top level; expected {{\"floes\": "
                                 "[{{\"centre\": [x, z], \"yaw_deg\": 0, \"polygon\": [[x, z], "
                                 "...]}}, ...]}}",
                                 path));
  }
  const json& list = root["floes"];
  if (!list.is_array()) {
    throw InputError(fmt::format("{}: floes = {}: expected an array of floe objects", path,
                                 shorten(list.dump())));
  }

  std::vector<RawFloe> floes;
  for (size_t i = 0; i < list.size(); ++i) {
    const json& item = list[i];
    auto fail = [&](const std::string& field, const json& value, const std::string& expected) {
      throw InputError(fmt::format("{}: floes[{}]{} = {}: expected {}", path, i,
                                   field.empty() ? "" : "." + field, shorten(value.dump()),
                                   expected));
    };
    if (!item.is_object()) fail("", item, "an object with centre, yaw_deg and polygon");
    for (const auto& [key, value] : item.items()) {
      if (key != "centre" && key != "yaw_deg" && key != "polygon") {
        fail(key, value, "only the keys centre, yaw_deg and polygon (unknown key '" + key + "')");
      }
    }
    for (const char* key : {"centre", "yaw_deg", "polygon"}) {
      if (!item.contains(key)) {
        throw InputError(fmt::format("{}: floes[{}].{} is missing; expected each floe to have "
                                     "centre [x, z] (m), yaw_deg and polygon [[x, z], ...] (m)",
                                     path, i, key));
      }
    }
    auto number = [&](const json& v, const std::string& field) {
      if (!v.is_number()) fail(field, v, "a number");
      const double d = v.get<double>();
      if (!std::isfinite(d)) fail(field, v, "a finite number");
      return d;
    };
    auto point = [&](const json& v, const std::string& field) {
      if (!v.is_array() || v.size() != 2) fail(field, v, "a pair [x, z] of numbers in m");
      return Eigen::Vector2d(number(v[0], field + "[0]"), number(v[1], field + "[1]"));
    };

    RawFloe r;
    r.index = i;
    r.centre = point(item["centre"], "centre");
    r.yaw_deg = number(item["yaw_deg"], "yaw_deg");
    const json& poly = item["polygon"];
    if (!poly.is_array()) fail("polygon", poly, "an array of vertices [[x, z], ...] in m");
    for (size_t k = 0; k < poly.size(); ++k) {
      r.polygon.push_back(point(poly[k], fmt::format("polygon[{}]", k)));
    }
    r.centre_text = item["centre"].dump();
    r.polygon_text = poly.dump();
    floes.push_back(std::move(r));
  }
  return floes;
}

// ---------------------------------------------------------------- checks

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
  const std::vector<RawFloe> raw = naming.csv ? read_csv(path, in) : read_json(path, in);

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
