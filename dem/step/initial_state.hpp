// The initial State of a run: floe layout, Bullet world and flow model built
// from the Scene.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dem/input/scene.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/step/state.hpp"
#include "dem/water/flow_coupling.hpp"
#include "dem/water/flow_field.hpp"

namespace icedem {

/// The floe field of the scene's channel.
Channel scene_channel(const Scene& scene);

/// The floes: read from layout.file, or generated at ice.concentration (`on_progress` told
/// the share of the generation done, 0..1). Throws InputError if one overlaps the
/// structure at t = 0, or a breakable floe does not cut into elements.
Layout scene_layout(const Scene& scene, const std::function<void(double)>& on_progress = {});

/// Warnings about floes the scene will not hold well, or not as asked: floes too narrow for their
/// thickness to float flat (they turn over); a structure whose path meets no floe within the run
/// (standing still, started too far back, or past them); breakable floes no wider than an
/// element (one element never breaks; a narrower floe is cut into parts of cells); a generated
/// field whose whole number of floes is more than one point of concentration from
/// ice.concentration. Empty if none.
std::vector<std::string> layout_warnings(const Scene& scene, const Layout& layout);

/// The water velocity model of flow.model ("coupled" from `coupling`).
std::unique_ptr<FlowField> make_flow(const Scene& scene, const FlowCoupling& coupling = {});

/// World, flow and structure at t = 0 with the given floes (a coupled flow and the drag
/// exchange from `coupling`).
State initial_state(const Scene& scene, const std::vector<Floe>& floes, const FlowCoupling& coupling = {});

}  // namespace icedem
