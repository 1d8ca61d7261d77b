#include "dem/initial_state.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "dem/activation.hpp"
#include "dem/errors.hpp"
#include "dem/step.hpp"
#include "dem/world_builder.hpp"

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
Layout generated_layout(const Scene& scene) {
  LayoutParams p;
  p.channel = scene_channel(scene);
  p.floe_size = scene.ice.floe_size;
  p.concentration = scene.ice.concentration;
  p.seed = scene.seed;
  p.max_yaw = scene.layout.max_yaw;
  p.sweeps = scene.layout.sweeps;
  p.min_gap = scene.layout.min_gap;
  Layout layout = generate_square_layout(p);
  // rafted ice: each further layer is its own arrangement, stacked on the first
  for (int k = 1; k < scene.layout.layers; ++k) {
    p.seed = scene.seed + static_cast<uint64_t>(k);
    const Layout layer = generate_square_layout(p);
    for (Floe f : layer.floes) {
      f.layer = k;
      layout.floes.push_back(f);
    }
    layout.achieved_concentration += layer.achieved_concentration;
  }
  return layout;
}

}  // namespace

Layout scene_layout(const Scene& scene) {
  // validation cases: one rectangular floe at the middle of the channel
  if (scene.validation.kind == ValidationKind::kPlateDeflection)
    return single_floe_layout(scene, scene.validation.plate_size, scene.validation.plate_size);
  if (scene.validation.kind == ValidationKind::kCantilever)  // a beam along x, one element wide
    return single_floe_layout(scene, scene.validation.beam_elements * scene.fracture.element_size,
                              scene.fracture.element_size);
  if (!scene.layout.file.empty()) return read_layout_file(scene.layout.file, scene_channel(scene));
  // a generated layout's problems come from the scenario's keys: name its file
  try {
    return generated_layout(scene);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", scene.source_path, e.what()));
  }
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
  state.world = build_world(scene, floes);
  install_activation(scene, *state.world);
  state.flow = make_flow(scene, coupling);
  if (coupling.drag_exchange) state.drag_exchange = coupling.drag_exchange(scene);
  state.structure_position = structure_position_at(scene, 0.0);
  state.structure_velocity = Eigen::Vector3d(scene.structure.speed, 0.0, 0.0);
  state.flow->set_structure(state.structure_position, state.structure_velocity);
  state.awake_floes = state.world->awake_floes();
  return state;
}

}  // namespace icedem
