// Scenario -> Scene (dem/input/scene_builder.hpp).
#include "dem/input/scene_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "dem/contact/registry.hpp"
#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/input/scenario.hpp"

namespace icedem {
namespace {

namespace fs = std::filesystem;

template <typename T>
const T& get(const Scenario& sc, const std::string& path) {
  return std::get<T>(sc.keys.at(path).value);
}
double real(const Scenario& sc, const std::string& path) { return get<double>(sc, path); }
int integer(const Scenario& sc, const std::string& path) {
  return static_cast<int>(get<std::int64_t>(sc, path));
}


// a count of elements that is a whole number (up to the decimals a scenario is written in),
// at least one (a side far below an element rounds to 0)
bool whole(double n) { return n >= 1 - 1e-6 && std::abs(n - std::round(n)) <= 1e-6; }

// The value of a choice key as its Scene type. `names` maps every name the key table allows,
// and no other, to its value: a name added to the table but not here (or the reverse) is a
// programming error, thrown by the first scene built, never a silent default.
template <typename T>
T choice(const Scenario& sc, const char* path, std::initializer_list<std::pair<const char*, T>> names) {
  const KeySpec* spec = find_key(path);
  bool same = spec && spec->type == KeyType::kChoice && spec->choices.size() == names.size();
  for (const auto& [name, value] : names)
    same = same && std::find(spec->choices.begin(), spec->choices.end(), name) != spec->choices.end();
  if (!same)
    throw std::logic_error(fmt::format("make_scene: the names mapped for '{}' are not the choices the key table "
                                       "declares (dem/input/scenario_keys.cpp)", path));
  const std::string& given = get<std::string>(sc, path);
  for (const auto& [name, value] : names)
    if (given == name) return value;
  throw std::logic_error(fmt::format("make_scene: '{}' = \"{}\" passed the key table but has no value", path, given));
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
    fail_key(sc, blamed(sc, {"time.dt", "time.duration", "time.substeps"}), fmt::format("time.duration = {} s at this step and {} substeps is {:.3g} Bullet steps, more "
                                    "than {:.0e} a run can hold; lengthen the step or shorten the run",
                                    s.time.duration, s.time.substeps, steps, kMaxSteps));
  // a hexagon of element_size across flats holds sqrt(3)/2 of that square's area
  const double per_cell = s.fracture.element_shape == ElementShape::kHexagon ? 2.0 / std::sqrt(3.0) : 1.0;
  if (s.ice.cover == IceCover::kLevel) {
    const double elements = per_cell * s.channel.length * s.channel.width / std::pow(s.fracture.element_size, 2);
    if (elements > kMaxBodies)
      fail_key(sc, blamed(sc, {"fracture.element_size", "channel.length", "channel.width"}),
               fmt::format("{:.3g} elements of level ice fill the channel, more than {:.0e} bodies; use larger "
                           "elements or a smaller channel", elements, kMaxBodies));
  } else if (s.layout.file.empty() && s.validation.kind == ValidationKind::kNone) {
    const double floes = s.ice.concentration * s.channel.length * s.channel.width / (s.ice.floe_size * s.ice.floe_size);
    const double per_floe =
        generated_floes_breakable(s) ? per_cell * std::pow(s.ice.floe_size / s.fracture.element_size, 2) : 1.0;
    if (floes > kMaxBodies)
      fail_key(sc, blamed(sc, {"ice.floe_size", "channel.length", "channel.width", "ice.concentration"}), fmt::format("{:.3g} floes of this size fill the channel, more than {:.0e}; use larger "
                                            "floes or a smaller channel", floes, kMaxBodies));
    if (floes * per_floe > kMaxBodies)
      fail_key(sc, "fracture.element_size", fmt::format("{:.3g} elements in {:.3g} floes, more than {:.0e} bodies; use "
                                                    "larger elements", floes * per_floe, floes, kMaxBodies));
  }
}

// The moored structure's body and mooring (structure.motion = "moored"): what the keys give, with
// the derived values (the hull's own mass and inertia, the added-mass estimate) left to
// dem/mooring/floating_structure.cpp, which reads the sentinels the key table documents (values no
// body has: a mass or inertia of 0, a negative added mass), so that a run's resolved scenario, which
// writes every key, makes the same body.
Eigen::Vector3d vector3(const Scenario& sc, const std::string& path) {
  const Vector3Value& v = get<Vector3Value>(sc, path);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

void read_floating_structure(const Scenario& sc, Scene& s) {
  StructureSettings& st = s.structure;
  st.mass = real(sc, "structure.mass");
  st.gravity_centre_y = real(sc, "structure.gravity_centre_y");
  st.inertia = vector3(sc, "structure.inertia");
  st.added_mass = vector3(sc, "structure.added_mass");
  st.added_inertia = vector3(sc, "structure.added_inertia");
  st.damping_ratio = vector3(sc, "structure.damping_ratio");
  st.angular_damping_ratio = vector3(sc, "structure.angular_damping_ratio");
  MooringSettings& m = s.mooring;
  m.model = choice<MooringModel>(sc, "mooring.model", {{"linear", MooringModel::kLinear}, {"catenary", MooringModel::kCatenary}});
  m.attachment_y = real(sc, "mooring.attachment_y");
  m.stiffness = vector3(sc, "mooring.stiffness");
  m.angular_stiffness = vector3(sc, "mooring.angular_stiffness");
  m.lines = integer(sc, "mooring.lines");
  m.first_line_angle = real(sc, "mooring.first_line_angle") * kPi / 180.0;
  m.fairlead_radius = real(sc, "mooring.fairlead_radius");
  m.fairlead_y = real(sc, "mooring.fairlead_y");
  m.anchor_radius = real(sc, "mooring.anchor_radius");
  m.line_length = real(sc, "mooring.line_length");
  m.line_weight = real(sc, "mooring.line_weight");
  m.line_stiffness = real(sc, "mooring.line_stiffness");
  m.seabed_friction = real(sc, "mooring.seabed_friction");
}

}  // namespace

// The structure can meet the ice and stays within the tank: a hull wholly above the floating ice
// (or under it) tows through nothing, and a hull through the tank's side (where it meets the ice,
// or anywhere from its keel to its deck) cannot be built (a tow
// scene; validation cases park the structure away from their plate). A keel below the bottom is a
// warning (dem/input/setting_warnings.hpp): a structure standing on the floor is one
void check_structure_in_tank(const Scenario& sc, const Scene& s) {
  const std::vector<ProfileStation>& hull = s.structure.profile;
  const double keel = hull.front().y, deck = hull.back().y;
  const double ice_bottom = -s.ice.draft, ice_top = s.ice.thickness - s.ice.draft;
  if (keel >= ice_top || deck <= ice_bottom)
    fail_key(sc, "structure.profile",
             fmt::format("the hull spans y = {} to {} m and the ice floats from y = {:.4f} to {:.4f} m: the structure "
                         "would pass {} the ice without meeting it",
                         keel, deck, ice_bottom, ice_top, keel >= ice_top ? "above" : "under"));
  const double r = hull_radius_in_ice(s);
  if (std::abs(s.structure.start_z) + r > 0.5 * s.channel.tank_width)
    fail_key(sc, "structure.start_z",
             fmt::format("the hull (radius {:.3f} m where it meets the ice) at z = {} m reaches beyond the tank's "
                         "side at |z| = {} m (tank.width / 2)",
                         r, s.structure.start_z, 0.5 * s.channel.tank_width));
  // the whole hull, above and below the ice too: the tank's walls stand above the water and reach
  // its bottom
  const double widest = hull_radius_over(hull, keel, deck);
  if (std::abs(s.structure.start_z) + widest > 0.5 * s.channel.tank_width)
    fail_key(sc, blamed(sc, {"structure.profile", "structure.start_z", "tank.width"}),
             fmt::format("the hull's widest part (radius {:.3f} m) at z = {} m (structure.start_z) reaches beyond "
                         "the tank's side at |z| = {} m (tank.width / 2): it does not fit in the tank",
                         widest, s.structure.start_z, 0.5 * s.channel.tank_width));
}

// Level ice (ice.cover = "level", dem/fracture/level_ice.hpp): a breakable sheet that moves near
// the structure and is held beyond, built from the channel alone
void check_level_ice(const Scenario& sc, const Scene& s) {
  const std::string why = "ice.cover = \"level\" ";
  if (s.validation.kind != ValidationKind::kNone)
    fail_key(sc, "ice.cover", "\"floes\" for a validation case: its plate or beam is the only ice");
  if (s.fracture.mode != FractureMode::kOn && s.fracture.mode != FractureMode::kAnalytic)
    fail_key(sc, "fracture.mode",
             "\"on\" (a lattice of breakable elements) or \"analytic\" (one sheet cut by closed forms) with " + why);
  if (!s.layout.file.empty())
    fail_key(sc, "layout.file", "empty with " + why + "(the sheet fills the channel; a layout is of floes)");
  if (s.layout.layers > 1) fail_key(sc, "layout.layers", "1 with " + why + "(one sheet)");
  if (s.fracture.mode == FractureMode::kAnalytic) {
    // the sheet is held and its crushed zones bear the crushing force as long as they overlap the hull: a
    // hull that advances; a moored one, which can back off, would be pushed back by ice already crushed
    if (s.structure.motion != StructureMotion::kTowed)
      fail_key(sc, "structure.motion", "\"towed\" with " + why + "and fracture.mode = \"analytic\" (the held sheet's "
                                       "crushing load is for a hull that advances into it)");
    const double top = s.ice.thickness - s.ice.draft, bottom = -s.ice.draft;
    const double flare = std::abs(profile_radius(s.structure.profile, top) - profile_radius(s.structure.profile, bottom));
    if (flare < kSteepestSheetFlare * s.ice.thickness)
      fail_key(sc, "structure.profile",
               fmt::format("a sloping hull where the ice meets it with {}and fracture.mode = \"analytic\": its radius "
                           "changes by {:.4f} m across the ice's thickness, a wall that crushes the ice and does not bend it",
                           why, flare));
    // the floes' pushes on the sheet's edge are bounded by its breaking load inside the solve
    // (dem/fracture/sheet_edge_bound.hpp), as the crushing law bounds a contact's
    if (!takes_crushing(s.solver.method))
      fail_key(sc, blamed(sc, {"solver.method", "fracture.mode"}),
               "a contact method that takes a bound on a contact's normal force (\"apgd\", \"newton\" or "
               "\"pgs_cone\") with " + why + "and fracture.mode = \"analytic\": the floes' pushes on the sheet's edge "
               "are bounded by its breaking load; solver.method = \"" + s.solver.method + "\" does not take it");
    return;  // the rest is the lattice's
  }
  if (s.water.added_mass)
    fail_key(sc, "water.added_mass", "false with " + why + "(the added mass is a floe's, of its whole outline; a "
                                     "sheet's has no such model here)");
  if (s.activation.freeze_outside_region)
    fail_key(sc, "activation.freeze_outside_region",
             "false with " + why + "(the sheet is held beyond fracture.lattice_radius by its own rule)");
  // the sheet moves within the radius: it must reach past the elements the hull can touch
  const double reach = hull_radius_in_ice(s) + 2 * s.fracture.element_size;
  if (s.fracture.lattice_radius < reach)
    fail_key(sc, "fracture.lattice_radius",
             fmt::format("at least the hull's radius in the ice plus two elements ({:.3f} m) with {}: level ice "
                         "moves within this distance of the structure axis and is held where it lies beyond it "
                         "(a few characteristic lengths, {:.3f} m here, keep the held edge from stiffening the "
                         "sheet the structure bends)",
                         reach, why, s.fracture.characteristic_length));
}

Scene make_scene(const Scenario& sc) {
  Scene s;
  s.source_path = sc.path;
  s.resolved_text = sc.resolved_text();
  s.seed = static_cast<std::uint64_t>(get<std::int64_t>(sc, "seed"));

  s.time.dt = real(sc, "time.dt");
  s.time.duration = real(sc, "time.duration");
  s.time.substeps = integer(sc, "time.substeps");
  if (s.time.duration < s.time.dt) fail_key(sc, "time.duration", "must be at least one time step (time.dt)");

  s.solver.iterations = integer(sc, "solver.iterations");
  s.solver.tolerance = real(sc, "solver.tolerance");
  s.solver.warm_start = real(sc, "solver.warm_start");
  s.solver.friction_warm_start = get<bool>(sc, "solver.friction_warm_start");
  s.solver.order = choice<SweepOrder>(
      sc, "solver.order",
      {{"bullet", SweepOrder::kBullet}, {"canonical", SweepOrder::kCanonical}, {"structure", SweepOrder::kFromStructure}});
  s.solver.sor = real(sc, "solver.sor");
  s.solver.broadphase =
      choice<Broadphase>(sc, "solver.broadphase", {{"dbvt", Broadphase::kDbvt}, {"sap", Broadphase::kSweepAndPrune}});
  s.solver.split_impulse = get<bool>(sc, "solver.split_impulse");
  s.solver.contact_erp = real(sc, "solver.contact_erp");
  s.solver.method = get<std::string>(sc, "solver.method");
  s.solver.merit_tolerance = real(sc, "solver.merit_tolerance");
  s.solver.merit = get<std::string>(sc, "solver.merit");
  s.solver.joint_merit_tolerance = real(sc, "solver.joint_merit_tolerance");
  s.solver.structure_merit_tolerance = real(sc, "solver.structure_merit_tolerance");
  s.solver.breaking_merit_tolerance = real(sc, "solver.breaking_merit_tolerance");
  s.solver.breaking_ratio = real(sc, "solver.breaking_ratio");
  s.solver.breaking_check_tolerance = real(sc, "solver.breaking_check_tolerance");
  s.solver.breaking_check_band = real(sc, "solver.breaking_check_band");
  s.solver.breaking_iterations = integer(sc, "solver.breaking_iterations");
  s.solver.method_iterations = integer(sc, "solver.method_iterations");
  s.solver.handover_method = get<std::string>(sc, "solver.handover_method");
  s.solver.handover_iterations = integer(sc, "solver.handover_iterations");
  s.solver.position_iterations = integer(sc, "solver.position_iterations");

  // structure profile: y strictly increasing, radii >= 0, some radius > 0
  s.structure.motion =
      choice<StructureMotion>(sc, "structure.motion", {{"towed", StructureMotion::kTowed}, {"moored", StructureMotion::kMoored}});
  s.structure.speed = real(sc, "structure.speed");
  s.structure.start_x = real(sc, "structure.start_x");
  s.structure.start_z = real(sc, "structure.start_z");
  s.structure.segments = integer(sc, "structure.segments");
  s.structure.collision_margin = real(sc, "structure.collision_margin");
  const PairList& profile = get<PairList>(sc, "structure.profile");
  bool any_radius = false;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    if (profile[i][1] < 0) fail_key(sc, "structure.profile", fmt::format("station {} has a negative radius", i + 1));
    if (i > 0 && !(profile[i][0] > profile[i - 1][0]))
      fail_key(sc, "structure.profile",
               fmt::format("station heights must increase from keel to deck (station {} is not above "
                           "station {})", i + 1, i));
    any_radius = any_radius || profile[i][1] > 0;
    s.structure.profile.push_back({profile[i][0], profile[i][1]});
  }
  if (!any_radius) fail_key(sc, "structure.profile", "at least one station needs a radius > 0");
  read_floating_structure(sc, s);

