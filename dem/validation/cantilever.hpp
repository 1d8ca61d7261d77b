// The cantilever cases (seed paper Fig. 7, eq. 6): a beam of elements one element wide, its
// root element clamped, loaded at the tip until a joint breaks. The stress at failure,
// sigma' = 6 (P_c - P_b) l / (L_e T_e^2), must match the bending strength, in bending, at the
// root. As docs/model/validation_targets.md §3 says, this checks how the joint load is
// extracted and judged, not the ice. Two ways (validation.tip_speed):
//  - in air (tip_speed = 0; cantilever_in_air.cpp): each free element's weight carried by an
//    upward force standing for buoyancy (so P_b = 0), the tip loaded by a force growing at
//    validation.load_rate;
//  - floating (tip_speed > 0; floating_cantilever.cpp), the paper's test: the tip element
//    pushed down at constant speed by a kinematic pusher pinned to it. The push force P_c
//    peaks at the break and then falls to the fragment's buoyancy P_b, measured 0.5-1.5 s
//    after the break as the paper did. Like the paper's, this P_b is the pushed-under
//    fragment's, not the inclined beam's at the break (§3).
#pragma once

#include <vector>

#include "dem/fracture/fracture_state.hpp"
#include "dem/validation/case.hpp"

namespace icedem {

/// What both cantilevers share: the first break, the histories, and eq. 6.
class Cantilever : public ValidationCase {
 public:
  ValidationResult result(const Scene& scene) const override;

 protected:
  /// Remembers the elements' initial x and mass, and clamps the root element (zero inverse mass).
  void clamp_root(State& state);
  /// Remembers the first break of the step just taken and the tip load then (the peak).
  void note_first_break(const State& state, double tip_load);
  /// kPa, the root joint's bending stress from its feedback: 6 M / (L_e T_e^2).
  static double root_stress(const Scene& scene, const State& state);
  /// N, the fragment's buoyancy P_b of eq. 6 (0 in air); none if it could not be measured.
  virtual std::optional<double> fragment_buoyancy() const = 0;
  virtual bool floating() const = 0;

  std::vector<double> x0_;   // m, initial x of each element, root first
  double element_mass_ = 0;  // kg
  bool broken_ = false;
  FractureEvent first_break_{};
  double load_at_break_ = 0;     // N
  double last_root_stress_ = 0;  // kPa, before the break
  // for the plot (the summary's "history"): time s, tip load N (the push when floating),
  // root-joint bending stress kPa, tip depth below its start m (floating only)
  std::vector<double> history_time_, history_load_, history_root_stress_, history_depth_;
};

class CantileverInAir : public Cantilever {
 public:
  /// Lifts the beam 1 m into the air and sets the weight supports of the first step.
  CantileverInAir(const Scene& scene, State& state);
  void after_step(const Scene& scene, State& state) override;

 private:
  std::optional<double> fragment_buoyancy() const override { return 0.0; }
  bool floating() const override { return false; }
  /// The next step's loads: each free element's weight carried, the tip load applied.
  void set_loads(const Scene& scene);
  double tip_load_ = 0;  // N, applied in the step just taken
};

class FloatingCantilever : public Cantilever {
 public:
  /// Pins the pusher to the tip element and sets its first target.
  FloatingCantilever(const Scene& scene, State& state);
  ~FloatingCantilever() override;
  void after_step(const Scene& scene, State& state) override;

 private:
  std::optional<double> fragment_buoyancy() const override;
  bool floating() const override { return true; }
  struct Pusher;
  std::unique_ptr<Pusher> pusher_;
};

}  // namespace icedem
