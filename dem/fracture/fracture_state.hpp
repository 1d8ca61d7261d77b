// What the fracture stage keeps between steps and finds in a step: the breaks of the last step
// (the recorder writes them), the breaks so far by mode and mechanism, how close each floe's
// joints came to failing, and the low-passed joint loads. It is the State's `fracture`
// (dem/step/state.hpp), and a checkpoint writes it through visit_fields like the rest.
#pragma once

#include <array>
#include <type_traits>
#include <vector>

#include "dem/fracture/break_context.hpp"
#include "dem/fracture/joint_loads.hpp"

namespace icedem {

/// One joint break, with what its floe was doing (dem/fracture/break_context.hpp).
struct FractureEvent {
  double time;   // s
  int floe;      // floe id
  int joint;     // joint index within the floe
  int mode;      // failure mode code (FailureMode, dem/fracture/joint_loads.hpp)
  double ratio;  // 1, load / threshold of the criterion that fired (>= 1)
  double x = 0;  // m, joint midpoint at the break, tank frame
  double z = 0;  // m
  int mechanism = 0;             // BreakMechanism code
  int touching_structure = 0;    // 1 if an element of the floe touched the structure
  double depth = 0;              // m, joint midpoint below the waterline (+ down)
  double distance = 0;           // m, horizontally from the structure's section at its height
  double structure_force = 0;    // N, the structure's contact force on the floe
  double press_down = 0;         // N, other floes' contact force on it, downward
  double press_toward = 0;       // N, the same, towards the structure axis
  double ratio_compression = 0;  // 1, load / capacity of each criterion (eq. 1-3)
  double ratio_shear = 0;
  double ratio_bending = 0;
  double ratio_tension = 0;
  double ratio_in_plane_bending = 0;
};

struct FractureState {
  std::vector<FractureEvent> events;  // breaks of the last step; check_fracture, check_splits
  std::array<int, kFailureModes> breaks_by_mode{};          // all breaks so far, by FailureMode value
  std::array<int, kBreakMechanisms> breaks_by_mechanism{};  // all breaks so far, by BreakMechanism value
  std::vector<FloeFailureMargin> floe_margins;   // per layout floe with joints: how close they came to failing
  std::vector<JointLoads> filtered_joint_loads;  // low-passed loads per World::joints() entry
                                                 // (fracture.load_filter_time > 0)

  /// A break found this step: the event, and the counts by mode and mechanism.
  void add(const FractureEvent& event) {
    events.push_back(event);
    ++breaks_by_mode[event.mode];
    ++breaks_by_mechanism[event.mechanism];
  }
};

/// Calls `visit(name, field)` for every field of a FractureState (as visit_fields of the State's
/// values, dem/step/state.hpp).
template <typename Fracture, typename Visit>  // Fracture: FractureState or const FractureState
std::enable_if_t<std::is_same_v<std::remove_const_t<Fracture>, FractureState>> visit_fields(Fracture& f,
                                                                                             Visit&& visit) {
  visit("events", f.events);
  visit("breaks_by_mode", f.breaks_by_mode);
  visit("breaks_by_mechanism", f.breaks_by_mechanism);
  visit("floe_margins", f.floe_margins);
  visit("filtered_joint_loads", f.filtered_joint_loads);
}

}  // namespace icedem