  s.channel.start_x = real(sc, "channel.start_x");
  s.channel.length = real(sc, "channel.length");
  s.channel.width = real(sc, "channel.width");
  s.channel.end_wall = get<bool>(sc, "channel.end_wall");
  s.channel.edge_friction_factor = real(sc, "channel.edge_friction_factor");
  s.channel.tank_width = real(sc, "tank.width");
  s.channel.tank_depth = real(sc, "tank.depth");
  if (s.channel.width > s.channel.tank_width)
    fail_key(sc, "channel.width", fmt::format("wider than the tank (tank.width = {} m)", s.channel.tank_width));

  s.ice.cover = choice<IceCover>(sc, "ice.cover", {{"floes", IceCover::kFloes}, {"level", IceCover::kLevel}});
  s.ice.floe_size = real(sc, "ice.floe_size");
  s.ice.thickness = real(sc, "ice.thickness");
  s.ice.concentration = real(sc, "ice.concentration");
  s.ice.density = real(sc, "ice.density");
  s.ice.elastic_modulus = real(sc, "ice.elastic_modulus");
  s.ice.bending_strength = real(sc, "ice.bending_strength");
  s.ice.compressive_strength = real(sc, "ice.compressive_strength");
  s.ice.shear_strength = real(sc, "ice.shear_strength");
  s.ice.poisson_ratio = real(sc, "ice.poisson_ratio");
  s.ice.contact_crushing = get<bool>(sc, "ice.contact_crushing");

