#include "dem/step/initial_state.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "dem/activation/activation.hpp"
#include "dem/core/errors.hpp"
#include "dem/fracture/ice_lattice.hpp"
#include "dem/fracture/level_ice.hpp"
#include "dem/step/step.hpp"
#include "dem/step/world_builder.hpp"
#include "dem/world/cone_geometry.hpp"

namespace icedem {

Channel scene_channel(const Scene& scene) {
  const ChannelSettings& c = scene.channel;
  return Channel{c.start_x, c.start_x + c.length, -c.width / 2, c.width / 2};
}

namespace {
Layout single_floe_layout(const Scene& scene, double lx, double lz) {
  const Channel c = scene_channel(scene);
  const double a = lx / 2, b = lz / 2;
  Layout layout;
  layout.floes.push_back(Floe{Eigen::Vector2d((c.x_min + c.x_max) / 2, (c.z_min + c.z_max) / 2), 0.0,
                              {{-a, -b}, {a, -b}, {a, b}, {-a, b}}});
  layout.channel_area = (c.x_max - c.x_min) * (c.z_max - c.z_min);
  layout.achieved_concentration = lx * lz / layout.channel_area;
  return layout;
}

// a generated square-floe field (layout.layers of them stacked for rafted ice)
Layout generated_layout(const Scene& scene, const std::function<void(double)>& on_progress) {
  LayoutParams p;
  p.channel = scene_channel(scene);
  p.floe_size = scene.ice.floe_size;
  p.size_spread = scene.layout.size_spread;
  p.concentration = scene.ice.concentration;
  p.seed = scene.seed;
  p.max_yaw = scene.layout.max_yaw;
  p.sweeps = scene.layout.sweeps;
  p.min_gap = scene.layout.min_gap;
  const int layers = scene.layout.layers;
  if (on_progress) p.on_sweep = [&on_progress, layers](double f) { on_progress(f / layers); };
  Layout layout = generate_square_layout(p);
  // rafted ice: each further layer is its own arrangement, stacked on the first
  for (int k = 1; k < layers; ++k) {
    p.seed = scene.seed + static_cast<uint64_t>(k);
    if (on_progress) p.on_sweep = [&on_progress, layers, k](double f) { on_progress((k + f) / layers); };
    const Layout layer = generate_square_layout(p);
    for (Floe f : layer.floes) {
      f.layer = k;
      layout.floes.push_back(f);
    }
    layout.achieved_concentration += layer.achieved_concentration;
  }
  return layout;
}

// distance from p to a convex ccw polygon, 0 inside it
double distance_to(const Polygon& polygon, const Eigen::Vector2d& p) {
  bool inside = true;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const Eigen::Vector2d e = b - a, d = p - a;
    if (e.x() * d.y() - e.y() * d.x() < 0) inside = false;
    const double t = std::clamp(d.dot(e) / std::max(e.squaredNorm(), 1e-300), 0.0, 1.0);
    nearest = std::min(nearest, (d - t * e).norm());
  }
  return inside ? 0.0 : nearest;
}

// The floes may not start inside the structure: Bullet would push them out at whatever speed
// resolves the penetration in one step, or leave them inside the hull (0.53 m of penetration
// was measured on such a run). A floe overlaps the structure when its outline comes nearer to
// the axis than the hull's radius over the floe's height.
void refuse_floes_in_structure(const Scene& scene, const std::vector<Floe>& floes) {
  const double h = scene.ice.thickness;
  const Eigen::Vector2d axis(scene.structure.start_x, scene.structure.start_z);
  for (std::size_t k = 0; k < floes.size(); ++k) {
    const Floe& f = floes[k];
    const double bottom = -scene.ice.draft + f.layer * (h + scene.layout.min_gap);
    double radius = 0;  // the hull's largest radius over the floe's height
    for (int i = 0; i <= 8; ++i) radius = std::max(radius, profile_radius(scene.structure.profile, bottom + h * i / 8));
    const double d = distance_to(transformed(f.shape, f.centre, f.yaw), axis);
    if (d < radius)
      throw InputError(fmt::format(
          "{}: floe {} (centre x = {:.3f} m, z = {:.3f} m) overlaps the structure at t = 0: its outline comes "
          "within {:.3f} m of the structure's axis at x = {:.3f} m, inside the hull's radius of {:.3f} m at the "
          "ice's height; start the structure farther away (structure.start_x) or move the floe",
          scene.layout.file.empty() ? scene.source_path : scene.layout.file, k, f.centre.x(), f.centre.y(), d,
          axis.x(), radius));
  }
}

}  // namespace

