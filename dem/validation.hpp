// Validation cases run by `icedem run` (scenarios/validation/): they set up their
// loads, measure during the run, and add a `validation` block to the summary
// JSON: {metric, value, reference, rel_error, tolerance, passed} (docs/model/architecture.md).
//
// plate_deflection (seed paper Fig. 6): a floating square plate of elements
// under a central point load P. Reference: Hertz's infinite plate on a Winkler
// foundation, w0 / P = 1 / (8 sqrt(D rho_w g)) = 0.0889 mm/N for the paper's
// ice, times the finite-plate factor of docs/model/validation_targets.md §2 (free-edge circular
// plate of equal area; 1.04-1.06 for 2.7 m).
//
// cantilever (seed paper Fig. 7, eq. 6), two ways:
//  - validation.tip_speed > 0, the paper's test: a floating beam of elements,
//    its root element clamped, its tip element pushed down at constant speed by
//    a kinematic pusher pinned to it, until a joint breaks. The push force P_c
//    peaks at the break; afterwards it falls to the fragment's buoyancy P_b
//    (measured 0.5-1.5 s after the break, as the paper did), and
//    sigma' = 6 (P_c - P_b) l / (L_e T_e^2) must match sigma_b, in bending, at
//    the root. Like the paper's, this P_b is the pushed-under fragment's, not
//    the inclined beam's at the break (docs/model/validation_targets.md §3).
//  - tip_speed = 0: the beam in air, each free element's weight carried by an
//    upward force (standing for buoyancy, so P_b = 0), the tip loaded by a force
//    growing at validation.load_rate.
// As docs/model/validation_targets.md §3 says, this checks how the joint load is extracted and
// judged, not the ice.
#pragma once

#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "dem/scene.hpp"
#include "dem/state.hpp"

namespace icedem {

/// Centre deflection of a free-edge floating plate of equal-area radius a,
/// relative to the infinite plate, against a / l_c (docs/model/validation_targets.md §2).
double finite_plate_factor(double a_over_lc);

/// The finite-plate factor of the scene's plate-deflection case (its plate's
/// equal-area radius over the characteristic length).
double plate_finite_factor(const Scene& scene);

/// Hertz's infinite floating plate: centre deflection per unit central load, m/N.
double hertz_plate_compliance(const Scene& scene);

/// Elastic modulus inverted from a measured compliance w0/P (m/N) of a plate
/// with the given finite-plate factor: E = 3 (1 - nu^2) f^2 / (16 rho_w g h^3 (w0/P)^2).
double modulus_from_compliance(const Scene& scene, double compliance, double factor);

class Validation {
 public:
  /// Set up the case's loads on the initial state (nothing for "none").
  Validation(const Scene& scene, State& state);
  /// Takes the floating cantilever's pusher out of the world (which must outlive this).
  ~Validation();
  Validation(const Validation&) = delete;
  Validation& operator=(const Validation&) = delete;

  /// Measure after a step, and set the loads of the next.
  void after_step(const Scene& scene, State& state);

  /// The summary block, or null for "none".
  nlohmann::json result(const Scene& scene) const;

 private:
  nlohmann::json plate_result(const Scene& scene) const;
  nlohmann::json cantilever_result(const Scene& scene) const;
  // cantilever: remember the first break of the step just taken and the tip load then
  void note_first_break(const State& state, double tip_load);

  ValidationCase kind_ = ValidationCase::kNone;
  // plate deflection
  std::vector<int> centre_;  // loaded bodies
  double y0_ = 0;            // m, their mean initial height
  double sum_ = 0;           // m: summed centre deflection over the measuring half
  long samples_ = 0;
  // cantilever
  std::vector<double> x0_;   // m, initial x of each element, root first
  double element_mass_ = 0;  // kg
  double tip_load_ = 0;      // N, applied in the step just taken
  bool broken_ = false;
  FractureEvent first_break_{};
  double load_at_break_ = 0;  // N
  // history for the plot (summary "history"): time s, tip load N (the push force when
  // floating), root-joint bending stress kPa from the joint feedback (6 M / (L_e T_e^2)),
  // tip depth below its start m
  std::vector<double> history_time_, history_load_, history_root_stress_, history_depth_;
  // floating cantilever: the kinematic pusher pinned to the tip element
  struct Pusher;
  std::unique_ptr<Pusher> pusher_;
  double last_root_stress_ = 0;  // kPa, before the break
};

}  // namespace icedem