  s.contact.model = choice<ContactModel>(sc, "contact.model",
                                        {{"rigid", ContactModel::kRigid}, {"crushing", ContactModel::kCrushing}});
  s.contact.pressure_area_exponent = real(sc, "contact.pressure_area_exponent");
  s.contact.crushing_contacts = choice<CrushingContacts>(
      sc, "contact.crushing_contacts",
      {{"structure", CrushingContacts::kStructure},
       {"structure_and_sheet", CrushingContacts::kStructureAndSheet},
       {"all", CrushingContacts::kAll}});
  if (s.contact.model == ContactModel::kCrushing && s.ice.contact_crushing)
    fail_key(sc, blamed(sc, {"ice.contact_crushing", "contact.model"}),
             "ice.contact_crushing (a fixed cap) and contact.model = \"crushing\" (the crushing law) are two "
             "models of the same thing: choose one");
  if (s.ice.contact_crushing && s.solver.method != kBulletSweeps)
    fail_key(sc, blamed(sc, {"solver.method", "ice.contact_crushing"}),
             "ice.contact_crushing caps the contact rows of the Gauss-Seidel sweeps; solver.method = \"" +
                 s.solver.method + "\" has no such cap: use solver.method = \"pgs\" with it");
  if (s.contact.model == ContactModel::kCrushing) {
    if (!takes_crushing(s.solver.method))
      fail_key(sc, blamed(sc, {"solver.method", "contact.model"}),
               "contact.model = \"crushing\" bounds each contact's normal force, which solver.method = \"" +
                   s.solver.method + "\" does not take: use \"apgd\", \"newton\" or \"pgs_cone\"");
    if (!s.solver.split_impulse)
      fail_key(sc, blamed(sc, {"solver.split_impulse", "contact.model"}),
               "contact.model = \"crushing\" needs solver.split_impulse = true: without it Bullet pushes the "
               "overlap, which is crushed ice, apart inside the contact impulses");
  }