namespace {

// a convex outline's least width: over its edges' normals
double least_width(const Polygon& s) {
  double width = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Eigen::Vector2d e = s[(i + 1) % s.size()] - s[i];
    const Eigen::Vector2d n = Eigen::Vector2d(e.y(), -e.x()).normalized();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Eigen::Vector2d& v : s) lo = std::min(lo, n.dot(v)), hi = std::max(hi, n.dot(v));
    width = std::min(width, hi - lo);
  }
  return width;
}

// A floating prism of draft d and thickness h floats flat only with a positive metacentric
// height: KB + BM > KG, d/2 + w^2 / (12 d) > h/2 for a width w, so w^2 > 6 d (h - d). Narrower
// floes turn over onto a side (and, being small and light, take the largest accelerations
// of the pack)
std::optional<std::string> narrow_floes_warning(const Scene& scene, const Layout& layout) {
  const double h = scene.ice.thickness, d = scene.ice.draft;
  const double narrowest = std::sqrt(std::max(0.0, 6 * d * (h - d)));
  int narrow = 0, first = -1;
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < layout.floes.size(); ++k) {
    const double width = least_width(layout.floes[k].shape);
    if (width < narrowest) {
      ++narrow;
      if (first < 0) first = static_cast<int>(k);
      smallest = std::min(smallest, width);
    }
  }
  if (!narrow) return std::nullopt;
  return fmt::format("{} floe(s) (the first: floe {}) are narrower than {:.4f} m, down to {:.4f} m: a floe of "
                     "{} m ice floats flat only if wider than sqrt(6 d (h - d)) (a positive metacentric height); "
                     "narrower ones turn over onto a side, and small light bodies take the pack's largest "
                     "accelerations (a run may blow up)",
                     narrow, first, narrowest, smallest, h);
}

// The structure's path over the run against the floes: a hull that never reaches one (standing
// still, started too far back, or past them and towed away) records no ice load at all
std::optional<std::string> no_ice_met_warning(const Scene& scene, const Layout& layout) {
  if (scene.validation.kind != ValidationKind::kNone || layout.floes.empty()) return std::nullopt;
  double first = std::numeric_limits<double>::infinity(), last = -first;  // m, the floes' extent in x
  for (const Floe& f : layout.floes)
    for (const Eigen::Vector2d& v : transformed(f.shape, f.centre, f.yaw)) {
      first = std::min(first, v.x());
      last = std::max(last, v.x());
    }
  const StructureSettings& st = scene.structure;
  const double r = hull_radius_in_ice(scene), T = scene.time.duration;
  if (st.start_x - r > last)
    return fmt::format("the structure (structure.start_x = {} m, radius {:.3f} m where it meets the ice) starts past "
                       "every floe (the last ends by x = {:.3f} m) and is towed away from them: it meets no ice",
                       st.start_x, r, last);
  const double front = st.start_x + st.speed * T + r;  // the hull's leading edge at the run's end
  if (front >= first) return std::nullopt;
  if (st.speed <= 0)
    return fmt::format("structure.speed = 0: the structure stands still {:.3f} m short of the nearest floe, and "
                       "nothing else moves the ice (the water is still): the run records no ice load",
                       first - (st.start_x + r));
  return fmt::format("the structure does not reach the ice within the run: its hull (radius {:.3f} m where it meets "
                     "the ice) ends at x = {:.3f} m at t = {} s (time.duration), short of the nearest floe at x = "
                     "{:.3f} m, which it would reach at t = {:.1f} s; start it closer (structure.start_x) or run longer",
                     r, front, T, first, (first - st.start_x - r) / st.speed);
}

