// Layout files in CSV: one floe per line, columns x, z, yaw_deg, polygon (dem/layout/floe_layout.hpp).
#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "dem/core/errors.hpp"
#include "dem/layout/layout_file_rows.hpp"

namespace icedem {
namespace layout_file {

// splits one CSV line into fields; double quotes protect commas, "" is a quote
namespace {

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

}  // namespace

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

}  // namespace layout_file
}  // namespace icedem