  s.water.density = real(sc, "water.density");
  s.water.gravity = real(sc, "water.gravity");
  s.water.drag_coefficient = real(sc, "water.drag_coefficient");
  s.water.skin_friction_coefficient = real(sc, "water.skin_friction_coefficient");
  s.water.heave_damping_ratio = real(sc, "water.heave_damping_ratio");
  s.water.added_mass = get<bool>(sc, "water.added_mass");
  s.water.linear_buoyancy = choice<bool>(sc, "water.buoyancy", {{"exact", false}, {"linear", true}});
  s.water.roll_pitch_damping_ratio = real(sc, "water.roll_pitch_damping_ratio");
  if (s.ice.density >= s.water.density)
    fail_key(sc, "ice.density", fmt::format("ice must be lighter than water (water.density = {} kg/m^3)",
                                            s.water.density));
  if (s.ice.cover == IceCover::kFloes && s.ice.floe_size >= s.channel.width)
    fail_key(sc, "ice.floe_size", fmt::format("floes must be smaller than the channel (channel.width = {} m)",
                                              s.channel.width));

  // layout file paths are relative to the scenario file
  std::string file = get<std::string>(sc, "layout.file");
  if (!file.empty()) {
    fs::path p(file);
    if (p.is_relative()) p = fs::path(sc.base_dir) / p;
    if (const std::string problem = not_a_file(p); !problem.empty())
      fail_key(sc, "layout.file", fmt::format("{} ({})", problem, excerpt(p.string())));
    file = p.string();
  }
  s.layout.file = file;
  s.layout.max_yaw = real(sc, "layout.max_yaw_deg") * kPi / 180.0;
  s.layout.sweeps = integer(sc, "layout.sweeps");
  s.layout.min_gap = real(sc, "layout.min_gap");
  s.layout.size_spread = real(sc, "layout.size_spread");
  if (s.layout.size_spread > 0 && !s.layout.file.empty())
    fail_key(sc, "layout.size_spread", "0 with a layout.file (the file gives each floe's size)");
  s.layout.layers = integer(sc, "layout.layers");
  if (s.layout.layers > 1 && !s.layout.file.empty())
    fail_key(sc, "layout.layers", "1 with a layout.file (layers stack generated fields only)");