// Breakable floes narrower than an element, or cut into one element only: a single element has no
// joint and never breaks, and a floe narrower than the elements is cut into parts of cells, not
// into the elements asked (the counts scene_layout made)
std::optional<std::string> element_size_warning(const Scene& scene, const Layout& layout) {
  if (scene.validation.kind != ValidationKind::kNone || scene.ice.cover != IceCover::kFloes ||
      layout.floe_elements.size() != layout.floes.size())
    return std::nullopt;
  const double size = scene.fracture.element_size;
  int flagged = 0, first = -1, single = 0;
  double narrowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < layout.floes.size(); ++k) {
    const std::size_t elements = layout.floe_elements[k];
    if (!elements) continue;  // rigid
    const double width = least_width(layout.floes[k].shape);
    if (elements > 1 && width >= size * (1 - 1e-9)) continue;
    if (flagged++ == 0) first = static_cast<int>(k);
    single += elements == 1;
    narrowest = std::min(narrowest, width);
  }
  if (!flagged) return std::nullopt;
  return fmt::format("{} breakable floe(s) (the first: floe {}; least width down to {:.3f} m) are no wider than "
                     "fracture.element_size = {} m: {} of them a single element, which has no joint and never "
                     "breaks, the others cut into parts of cells rather than elements of that size; use smaller "
                     "elements or make such floes rigid (fracture.mode)",
                     flagged, first, narrowest, size, single);
}

// A generated field holds a whole number of floes: with few of them, its concentration can be far
// from ice.concentration (the generator refuses only one that cannot be packed at all)
std::optional<std::string> concentration_warning(const Scene& scene, const Layout& layout) {
  if (scene.validation.kind != ValidationKind::kNone || scene.ice.cover != IceCover::kFloes ||
      !scene.layout.file.empty() || layout.floes.empty())
    return std::nullopt;
  const double per_layer = layout.achieved_concentration / scene.layout.layers;
  if (std::abs(per_layer - scene.ice.concentration) <= 0.01) return std::nullopt;
  return fmt::format("ice.concentration = {} asked; the layout's {} floes of ice.floe_size = {} m cover {:.2f} % of "
                     "the channel{}: a whole number of floes comes no closer. Use smaller floes or a larger channel "
                     "for the concentration asked",
                     scene.ice.concentration, layout.floes.size(), scene.ice.floe_size, 100 * per_layer,
                     scene.layout.layers > 1 ? " (each layer)" : "");
}

}  // namespace

std::vector<std::string> layout_warnings(const Scene& scene, const Layout& layout) {
  std::vector<std::string> out;
  for (const auto& w : {narrow_floes_warning(scene, layout), no_ice_met_warning(scene, layout),
                        element_size_warning(scene, layout), concentration_warning(scene, layout)})
    if (w) out.push_back(*w);
  return out;
}

