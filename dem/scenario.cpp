#include "dem/scenario.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dem/constants.hpp"
#include "dem/errors.hpp"
#include "dem/solver_profile.hpp"

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

// `text` cut to kMaxQuote characters, saying how long it was
std::string excerpt(const std::string& text) {
  if (text.size() <= kMaxQuote) return text;
  return fmt::format("{}... ({} characters)", text.substr(0, kMaxQuote), text.size());
}

// Why `path` is not a readable regular file ("" if it is): missing, a directory or a device
// (/dev/null), or what the system says (a path too long, a symlink loop), never thrown.
std::string not_a_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (st.type() == fs::file_type::not_found) return "no such file";
  if (ec) return ec.message();
  return st.type() == fs::file_type::regular ? "" : "not a regular file";
}

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
      if (!i || !in_range(s, static_cast<double>(i->get()))) return std::nullopt;
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

template <typename T>
const T& get(const Scenario& sc, const std::string& path) {
  return std::get<T>(sc.keys.at(path).value);
}
double real(const Scenario& sc, const std::string& path) { return get<double>(sc, path); }
int integer(const Scenario& sc, const std::string& path) {
  return static_cast<int>(get<std::int64_t>(sc, path));
}

[[noreturn]] void fail(const Scenario& sc, const std::string& path, const std::string& problem) {
  const ResolvedKey& k = sc.keys.at(path);
  // a key the scenario leaves at its default is still the scenario's: name the file
  const std::string where = k.origin == "default" ? sc.path : k.origin;
  throw InputError(fmt::format("{}: {} = {}{}: {}", excerpt(where), path, excerpt(format_value(k.value)),
                               k.origin == "default" ? " (the default)" : "", problem));
}

}  // namespace

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
    throw InputError(fmt::format("{}:{}: TOML syntax error: {}", display_name, e.source().begin.line,
                                 e.description()));
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

// What a run can do, checked before it starts, so that `check` refuses what `run` cannot:
// the number of steps and bodies (memory and time). (A hull may reach below the tank
// floor: a bottom-founded structure, or the cylinder of the flow test.)
// The bounds are far above any real scene: the paper's is 15,000 steps and 15,000 bodies.
constexpr double kMaxSteps = 2.0e7;   // Bullet steps: about 1 GB of per-step records
constexpr double kMaxBodies = 1.0e6;  // floes and elements: about 2 GB of Bullet bodies

// of keys that together break a limit, the first one the user set (else the first)
std::string blamed(const Scenario& sc, std::initializer_list<const char*> keys) {
  for (const char* k : keys)
    if (sc.keys.at(k).origin != "default") return k;
  return *keys.begin();
}

void check_limits(const Scenario& sc, const Scene& s) {
  const double steps = s.time.duration / s.time.dt * s.time.substeps;
  if (steps > kMaxSteps)
    fail(sc, blamed(sc, {"time.dt", "time.duration", "time.substeps"}), fmt::format("time.duration = {} s at this step and {} substeps is {:.3g} Bullet steps, more "
                                    "than {:.0e} a run can hold; lengthen the step or shorten the run",
                                    s.time.duration, s.time.substeps, steps, kMaxSteps));
  if (s.layout.file.empty() && s.validation.kind == ValidationCase::kNone) {
    const double floes = s.ice.concentration * s.channel.length * s.channel.width / (s.ice.floe_size * s.ice.floe_size);
    const bool breakable = s.fracture.mode == FractureMode::kOn ||
                           (s.fracture.mode == FractureMode::kAuto && s.ice.floe_size >= s.fracture.characteristic_length);
    const double per_floe = breakable ? std::pow(s.ice.floe_size / s.fracture.element_size, 2) : 1.0;
    if (floes > kMaxBodies)
      fail(sc, blamed(sc, {"ice.floe_size", "channel.length", "channel.width", "ice.concentration"}), fmt::format("{:.3g} floes of this size fill the channel, more than {:.0e}; use larger "
                                            "floes or a smaller channel", floes, kMaxBodies));
    if (floes * per_floe > kMaxBodies)
      fail(sc, "fracture.element_size", fmt::format("{:.3g} elements in {:.3g} floes, more than {:.0e} bodies; use "
                                                    "larger elements", floes * per_floe, floes, kMaxBodies));
  }
}