  s.friction.ice_ice = real(sc, "friction.ice_ice");
  s.friction.ice_structure = real(sc, "friction.ice_structure");
  s.friction.ice_ice_static = real(sc, "friction.ice_ice_static");
  s.friction.ice_structure_static = real(sc, "friction.ice_structure_static");
  s.friction.stick_speed = real(sc, "friction.stick_speed");
  // a static coefficient below the kinetic one would make a sticking contact easier to move
  // than a sliding one
  for (const auto& [key, stat, kinetic] : {std::tuple{"friction.ice_ice_static", s.friction.ice_ice_static, s.friction.ice_ice},
                                            std::tuple{"friction.ice_structure_static", s.friction.ice_structure_static,
                                                       s.friction.ice_structure}})
    if (stat > 0 && stat < kinetic)
      fail_key(sc, key, fmt::format("0 (none) or at least the kinetic coefficient {} (static friction is never "
                                    "below kinetic)", kinetic));

  s.flow.model = choice<FlowModel>(sc, "flow.model",
                                   {{"still", FlowModel::kStill}, {"uniform", FlowModel::kUniform},
                                    {"potential", FlowModel::kPotential}, {"coupled", FlowModel::kCoupled}});
  const Vector3Value& u = get<Vector3Value>(sc, "flow.velocity");
  s.flow.velocity = Eigen::Vector3d(u[0], u[1], u[2]);

