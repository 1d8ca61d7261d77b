// Calibration of the element joints' softness (seed paper, Fig. 6): find the
// constraint force mixing (fracture.cfm) that gives a floating plate of elements
// the target elastic modulus in the plate-deflection test.
//
// Bullet scales CFM by each row's effective mass, so the paper's Sigma values
// do not transfer, and a plate's compliance also comes from PGS
// non-convergence: E depends on the CFM *and* on solver.iterations and time.dt
// (docs/model/validation_targets.md §6). The search therefore holds the scene's solver
// settings fixed; when even stiff joints (CFM -> 0) are too soft, it says so
// and names solver.iterations as the key to raise.
#pragma once

#include <vector>

#include "dem/scene.hpp"

namespace icedem {

/// Centre deflection per unit load (m/N) of the scene's plate-deflection case,
/// measured over the second half of a run of time.duration.
double measure_plate_compliance(const Scene& plate_scene);

struct CalibrationPoint {
  double cfm;         // -, Bullet units
  double compliance;  // m/N
  double modulus;     // Pa, inferred with the finite-plate factor
};

struct CalibrationResult {
  bool reached = false;  // the target lies inside the searched CFM range
  double cfm = 0;        // -, best estimate
  double modulus = 0;    // Pa, at that CFM
  std::vector<CalibrationPoint> points;  // every evaluation, in order
  std::string note;      // why it was not reached
};

/// Bisect log10(fracture.cfm) in [cfm_min, cfm_max] until the inferred modulus
/// is within `tolerance` (relative) of target_modulus, or `max_evaluations`.
/// `plate_scene` must be a plate_deflection validation scene.
CalibrationResult calibrate_cfm(const Scene& plate_scene, double target_modulus, double tolerance = 0.02,
                                double cfm_min = 1e-10, double cfm_max = 1.0, int max_evaluations = 16);

}  // namespace icedem
