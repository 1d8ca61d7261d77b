// Layout files in JSON: {"floes": [{"centre": [x, z], "yaw_deg": ..., "polygon": [[x, z], ...]}, ...]}.
#include <algorithm>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dem/core/errors.hpp"
#include "dem/layout/layout_file_rows.hpp"

namespace icedem {
namespace layout_file {

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

}  // namespace layout_file
}  // namespace icedem