  // solved OpenFOAM cases are kept by the hash of their inputs, shared between runs
  std::string cache = get<std::string>(sc, "coupling.cache_dir");
  if (cache.empty()) {
    const char* env = std::getenv("ICEDEM_FOAM_CACHE");
    const char* home = std::getenv("HOME");
    cache = env && *env ? env : (fs::path(home && *home ? home : "/tmp") / ".cache" / "icedem" / "foam").string();
  } else if (fs::path(cache).is_relative()) {
    cache = (fs::path(sc.base_dir) / cache).string();
  }
  s.coupling.mode = choice<CouplingMode>(sc, "coupling.mode", {{"field", CouplingMode::kField}, {"probe", CouplingMode::kProbe}});
  s.coupling.mesh = choice<std::string>(sc, "coupling.mesh", {{"coarse", "coarse"}, {"medium", "medium"}, {"fine", "fine"}});
  s.coupling.cache_dir = cache;
  s.coupling.domain_length = real(sc, "coupling.domain_length");
  s.coupling.grid_spacing = real(sc, "coupling.grid_spacing");
  s.coupling.grid_depth = real(sc, "coupling.grid_depth");
  s.coupling.exchange_steps = integer(sc, "coupling.exchange_steps");
  s.coupling.timeout = real(sc, "coupling.timeout");
  s.coupling.exchange_dir = get<std::string>(sc, "coupling.exchange_dir");
  s.coupling.spawn_partner = choice<bool>(sc, "coupling.partner", {{"spawn", true}, {"external", false}});
  if (!s.coupling.exchange_dir.empty() && fs::path(s.coupling.exchange_dir).is_relative())
    s.coupling.exchange_dir = (fs::path(sc.base_dir) / s.coupling.exchange_dir).string();
  if (!s.coupling.spawn_partner && s.coupling.exchange_dir.empty() && s.coupling.mode == CouplingMode::kProbe)
    fail_key(sc, "coupling.exchange_dir", "a directory shared with the external partner (coupling.partner = \"external\")");

  // the ice's derived properties, computed here once
  s.ice.draft = s.ice.thickness * s.ice.density / s.water.density;
  s.ice.flexural_rigidity = s.ice.elastic_modulus * std::pow(s.ice.thickness, 3) /
                            (12.0 * (1.0 - s.ice.poisson_ratio * s.ice.poisson_ratio));

  s.fracture.mode = choice<FractureMode>(sc, "fracture.mode",
                                         {{"off", FractureMode::kOff},
                                          {"on", FractureMode::kOn},
                                          {"auto", FractureMode::kAuto},
                                          {"analytic", FractureMode::kAnalytic}});
  s.fracture.element_size = real(sc, "fracture.element_size");
  s.fracture.element_shape =
      choice<ElementShape>(sc, "fracture.element_shape", {{"square", ElementShape::kSquare}, {"hexagon", ElementShape::kHexagon}});
  s.fracture.tiling = choice<Tiling>(sc, "fracture.tiling", {{"corner", Tiling::kCorner}, {"fitted", Tiling::kFitted}});
  s.fracture.lattice_angle = real(sc, "fracture.lattice_angle") * kPi / 180.0;
  s.fracture.cfm = real(sc, "fracture.cfm");
  s.fracture.erp = real(sc, "fracture.erp");
  s.fracture.elastic_joints = choice<bool>(sc, "fracture.joint_stiffness", {{"cfm", false}, {"elastic", true}});
  s.fracture.stiffness_scale = real(sc, "fracture.stiffness_scale");
  s.fracture.strength_scale = real(sc, "fracture.strength_scale");
  // characteristic length l_c = (D / (rho_w g))^(1/4): "auto" makes only floes at least this
  // large breakable
  s.fracture.characteristic_length = std::pow(s.ice.flexural_rigidity / (s.water.density * s.water.gravity), 0.25);
  s.fracture.joint_iterations = integer(sc, "fracture.joint_iterations");
  s.fracture.load_filter_time = real(sc, "fracture.load_filter_time");
  s.fracture.lattice_radius = real(sc, "fracture.lattice_radius");

