// The scenario keys: each key declared once, with its type, unit, default,
// allowed range and a one-line doc. The parser, the validator, the resolved
// scenario text written to /meta and `icedem keys` (docs/user/scenario_keys.md) all
// read this one table.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace icedem {

enum class KeyType {
  kReal,        // a number; integers are accepted
  kInteger,     // a whole number
  kBoolean,     // true | false
  kString,      // free text (e.g. a file path)
  kChoice,      // one of `choices`
  kVector3,     // [x, y, z]
  kPairList,    // [[a, b], [a, b], ...], at least two pairs
};

using PairList = std::vector<std::array<double, 2>>;
using Vector3Value = std::array<double, 3>;

/// A scenario value, typed by its key's KeyType.
using KeyValue = std::variant<double, std::int64_t, bool, std::string, Vector3Value, PairList>;

/// One declared scenario key.
struct KeySpec {
  std::string path;        // dotted path, e.g. "ice.floe_size"
  KeyType type;
  std::string unit;        // SI unit, "-" for dimensionless, "" for text
  KeyValue default_value;
  double min = -std::numeric_limits<double>::infinity();  // inclusive bounds for numbers,
  double max = std::numeric_limits<double>::infinity();   // applied element-wise to lists
  bool min_exclusive = false;                             // true: value must be > min
  std::vector<std::string> choices;                       // kChoice only
  std::string doc;                                        // one line
};

/// All declared keys, in the order they are documented and written out.
const std::vector<KeySpec>& scenario_keys();

/// The key declared at `path`, or nullptr.
const KeySpec* find_key(const std::string& path);

/// True if `path` names a section (e.g. "ice") that holds declared keys.
bool is_section(const std::string& path);

/// The declared key or section nearest to `path` by edit distance (for
/// "did you mean" hints), or "" if nothing is reasonably close.
std::string nearest_key(const std::string& path);

/// Human-readable type and range, e.g. "a number > 0 (m)".
std::string describe_expected(const KeySpec& spec);

/// A value formatted as TOML (strings quoted, lists bracketed).
std::string format_value(const KeyValue& value);

/// Markdown table of every key (docs/user/scenario_keys.md is generated from it).
std::string keys_markdown();

}  // namespace icedem
