// The contact solve's settings (the scenario's solver.* keys), declared once: the scene holds
// them (dem/input/scene.hpp), the island solve (dem/contact/island_solve.hpp) and the Bullet
// adapter (dem/world/contact_solver.hpp) read them. Their defaults and meanings are the keys'
// (dem/input/scenario_keys.cpp; solver.profile's in dem/input/solver_profile.cpp).
#pragma once

#include <string>

namespace icedem {

enum class Broadphase { kDbvt, kSweepAndPrune };

/// Order of the rows within a sweep.
enum class SweepOrder {
  kBullet,         // the order Bullet builds them (manifold by manifold): its arrays' history
  kCanonical,      // by the bodies (contacts) and joints (joint rows) they act on: the same in a
                   // world rebuilt from a checkpoint (dem/output/world_state.hpp)
  kFromStructure,  // canonical, then the contacts by distance from the structure axis, outward
                   // on even sweeps, inward on odd
};

struct SolverSettings {
  int iterations;             // cap of PGS sweeps over the contacts per island and Bullet step
  double tolerance;           // -, residual that ends an island's sweeps early; 0 = never
  double warm_start;          // -, fraction of the last step's impulses a step starts from
  bool friction_warm_start;   // friction impulses warm-started too
  SweepOrder order;           // of the rows in a sweep
  double sor;                 // -, over-relaxation of the contact rows
  Broadphase broadphase;
  bool split_impulse;         // position correction kept out of the contact impulses
  double contact_erp;         // -, fraction of penetration corrected per step
  std::string method;         // contact method of an island: "pgs" (the sweeps above), "pgs_cone", "newton", "apgd"
  double merit_tolerance;     // -, merit that ends a method's solve
  std::string merit;          // which: "impulse" (forces relative to forces) or "siconos" (dem/contact/merit.hpp)
  double joint_merit_tolerance;  // -, the same for an island with joint rows, if smaller
  double structure_merit_tolerance;  // -, the same for an island touching the structure, if smaller
  double breaking_merit_tolerance;  // -, an island with a joint near its capacity is solved again to this
  double breaking_ratio;            // -, a joint's failure ratio within 1 - this of 1 has its island solved again
  double breaking_check_tolerance;  // -, merit of a first check of such an island's breaks
  double breaking_check_band;       // -, how far from 1 every ratio must then be to stop there
  int breaking_iterations;          // cap of the method's iterations then
  int method_iterations;      // cap of the method's iterations per island and Bullet step
  std::string handover_method;  // what goes on with an island capped there ("none": nothing)
  int handover_iterations;      // its cap
  int position_iterations;    // cap of the split-impulse position sweeps per island and Bullet step
};

}  // namespace icedem