  s.validation.kind = choice<ValidationKind>(sc, "validation.case",
                                             {{"none", ValidationKind::kNone},
                                              {"plate_deflection", ValidationKind::kPlateDeflection},
                                              {"cantilever", ValidationKind::kCantilever},
                                              {"wide_cantilever", ValidationKind::kWideCantilever}});
  s.validation.plate_size = real(sc, "validation.plate_size");
  s.validation.load = real(sc, "validation.load");
  s.validation.tolerance = real(sc, "validation.tolerance");
  s.validation.beam_elements = integer(sc, "validation.beam_elements");
  s.validation.beam_length = real(sc, "validation.beam_length");
  s.validation.beam_width = real(sc, "validation.beam_width");
  s.validation.load_rate = real(sc, "validation.load_rate");
  s.validation.tip_speed = real(sc, "validation.tip_speed");
  s.validation.plate_load =
      choice<PlateLoad>(sc, "validation.plate_load", {{"down", PlateLoad::kDown}, {"along", PlateLoad::kAlong}});

  // a lattice is a whole number of elements across; floes of any size stay rigid
  if (s.ice.cover == IceCover::kFloes && s.layout.size_spread > 0 && generated_floes_breakable(s))
    fail_key(sc, "layout.size_spread",
             fmt::format("0 with breakable floes (fracture.mode = \"on\", or \"auto\" with floes up to {:.3g} m against "
                         "the characteristic length {:.3g} m): a lattice needs a whole number of elements across; "
                         "a spread of sizes is for rigid floes (fracture.mode \"off\" or \"analytic\")",
                         largest_generated_floe(s), s.fracture.characteristic_length));
  if (s.ice.cover == IceCover::kFloes && generated_floes_breakable(s) && s.layout.file.empty() &&
      s.validation.kind == ValidationKind::kNone &&
      s.fracture.element_shape == ElementShape::kSquare && s.fracture.lattice_angle == 0) {
    // generated square floes must be a whole number of square elements across (the paper's lattice)
    if (const double n = s.ice.floe_size / s.fracture.element_size; !whole(n))
      fail_key(sc, "fracture.element_size",
               fmt::format("ice.floe_size = {} m is not a whole number of elements ({:.3f}); choose an element size "
                           "that divides the floe size", s.ice.floe_size, n));
  }

  s.activation.sleeping = get<bool>(sc, "activation.sleeping");
  s.activation.islands =
      choice<IslandMode>(sc, "activation.islands", {{"contact", IslandMode::kContact}, {"bullet", IslandMode::kBullet}});
  s.activation.skip_asleep = get<bool>(sc, "activation.skip_asleep");
  s.activation.linear_threshold = real(sc, "activation.linear_threshold");
  s.activation.angular_threshold = real(sc, "activation.angular_threshold");
  s.activation.time = real(sc, "activation.time");
  s.activation.unreached_out_of_world = get<bool>(sc, "activation.unreached_out_of_world");
  s.activation.freeze_outside_region = get<bool>(sc, "activation.freeze_outside_region");
  s.activation.region_ahead = real(sc, "activation.region_ahead");
  s.activation.region_behind = real(sc, "activation.region_behind");
  s.activation.leave_behind = real(sc, "activation.leave_behind");
  // a floe touching the hull must never be frozen: the solver cannot resolve a
  // contact between the kinematic hull and a fixed obstacle
  double hull_radius = 0;
  for (const ProfileStation& st : s.structure.profile) hull_radius = std::max(hull_radius, st.radius);
  const double reach = hull_radius + std::sqrt(2.0) * s.ice.floe_size;
  for (const char* key : {"activation.region_ahead", "activation.region_behind"})
    if (s.activation.freeze_outside_region && real(sc, key) < reach)
      fail_key(sc, key, fmt::format("must be at least the hull radius plus a floe diagonal ({:.3f} m), so that "
                                    "no floe touching the structure is frozen", reach));
  if (s.activation.leave_behind > 0 && s.activation.leave_behind < hull_radius)
    fail_key(sc, "activation.leave_behind",
             fmt::format("must be 0 or at least the hull's largest radius ({:.3f} m), so that no floe touching the "
                         "structure leaves the run", hull_radius));

  s.output.snapshot_interval = real(sc, "output.snapshot_interval");
  s.output.checkpoint_interval = real(sc, "output.checkpoint_interval");
  s.output.stop_grace = real(sc, "output.stop_grace");
  s.stats.window_start_travel = real(sc, "stats.window_start_travel");
  s.stats.window_end_travel = real(sc, "stats.window_end_travel");
  s.stats.lowpass_hz = real(sc, "stats.lowpass_hz");
  s.stats.include_squeeze = get<bool>(sc, "stats.include_squeeze");

