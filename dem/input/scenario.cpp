#include "dem/input/scenario.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/input/solver_profile.hpp"

namespace icedem {
namespace {

namespace fs = std::filesystem;

// "file:line" for a TOML node
std::string origin_of(const std::string& file, const toml::node& node) {
  return fmt::format("{}:{}", file, node.source().begin.line);
}

// Limits on what a scenario can be: far above any real one, low enough that a
// malformed file is refused at once instead of exhausting the parser (toml++
// recurses once per nesting level) or the messages (which quote what they name).
constexpr std::size_t kMaxScenarioBytes = std::size_t(1) << 20;  // a real scenario is a few kB
constexpr int kMaxNesting = 16;        // dotted key segments, or brackets, per line (keys have 3)
constexpr std::size_t kMaxQuote = 60;  // characters of a value or key quoted in a message

// short text of a TOML node as the user wrote it, for messages
std::string show(const toml::node& node) {
  std::ostringstream s;
  if (auto* str = node.as_string())
    s << '"' << str->get() << '"';
  else if (node.is_table())
    s << "a table";
  else
    node.visit([&](auto&& n) { s << n; });
  return excerpt(s.str());
}

// Refuse text nested deeper than kMaxNesting (dotted keys, table headers, arrays) before the
// parser sees it. Strings and comments are skipped; a line is judged by its worst nesting.
void check_nesting(const std::string& text, const std::string& file) {
  int line = 1, brackets = 0, dots = 0;
  char quote = 0;
  bool comment = false, in_value = false;
  for (char c : text) {
    if (c == '\n') {
      ++line;
      comment = false;
      dots = 0;
      in_value = brackets > 0;  // a multi-line array continues its value
      if (quote == '"' || quote == '\'') quote = 0;  // single-line strings end at the line
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    else if (c == '#') comment = true;
    else if (c == '=') in_value = true;
    else if (c == '[') ++brackets;
    else if (c == ']') brackets = std::max(0, brackets - 1);
    else if (c == '.' && !in_value) ++dots;
    if (brackets > kMaxNesting || dots > kMaxNesting)
      throw InputError(fmt::format("{}:{}: nested more than {} levels deep; scenario keys have at most 3 "
                                   "(`icedem keys` lists them)",
                                   file, line, kMaxNesting));
  }
}

std::optional<double> number(const toml::node& n) {
  if (auto* f = n.as_floating_point()) return f->get();
  if (auto* i = n.as_integer()) return static_cast<double>(i->get());
  return std::nullopt;
}

bool in_range(const KeySpec& s, double v) {
  if (!std::isfinite(v)) return false;
  if (s.min_exclusive ? !(v > s.min) : !(v >= s.min)) return false;
  return v <= s.max;
}

// Convert one TOML node to the key's type; nullopt if the type or range is wrong.
std::optional<KeyValue> convert(const KeySpec& s, const toml::node& n) {
  switch (s.type) {
    case KeyType::kReal: {
      auto v = number(n);
      if (!v || !in_range(s, *v)) return std::nullopt;
      return KeyValue{*v};
    }
    case KeyType::kInteger: {
      auto* i = n.as_integer();
      // compared as integers: 9000000000000000001 is 9e18 as a double, and would pass a bound of 9e18
      if (!i || !in_range(s, static_cast<double>(i->get())) || i->get() > static_cast<std::int64_t>(s.max))
        return std::nullopt;
      return KeyValue{static_cast<std::int64_t>(i->get())};
    }
    case KeyType::kBoolean: {
      auto* b = n.as_boolean();
      if (!b) return std::nullopt;
      return KeyValue{b->get()};
    }
    case KeyType::kString: {
      auto* str = n.as_string();
      if (!str) return std::nullopt;
      return KeyValue{str->get()};
    }
    case KeyType::kChoice: {
      auto* str = n.as_string();
      if (!str) return std::nullopt;
      for (const auto& c : s.choices)
        if (c == str->get()) return KeyValue{c};
      return std::nullopt;
    }
    case KeyType::kVector3: {
      auto* a = n.as_array();
      if (!a || a->size() != 3) return std::nullopt;
      Vector3Value v{};
      for (std::size_t i = 0; i < 3; ++i) {
        auto x = number(*a->get(i));
        if (!x || !in_range(s, *x)) return std::nullopt;
        v[i] = *x;
      }
      return KeyValue{v};
    }
    case KeyType::kPairList: {
      auto* a = n.as_array();
      if (!a || a->size() < 2) return std::nullopt;
      PairList list;
      for (std::size_t i = 0; i < a->size(); ++i) {
        auto* pair = a->get(i)->as_array();
        if (!pair || pair->size() != 2) return std::nullopt;
        auto p0 = number(*pair->get(0)), p1 = number(*pair->get(1));
        if (!p0 || !p1 || !in_range(s, *p0) || !in_range(s, *p1)) return std::nullopt;
        list.push_back({*p0, *p1});
      }
      return KeyValue{list};
    }
  }
  return std::nullopt;
}

std::string unknown_key_message(const std::string& where, const std::string& path, bool section) {
  std::string msg = fmt::format("{}: unknown {} '{}'", excerpt(where), section ? "section" : "key", excerpt(path));
  // a key far longer than any real one has no near neighbour (and the search would be slow)
  const std::string hint = path.size() <= 3 * kMaxQuote ? nearest_key(path) : "";
  if (!hint.empty()) msg += fmt::format(" (did you mean '{}'?)", hint);
  msg += "; `icedem keys` lists every key";
  return msg;
}

// Set one key from a TOML node, or throw naming where it came from.
void assign(Scenario& sc, const std::string& path, const toml::node& node, const std::string& where) {
  const KeySpec* spec = find_key(path);
  // a section's name given a value ("structure = 3"): it is a section, not an unknown key
  if (!spec && is_section(path))
    throw InputError(fmt::format("{}: '{}' is a section: write its keys under [{}] (`icedem keys` lists them), "
                                 "not '{} = {}'",
                                 excerpt(where), path, path, path, show(node)));
  if (!spec) throw InputError(unknown_key_message(where, path, false));
  auto value = convert(*spec, node);
  if (!value)
    throw InputError(fmt::format("{}: {} = {}: expected {}", where, excerpt(path), show(node),
                                 describe_expected(*spec)));
  sc.keys[path] = ResolvedKey{*value, where};
}

// Walk a parsed table, flattening it to dotted paths. Keys that a --set replaces are not
// checked: a --set can repair an invalid value in the file.
void walk(Scenario& sc, const toml::table& table, const std::string& prefix, const std::string& file,
          const std::set<std::string>& overridden) {
  for (auto&& [key, node] : table) {
    // "time.dt" = 0.5 is one key whose name holds a dot, not dt of [time]: joined into a path it
    // would pass for time.dt and silently override [time] dt
    if (key.str().find('.') != std::string_view::npos)
      throw InputError(fmt::format("{}: the quoted key \"{}\" is one key with a dot in its name, not a key of a "
                                   "section: write it unquoted under its section ([{}] {} = ...)",
                                   origin_of(file, node), excerpt(std::string(key.str())),
                                   excerpt(std::string(key.str().substr(0, key.str().rfind('.')))),
                                   excerpt(std::string(key.str().substr(key.str().rfind('.') + 1)))));
    const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    if (overridden.count(path) && find_key(path)) continue;
    if (const toml::table* sub = node.as_table()) {
      if (find_key(path)) {
        // a key was given as a table: a type error, reported by assign()
        assign(sc, path, node, origin_of(file, node));
      }
      if (!is_section(path)) throw InputError(unknown_key_message(origin_of(file, node), path, true));
      walk(sc, *sub, path, file, overridden);
    } else {
      assign(sc, path, node, origin_of(file, node));
    }
  }
}

std::string trimmed(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

// the key a --set text names ("" without an '=')
std::string override_key(const std::string& text) {
  const auto eq = text.find('=');
  return eq == std::string::npos ? "" : trimmed(text.substr(0, eq));
}

void apply_override(Scenario& sc, const std::string& text) {
  // TOML would read a second line as a second key and the value would be cut silently at the first
  if (text.find_first_of("\n\r") != std::string::npos)
    throw InputError(fmt::format("--set {}: a value of more than one line; give the key and its value on one line",
                                 excerpt(text)));
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(fmt::format("--set {}: expected key.path=value", text));
  const std::string path = override_key(text), raw = trimmed(text.substr(eq + 1));
  const std::string where = "--set " + path + "=" + raw;
  const KeySpec* spec = find_key(path);
  if (!spec && is_section(path))
    throw InputError(fmt::format("{}: '{}' is a section, not a key: set one of its keys, e.g. --set {}.<key>=...; "
                                 "`icedem keys` lists them",
                                 excerpt(where), path, path));
  if (!spec) throw InputError(unknown_key_message(where, path, false));
  // parse the value as TOML; a bare word is taken as a string for text keys
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + raw);
  } catch (const toml::parse_error&) {
    if (spec->type != KeyType::kString && spec->type != KeyType::kChoice)
      throw InputError(fmt::format("{}: '{}' is not a valid value; expected {}", excerpt(where), excerpt(raw),
                                   describe_expected(*spec)));
    parsed = toml::table{{"v", raw}};
  }
  assign(sc, path, *parsed.get("v"), where);
}

// The key a line of a scenario sets, with its section ("ice.thickness"), "" if it sets none: a
// syntax error in a value (a number too long for 64 bits) then names its key, not only its line
std::string key_on_line(const std::string& text, std::size_t line) {
  std::stringstream in(text);
  std::string section, current;
  for (std::size_t n = 1; n <= line && std::getline(in, current); ++n) {
    const std::string t = trimmed(current);
    if (n < line && t.size() > 2 && t.front() == '[' && t[1] != '[') section = trimmed(t.substr(1, t.find(']') - 1));
  }
  const std::string t = trimmed(current);
  const auto eq = t.find('=');
  if (eq == std::string::npos || t.empty() || t.front() == '#' || t.front() == '[') return "";
  const std::string key = trimmed(t.substr(0, eq));
  if (key.empty() || key.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-.") !=
                         std::string::npos)
    return "";
  return section.empty() ? key : section + "." + key;
}

}  // namespace

// `text` cut to kMaxQuote characters, saying how long it was, its control characters written
// as escapes (a NUL would end the message where it stands)
std::string excerpt(const std::string& text) {
  std::string shown;
  for (char c : text.size() <= kMaxQuote ? text : text.substr(0, kMaxQuote))
    shown += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? fmt::format("\\x{:02x}", static_cast<unsigned char>(c))
                                                                 : std::string(1, c);
  if (text.size() <= kMaxQuote) return shown;
  return fmt::format("{}... ({} characters)", shown, text.size());
}

// Why `path` is not a readable regular file ("" if it is): missing, a directory or a device
// (/dev/null), or what the system says (a path too long, a symlink loop), never thrown.
std::string not_a_file(const std::filesystem::path& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) return "no such file";
  if (ec) return ec.message();
  return st.type() == fs::file_type::regular ? "" : "not a regular file";
}