Layout scene_layout(const Scene& scene, const std::function<void(double)>& on_progress) {
  // validation cases: one rectangular floe at the middle of the channel
  if (scene.validation.kind == ValidationKind::kPlateDeflection)
    return single_floe_layout(scene, scene.validation.plate_size, scene.validation.plate_size);
  if (scene.validation.kind == ValidationKind::kWideCantilever)  // a plate, clamped along its x = 0 edge
    return single_floe_layout(scene, scene.validation.beam_length, scene.validation.beam_width);
  if (scene.validation.kind == ValidationKind::kCantilever)  // a beam along x, one element wide
    return single_floe_layout(scene, scene.validation.beam_elements * scene.fracture.element_size,
                              scene.fracture.element_size);
  Layout layout;
  if (scene.ice.cover == IceCover::kLevel) {  // one sheet over the channel (dem/fracture/level_ice.hpp)
    layout.floes.push_back(level_sheet_floe(scene));
    layout.channel_area = scene.channel.length * scene.channel.width;
    layout.achieved_concentration = area(layout.floes[0].shape) / layout.channel_area;
  } else if (!scene.layout.file.empty()) {
    layout = read_layout_file(scene.layout.file, scene_channel(scene));
  } else {
    // a generated layout's problems come from the scenario's keys: name its file
    try {
      layout = generated_layout(scene, on_progress);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", scene.source_path, e.what()));
    }
  }
  refuse_floes_in_structure(scene, layout.floes);
  // a breakable floe is cut into the paper's lattice (a rectangle of whole squares) or filled
  // with elements cut at its outline; one too small to hold an element is refused here,
  // naming the input the floes came from, before anything is built. Each floe's elements are
  // counted for the warnings (layout_warnings), so that no lattice is cut twice (level ice's
  // sheet has no such warning)
  layout.floe_elements.assign(layout.floes.size(), 0);
  for (std::size_t i = 0; i < layout.floes.size(); ++i) {
    const Floe& floe = layout.floes[i];
    if (!is_breakable(scene, floe.shape)) continue;
    double yaw = 0;
    if (paper_lattice(floe.shape, scene.fracture)) {
      if (scene.ice.cover == IceCover::kFloes)
        layout.floe_elements[i] = floe_lattice(floe.shape, scene.fracture.element_size, yaw).centres.size();
      continue;
    }
    layout.floe_elements[i] = floe_outline_lattice(floe.shape, scene.fracture, yaw).elements.size();
    if (layout.floe_elements[i] == 0)
      throw InputError(fmt::format("{}: floe {} ({:.4g} m^2) is smaller than a quarter of an element of "
                                   "fracture.element_size = {} m; make it rigid (fracture.mode = \"auto\" "
                                   "or \"off\") or the elements smaller",
                                   scene.layout.file.empty() ? scene.source_path : scene.layout.file, i,
                                   area(floe.shape), scene.fracture.element_size));
  }
  return layout;
}

std::unique_ptr<FlowField> make_flow(const Scene& scene, const FlowCoupling& coupling) {
  switch (scene.flow.model) {
    case FlowModel::kStill: return std::make_unique<StillWater>();
    case FlowModel::kUniform: return std::make_unique<UniformFlow>(scene.flow.velocity);
    case FlowModel::kPotential: {
      std::vector<std::pair<double, double>> stations;
      for (const ProfileStation& s : scene.structure.profile) stations.emplace_back(s.y, s.radius);
      return std::make_unique<ConePotentialFlow>(stations);
    }
    case FlowModel::kCoupled:
      if (coupling.flow) return coupling.flow(scene);
      throw InputError("flow.model = \"coupled\": this program was built without the OpenFOAM coupling "
                       "(coupling/); the icedem command has it");
  }
  throw std::logic_error("make_flow: unknown flow model");
}

State initial_state(const Scene& scene, const std::vector<Floe>& floes, const FlowCoupling& coupling) {
  State state;
  state.structure_position = structure_position_at(scene, 0.0);
  state.structure_velocity = Eigen::Vector3d(scene.structure.speed, 0.0, 0.0);
  if (scene.structure.motion == StructureMotion::kMoored) {
    state.floating = std::make_shared<const FloatingStructure>(checked_floating_structure(scene));
    // floating at its draft and moving with the carriage, as a tank's model does once towed up to
    // speed: its mooring at rest, nothing to settle before the ice
    state.structure_position = state.floating->start;
    state.structure_motion.velocity = state.structure_velocity;
  }
  state.world = build_world(scene, floes, state.structure_position);
  if (analytic_level_ice(scene)) {
    const Floe& sheet = floes.front();  // level ice's layout is its one sheet
    state.sheet = std::make_unique<AnalyticSheet>(scene, *state.world, transformed(sheet.shape, sheet.centre, sheet.yaw),
                                                  static_cast<int>(floes.size()));
  }
  install_activation(scene, *state.world);
  state.flow = make_flow(scene, coupling);
  if (coupling.drag_exchange) state.drag_exchange = coupling.drag_exchange(scene);
  state.flow->set_structure(state.structure_position, state.structure_velocity);
  state.awake_floes = state.world->awake_floes();
  return state;
}

}  // namespace icedem