  if (s.validation.kind != ValidationKind::kNone && s.fracture.mode != FractureMode::kOn)
    fail_key(sc, "fracture.mode", fmt::format("the {} case needs ice elements: set fracture.mode = \"on\"",
                                              get<std::string>(sc, "validation.case")));
  // the plate takes any elements: its load is on the elements at its centre and its theory a
  // plate's; the cantilevers' loads and beam theory are laid out for a row of squares
  if (s.validation.kind == ValidationKind::kCantilever &&
      (s.fracture.element_shape != ElementShape::kSquare || s.fracture.lattice_angle != 0))
    fail_key(sc, s.fracture.lattice_angle != 0 ? "fracture.lattice_angle" : "fracture.element_shape",
             fmt::format("{} for the {} case: its load and its beam theory are laid out for a row of squares "
                         "along the grid (validation.case = \"wide_cantilever\" takes any elements and angle)",
                         s.fracture.lattice_angle != 0 ? "0" : "\"square\"", get<std::string>(sc, "validation.case")));
  // the wide cantilever's plate: a clamped strip, a free span and a loaded strip, each an element long
  if (s.validation.kind == ValidationKind::kWideCantilever &&
      s.validation.beam_length < 3 * s.fracture.element_size * (1 - 1e-9))
    fail_key(sc, "validation.beam_length",
             fmt::format("at least 3 x fracture.element_size = {:g} m for the wide_cantilever case: a clamped strip, a "
                         "free span and a loaded strip, each one element long", 3 * s.fracture.element_size));
  if (s.validation.kind == ValidationKind::kWideCantilever &&
      s.validation.beam_width < s.fracture.element_size * (1 - 1e-9))
    fail_key(sc, "validation.beam_width",
             fmt::format("at least fracture.element_size = {:g} m for the wide_cantilever case", s.fracture.element_size));
  if (s.validation.kind == ValidationKind::kPlateDeflection && s.fracture.element_shape == ElementShape::kSquare &&
      s.fracture.lattice_angle == 0) {
    if (const double n = s.validation.plate_size / s.fracture.element_size; !whole(n))
      fail_key(sc, "validation.plate_size", fmt::format("is not a whole number of elements of fracture.element_size = {} m "
                                                        "({:.3f})", s.fracture.element_size, n));
  } else if (s.validation.kind == ValidationKind::kPlateDeflection &&
             s.validation.plate_size < s.fracture.element_size * (1 - 1e-9)) {
    // hexagons or a turned grid: the plate is cut from the tiling at its outline, which needs room
    // for an element's centre at least (smaller, the cut has no element to load)
    fail_key(sc, "validation.plate_size",
             fmt::format("at least fracture.element_size = {:g} m for a plate of hexagons or of a turned grid",
                         s.fracture.element_size));
  }
  if (s.stats.lowpass_hz > 0 && s.stats.lowpass_hz >= 0.5 / s.time.dt)
    fail_key(sc, "stats.lowpass_hz", fmt::format("must be below the Nyquist frequency 1/(2 dt) = {} Hz", 0.5 / s.time.dt));
  if (s.stats.window_end_travel > 0 && s.stats.window_end_travel <= s.stats.window_start_travel)
    fail_key(sc, "stats.window_end_travel", "must be beyond stats.window_start_travel (or 0 for the end of the run)");
  if (s.ice.cover == IceCover::kLevel) check_level_ice(sc, s);
  if (s.contact.crushing_contacts == CrushingContacts::kStructureAndSheet) {
    // what it adds is the held level sheet's edge: elsewhere it would be "structure" under another name
    if (s.contact.model != ContactModel::kCrushing)
      fail_key(sc, blamed(sc, {"contact.crushing_contacts", "contact.model"}),
               "contact.crushing_contacts = \"structure_and_sheet\" says which contacts the crushing law acts on: it "
               "needs contact.model = \"crushing\"");
    if (s.ice.cover != IceCover::kLevel || s.fracture.mode != FractureMode::kAnalytic)
      fail_key(sc, blamed(sc, {"contact.crushing_contacts", "ice.cover", "fracture.mode"}),
               "contact.crushing_contacts = \"structure_and_sheet\" crushes the floes against the held level sheet "
               "of ice.cover = \"level\" with fracture.mode = \"analytic\", which this scenario does not have: use "
               "\"structure\" (or \"all\")");
  }
  if (s.validation.kind == ValidationKind::kNone) check_structure_in_tank(sc, s);
  check_limits(sc, s);
  return s;
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return make_scene(read_scenario(path, overrides));
}

}  // namespace icedem