[[noreturn]] void fail_key(const Scenario& sc, const std::string& path, const std::string& problem) {
  const ResolvedKey& k = sc.keys.at(path);
  // a key the scenario leaves at its default is still the scenario's: name the file
  const std::string where = k.origin == "default" ? sc.path : k.origin;
  throw InputError(fmt::format("{}: {} = {}{}: {}", excerpt(where), path, excerpt(format_value(k.value)),
                               k.origin == "default" ? " (the default)" : "", problem));
}


std::string Scenario::resolved_text() const {
  std::ostringstream out;
  out << "# resolved scenario: every key, with defaults filled in\n";
  std::string section;
  for (const KeySpec& spec : scenario_keys()) {
    const auto dot = spec.path.find('.');
    const std::string sec = dot == std::string::npos ? "" : spec.path.substr(0, dot);
    const std::string name = dot == std::string::npos ? spec.path : spec.path.substr(dot + 1);
    if (sec != section) {
      out << "\n[" << sec << "]\n";
      section = sec;
    }
    out << name << " = " << format_value(keys.at(spec.path).value);
    if (!spec.unit.empty() && spec.unit != "-") out << "  # " << spec.unit;
    out << "\n";
  }
  return out.str();
}

Scenario parse_scenario(const std::string& toml_text, const std::string& display_name,
                        const std::string& base_dir, const std::vector<std::string>& overrides) {
  Scenario sc;
  sc.path = display_name;
  sc.base_dir = base_dir;
  for (const KeySpec& spec : scenario_keys()) sc.keys[spec.path] = ResolvedKey{spec.default_value, "default"};

  if (toml_text.size() > kMaxScenarioBytes)
    throw InputError(fmt::format("{}: {} bytes; a scenario is a few kB (at most {})", display_name, toml_text.size(),
                                 kMaxScenarioBytes));
  check_nesting(toml_text, display_name);
  toml::table table;
  try {
    table = toml::parse(toml_text, display_name);
  } catch (const toml::parse_error& e) {
    const std::string key = key_on_line(toml_text, e.source().begin.line);
    throw InputError(fmt::format("{}:{}: {}TOML syntax error: {}", display_name, e.source().begin.line,
                                 key.empty() ? "" : excerpt(key) + ": ", e.description()));
  }
  std::set<std::string> overridden;
  for (const std::string& o : overrides) overridden.insert(override_key(o));
  walk(sc, table, "", display_name, overridden);
  for (const std::string& o : overrides) apply_override(sc, o);
  apply_solver_profile(sc);
  return sc;
}

Scenario read_scenario(const std::string& path, const std::vector<std::string>& overrides) {
  if (const std::string problem = not_a_file(path); !problem.empty())
    throw InputError(fmt::format("{}: not a scenario file ({})", excerpt(path), problem));
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open scenario file", path));
  std::stringstream text;
  text << in.rdbuf();
  const fs::path parent = fs::absolute(fs::path(path)).parent_path();
  return parse_scenario(text.str(), path, parent.string(), overrides);
}

}  // namespace icedem