Scene make_scene(const Scenario& sc) {
  Scene s;
  s.source_path = sc.path;
  s.resolved_text = sc.resolved_text();
  s.seed = static_cast<std::uint64_t>(get<std::int64_t>(sc, "seed"));

  s.time = {real(sc, "time.dt"), real(sc, "time.duration"), integer(sc, "time.substeps")};
  if (s.time.duration < s.time.dt) fail(sc, "time.duration", "must be at least one time step (time.dt)");

  s.solver.iterations = integer(sc, "solver.iterations");
  s.solver.tolerance = real(sc, "solver.tolerance");
  s.solver.warm_start = real(sc, "solver.warm_start");
  s.solver.friction_warm_start = get<bool>(sc, "solver.friction_warm_start");
  s.solver.order_from_structure = get<std::string>(sc, "solver.order") == "structure";
  s.solver.sor = real(sc, "solver.sor");
  s.solver.broadphase = get<std::string>(sc, "solver.broadphase") == "sap" ? Broadphase::kSweepAndPrune : Broadphase::kDbvt;
  s.solver.split_impulse = get<bool>(sc, "solver.split_impulse");
  s.solver.contact_erp = real(sc, "solver.contact_erp");

  // structure profile: y strictly increasing, radii >= 0, some radius > 0
  s.structure.speed = real(sc, "structure.speed");
  s.structure.start_x = real(sc, "structure.start_x");
  s.structure.start_z = real(sc, "structure.start_z");
  s.structure.segments = integer(sc, "structure.segments");
  const PairList& profile = get<PairList>(sc, "structure.profile");
  bool any_radius = false;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    if (profile[i][1] < 0) fail(sc, "structure.profile", fmt::format("station {} has a negative radius", i + 1));
    if (i > 0 && !(profile[i][0] > profile[i - 1][0]))
      fail(sc, "structure.profile",
           fmt::format("station heights must increase from keel to deck (station {} is not above "
                       "station {})", i + 1, i));
    any_radius = any_radius || profile[i][1] > 0;
    s.structure.profile.push_back({profile[i][0], profile[i][1]});
  }
  if (!any_radius) fail(sc, "structure.profile", "at least one station needs a radius > 0");

  s.channel = {real(sc, "channel.start_x"), real(sc, "channel.length"), real(sc, "channel.width"),
               get<bool>(sc, "channel.end_wall"), real(sc, "tank.width"), real(sc, "tank.depth")};
  if (s.channel.width > s.channel.tank_width)
    fail(sc, "channel.width", fmt::format("wider than the tank (tank.width = {} m)", s.channel.tank_width));

  s.ice = {real(sc, "ice.floe_size"),        real(sc, "ice.thickness"),
           real(sc, "ice.concentration"),    real(sc, "ice.density"),
           real(sc, "ice.elastic_modulus"),  real(sc, "ice.bending_strength"),
           real(sc, "ice.compressive_strength"), real(sc, "ice.shear_strength"),
           real(sc, "ice.poisson_ratio"),    get<bool>(sc, "ice.contact_crushing")};
  s.water = {real(sc, "water.density"),          real(sc, "water.gravity"),
             real(sc, "water.drag_coefficient"), real(sc, "water.skin_friction_coefficient"),
             real(sc, "water.heave_damping_ratio"), real(sc, "water.roll_pitch_damping_ratio")};
  if (s.ice.density >= s.water.density)
    fail(sc, "ice.density", fmt::format("ice must be lighter than water (water.density = {} kg/m^3)",
                                        s.water.density));
  if (s.ice.floe_size >= s.channel.width)
    fail(sc, "ice.floe_size", fmt::format("floes must be smaller than the channel (channel.width = {} m)",
                                          s.channel.width));

  // layout file paths are relative to the scenario file
  std::string file = get<std::string>(sc, "layout.file");
  if (!file.empty()) {
    fs::path p(file);
    if (p.is_relative()) p = fs::path(sc.base_dir) / p;
    if (const std::string problem = not_a_file(p); !problem.empty())
      fail(sc, "layout.file", fmt::format("{} ({})", problem, excerpt(p.string())));
    file = p.string();
  }
  s.layout = {file, real(sc, "layout.max_yaw_deg") * kPi / 180.0, integer(sc, "layout.sweeps"),
              real(sc, "layout.min_gap"), integer(sc, "layout.layers")};
  if (s.layout.layers > 1 && !s.layout.file.empty())
    fail(sc, "layout.layers", "1 with a layout.file (layers stack generated fields only)");

  s.friction = {real(sc, "friction.ice_ice"), real(sc, "friction.ice_structure")};

  const std::string& flow = get<std::string>(sc, "flow.model");
  s.flow.model = flow == "still"     ? FlowModel::kStill
                 : flow == "uniform" ? FlowModel::kUniform
                 : flow == "coupled" ? FlowModel::kCoupled
                                     : FlowModel::kPotential;
  const Vector3Value& u = get<Vector3Value>(sc, "flow.velocity");
  s.flow.velocity = Eigen::Vector3d(u[0], u[1], u[2]);
  std::string cache = get<std::string>(sc, "coupling.cache_dir");
  if (cache.empty()) {
    const char* env = std::getenv("ICEDEM_FOAM_CACHE");
    const char* home = std::getenv("HOME");
    cache = env && *env ? env : (fs::path(home && *home ? home : "/tmp") / ".cache" / "icedem" / "foam").string();
  } else if (fs::path(cache).is_relative()) {
    cache = (fs::path(sc.base_dir) / cache).string();
  }
  s.coupling = {get<std::string>(sc, "coupling.mode") == "probe" ? CouplingMode::kProbe : CouplingMode::kField,
                get<std::string>(sc, "coupling.mesh"), cache, real(sc, "coupling.domain_length"),
                real(sc, "coupling.grid_spacing"), real(sc, "coupling.grid_depth"),
                integer(sc, "coupling.exchange_steps"), real(sc, "coupling.timeout"),
                get<std::string>(sc, "coupling.exchange_dir"), get<std::string>(sc, "coupling.partner") == "spawn"};
  if (!s.coupling.exchange_dir.empty() && fs::path(s.coupling.exchange_dir).is_relative())
    s.coupling.exchange_dir = (fs::path(sc.base_dir) / s.coupling.exchange_dir).string();
  if (!s.coupling.spawn_partner && s.coupling.exchange_dir.empty() && s.coupling.mode == CouplingMode::kProbe)
    fail(sc, "coupling.exchange_dir", "a directory shared with the external partner (coupling.partner = \"external\")");

  // the ice's derived properties, computed here once
  s.ice.draft = s.ice.thickness * s.ice.density / s.water.density;
  s.ice.flexural_rigidity = s.ice.elastic_modulus * std::pow(s.ice.thickness, 3) /
                            (12.0 * (1.0 - s.ice.poisson_ratio * s.ice.poisson_ratio));
  // characteristic length l_c = (D / (rho_w g))^(1/4): "auto" makes only floes at least this
  // large breakable
  const double D = s.ice.flexural_rigidity;
  const std::string& fracture = get<std::string>(sc, "fracture.mode");
  s.fracture = {fracture == "on" ? FractureMode::kOn : fracture == "auto" ? FractureMode::kAuto
                                                                           : FractureMode::kOff,
                real(sc, "fracture.element_size"), real(sc, "fracture.cfm"), real(sc, "fracture.erp"),
                std::pow(D / (s.water.density * s.water.gravity), 0.25),
                integer(sc, "fracture.joint_iterations"), real(sc, "fracture.load_filter_time"),
                real(sc, "fracture.lattice_radius")};
  const bool breakable = s.fracture.mode == FractureMode::kOn ||
                         (s.fracture.mode == FractureMode::kAuto && s.ice.floe_size >= s.fracture.characteristic_length);
  if (breakable && s.layout.file.empty() && get<std::string>(sc, "validation.case") == "none") {
    // generated square floes must be a whole number of elements across
    const double n = s.ice.floe_size / s.fracture.element_size;
    if (std::abs(n - std::round(n)) > 1e-6)
      fail(sc, "fracture.element_size",
           fmt::format("ice.floe_size = {} m is not a whole number of elements ({:.3f}); choose an element size "
                       "that divides the floe size", s.ice.floe_size, n));
  }

  s.activation = {get<bool>(sc, "activation.sleeping"),
                  get<std::string>(sc, "activation.islands") == "bullet" ? IslandMode::kBullet
                                                                         : IslandMode::kContact,
                  get<bool>(sc, "activation.skip_asleep"),
                  real(sc, "activation.linear_threshold"), real(sc, "activation.angular_threshold"),
                  real(sc, "activation.time"),
                  get<bool>(sc, "activation.freeze_outside_region"),
                  real(sc, "activation.region_ahead"),
                  real(sc, "activation.region_behind")};
  // a floe touching the hull must never be frozen: the solver cannot resolve a
  // contact between the kinematic hull and a fixed obstacle
  double hull_radius = 0;
  for (const ProfileStation& st : s.structure.profile) hull_radius = std::max(hull_radius, st.radius);
  const double reach = hull_radius + std::sqrt(2.0) * s.ice.floe_size;
  for (const char* key : {"activation.region_ahead", "activation.region_behind"})
    if (s.activation.freeze_outside_region && real(sc, key) < reach)
      fail(sc, key, fmt::format("must be at least the hull radius plus a floe diagonal ({:.3f} m), so that "
                                "no floe touching the structure is frozen", reach));
  s.output = {real(sc, "output.snapshot_interval")};
  s.stats = {real(sc, "stats.window_start_travel"), real(sc, "stats.window_end_travel"),
             real(sc, "stats.lowpass_hz")};
  const std::string& vcase = get<std::string>(sc, "validation.case");
  s.validation = {vcase == "plate_deflection" ? ValidationCase::kPlateDeflection
                  : vcase == "cantilever"     ? ValidationCase::kCantilever
                                              : ValidationCase::kNone,
                  real(sc, "validation.plate_size"), real(sc, "validation.load"), real(sc, "validation.tolerance"),
                  integer(sc, "validation.beam_elements"), real(sc, "validation.load_rate"),
                  real(sc, "validation.tip_speed")};
  if (s.validation.kind != ValidationCase::kNone && s.fracture.mode != FractureMode::kOn)
    fail(sc, "fracture.mode", fmt::format("the {} case needs ice elements: set fracture.mode = \"on\"", vcase));
  if (s.validation.kind == ValidationCase::kPlateDeflection) {
    const double n = s.validation.plate_size / s.fracture.element_size;
    if (std::abs(n - std::round(n)) > 1e-6)
      fail(sc, "validation.plate_size", fmt::format("is not a whole number of elements of fracture.element_size = {} m "
                                                    "({:.3f})", s.fracture.element_size, n));
  }
  if (s.stats.lowpass_hz > 0 && s.stats.lowpass_hz >= 0.5 / s.time.dt)
    fail(sc, "stats.lowpass_hz", fmt::format("must be below the Nyquist frequency 1/(2 dt) = {} Hz", 0.5 / s.time.dt));
  if (s.stats.window_end_travel > 0 && s.stats.window_end_travel <= s.stats.window_start_travel)
    fail(sc, "stats.window_end_travel", "must be beyond stats.window_start_travel (or 0 for the end of the run)");
  check_limits(sc, s);
  return s;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return make_scene(read_scenario(path, overrides));
}

}  // namespace icedem
