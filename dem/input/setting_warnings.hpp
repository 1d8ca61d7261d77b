// Settings each of which is legal but which together cannot be what was meant. `icedem check`
// prints them and `icedem run` puts them in the summary, beside the step-size advice
// (dem/input/step_size_advice.hpp); none stops a run.
#pragma once

#include <string>
#include <vector>

#include "dem/input/scene.hpp"

namespace icedem {

/// One sentence per setting that cannot be meant, naming its keys and what happens instead:
/// - the structure's path reaching the channel's end wall within the run (a squeeze of the ice
///   against the wall, left out of the statistics: dem/input/structure_path.hpp), or its hull
///   running through the mother-ice edges along the sides, or its keel below the tank's bottom;
/// - activation.unreached_out_of_world asked for where it does nothing (without sleeping, or with
///   the other activation keys it needs set otherwise): every floe is simulated from the start;
/// - snapshot or checkpoint intervals shorter than the step: one every step instead.
std::vector<std::string> setting_warnings(const Scene& scene);

}  // namespace icedem
