// What the layout-file readers share (dem/layout/layout_file.cpp, layout_csv.cpp, layout_json.cpp):
// a floe as read, before the checks, with where it came from, and the text helpers of their
// messages. Internal to the layout file readers.
#pragma once

#include <cctype>
#include <charconv>
#include <cmath>
#include <ios>
#include <istream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dem/layout/polygon.hpp"

namespace icedem {
namespace layout_file {

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

// limits on a layout file, far above a tank's (hundreds of floes, tens of kB)
constexpr std::streamoff kMaxLayoutBytes = 64 << 20;
constexpr int kMaxJsonDepth = 16;

inline std::string shorten(const std::string& s) {
  constexpr size_t kMax = 160;
  return s.size() <= kMax ? s : s.substr(0, kMax) + "...";
}

inline std::string trim(const std::string& s) {
  const char* ws = " \t\r\n";
  const size_t a = s.find_first_not_of(ws);
  if (a == std::string::npos) return "";
  const size_t b = s.find_last_not_of(ws);
  return s.substr(a, b - a + 1);
}

inline std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// a finite decimal number, the whole of `text` (locale independent)
inline bool parse_number(const std::string& text, double& value) {
  std::string t = trim(text);
  if (!t.empty() && t[0] == '+') t.erase(0, 1);
  if (t.empty()) return false;
  const char* end = t.data() + t.size();
  const auto result = std::from_chars(t.data(), end, value);
  return result.ec == std::errc() && result.ptr == end && std::isfinite(value);
}

/// The floes of a CSV layout (columns x, z, yaw_deg, polygon); InputError naming line and field.
std::vector<RawFloe> read_csv(const std::string& path, std::istream& in);

/// The floes of a JSON layout ({"floes": [...]}); InputError naming the floe's index and field.
std::vector<RawFloe> read_json(const std::string& path, std::istream& in);

}  // namespace layout_file
}  // namespace icedem
