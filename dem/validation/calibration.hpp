// Calibration of the element joints' softness (seed paper, Fig. 6): find the
// constraint force mixing (fracture.cfm, Bullet's joints) or the factor on the
// elastic joints' springs (fracture.stiffness_scale) that gives a floating plate
// of elements the target elastic modulus in the plate-deflection test.
//
// Elastic joints (dem/world/joint_springs.hpp) are springs of the ice, so the plate's
// modulus grows nearly in proportion to their scale when the joints are solved: the
// search is a secant, two or three plate runs, and its result holds at any step.
//
// Bullet scales CFM by each row's effective mass, so the paper's Sigma values
// do not transfer, and a plate's compliance also comes from PGS
// non-convergence: E depends on the CFM *and* on solver.iterations and time.dt
// (docs/model/validation_targets.md §6). The search therefore holds the scene's solver
// settings fixed; when even stiff joints (CFM -> 0) are too soft, it says so
// and names solver.iterations as the key to raise.
#pragma once

#include <string>
#include <vector>

#include "dem/input/scene.hpp"

namespace icedem {

/// Centre deflection per unit load (m/N) of the scene's plate-deflection case,
/// measured over the second half of a run of time.duration.
double measure_plate_compliance(const Scene& plate_scene);

struct CalibrationPoint {
  double value;       // -, the calibrated key's value (fracture.cfm in Bullet units, or fracture.stiffness_scale)
  double compliance;  // m/N
  double modulus;     // Pa, inferred with the finite-plate factor
};

struct CalibrationResult {
  std::string key;       // the key calibrated: "fracture.cfm" or "fracture.stiffness_scale"
  bool reached = false;  // the target was met within the tolerance
  double value = 0;      // -, best estimate of the key's value
  double modulus = 0;    // Pa, at that CFM
  std::vector<CalibrationPoint> points;  // every evaluation, in order
  std::string note;      // why it was not reached
};

/// Bisect log10(fracture.cfm) in [cfm_min, cfm_max] until the inferred modulus
/// is within `tolerance` (relative) of target_modulus, or `max_evaluations`.
/// `plate_scene` must be a plate_deflection validation scene.
CalibrationResult calibrate_cfm(const Scene& plate_scene, double target_modulus, double tolerance = 0.02,
                                double cfm_min = 1e-10, double cfm_max = 1.0, int max_evaluations = 16);

/// The scale of the elastic joints' springs (fracture.stiffness_scale) that gives the
/// plate target_modulus within `tolerance` (relative), starting from the scene's scale.
/// `plate_scene` must be a plate_deflection validation scene with elastic joints.
CalibrationResult calibrate_stiffness_scale(const Scene& plate_scene, double target_modulus, double tolerance = 0.02,
                                            int max_evaluations = 6);

/// The one the scene's joints take: calibrate_stiffness_scale for elastic joints, else calibrate_cfm.
CalibrationResult calibrate_joints(const Scene& plate_scene, double target_modulus, double tolerance = 0.02);

}  // namespace icedem
