#include "dem/input/scenario_keys.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "dem/contact/registry.hpp"

namespace icedem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

KeySpec real(std::string path, std::string unit, double def, double min, double max,
             std::string doc, bool min_exclusive = false) {
  KeySpec k{std::move(path), KeyType::kReal, std::move(unit), def, min, max, min_exclusive, {},
            std::move(doc)};
  return k;
}
KeySpec positive(std::string path, std::string unit, double def, double max, std::string doc) {
  return real(std::move(path), std::move(unit), def, 0.0, max, std::move(doc), true);
}
KeySpec integer(std::string path, std::int64_t def, double min, double max, std::string doc) {
  return KeySpec{std::move(path), KeyType::kInteger, "-", def, min, max, false, {}, std::move(doc)};
}
KeySpec boolean(std::string path, bool def, std::string doc) {
  return KeySpec{std::move(path), KeyType::kBoolean, "-", def, -kInf, kInf, false, {}, std::move(doc)};
}
KeySpec text(std::string path, std::string def, std::string doc) {
  return KeySpec{std::move(path), KeyType::kString, "", std::move(def), -kInf, kInf, false, {},
                 std::move(doc)};
}
KeySpec vector3(std::string path, std::string unit, Vector3Value def, double min, double max, std::string doc) {
  return KeySpec{std::move(path), KeyType::kVector3, std::move(unit), def, min, max, false, {}, std::move(doc)};
}
KeySpec choice(std::string path, std::string def, std::vector<std::string> choices, std::string doc) {
  return KeySpec{std::move(path), KeyType::kChoice, "", std::move(def), -kInf, kInf, false,
                 std::move(choices), std::move(doc)};
}

// The key table. Defaults reproduce the seed paper's smaller-floe test (Table 3)
// with the analytic flow; sources of the non-paper defaults are given in `doc`.
std::vector<KeySpec> make_keys() {
  std::vector<KeySpec> k;
  k.push_back(integer("seed", 1, 0, 9.0e18, "random seed of the floe layout; same seed, same run"));

  // time
  k.push_back(positive("time.dt", "s", 0.02, 1.0, "solver time step (paper Table 3: 0.02 s)"));
  k.push_back(positive("time.duration", "s", 300.0, 1.0e6, "simulated time"));
  k.push_back(integer("time.substeps", 1, 1, 1000,
                      "Bullet steps per time step (dt/substeps each); outputs stay at dt"));

  // solver
  // Every key below marked "(profile)" takes its default from solver.profile when the
  // scenario does not set it (dem/input/solver_profile.cpp); the default shown is that of the
  // default profile, "converged".
  k.push_back(choice("solver.profile", "converged", {"converged", "paper"},
                     "solver settings as a set (dem/input/solver_profile.cpp): \"converged\" = every island solved "
                     "whole by the accelerated projected gradient to a merit of 1e-3, warm-started (the "
                     "work-precision benchmark's choice, docs/model/contact_problems.md); \"paper\" = the seed "
                     "paper's numerics, 10 PGS sweeps a step on Bullet's solver as it comes, Bullet's CFM "
                     "joints"));
  k.push_back(integer("solver.iterations", 160, 1, 100000,
                      "(profile) solver.method = \"pgs\": cap of projected Gauss-Seidel sweeps over the contacts per "
                      "island and Bullet step; every method: cap of the split-impulse position sweeps"));
  k.push_back(real("solver.tolerance", "-", 0.01, 0.0, 1.0,
                   "(profile) solver.method = \"pgs\" (and the split-impulse position sweeps): an island stops "
                   "sweeping once its residual, the relative error of its "
                   "bodies' net impulses and of its load on the structure estimated from the last two "
                   "sweeps, is below this (dem/world/contact_solver.hpp); 0: always solver.iterations"));
  k.push_back(real("solver.warm_start", "-", 1.0, 0.0, 1.0,
                   "(profile) fraction of the last step's contact impulses a step starts from (Bullet: 0.85)"));
  k.push_back(boolean("solver.friction_warm_start", true,
                      "(profile) warm-start friction impulses too (Bullet starts them from zero)"));
  k.push_back(choice("solver.order", "canonical", {"bullet", "canonical", "structure"},
                     "(profile) order of the rows in a sweep: Bullet's (its arrays' history; the paper "
                     "profile), canonical (by the bodies and joints they act on, so that a world rebuilt "
                     "from a checkpoint solves as the original), or canonical and then by distance from "
                     "the structure, outward and inward in turn"));
  k.push_back(real("solver.sor", "-", 1.0, 0.1, 1.9,
                   "(profile) successive over-relaxation factor of the contact rows (1: plain Gauss-Seidel)"));
  k.push_back(choice("solver.method", "apgd", contact_method_names(true),
                     "(profile) how an island's contacts are solved: \"pgs\", projected Gauss-Seidel sweeps on "
                     "Bullet's rows (solver.iterations, solver.tolerance; friction clamped per direction, a "
                     "square); \"pgs_cone\", the same sweeps with Coulomb's disc on the island's problem; "
                     "\"newton\", the primal Newton method on the island's whole problem, joints included; "
                     "\"apgd\", accelerated projected gradient on the same problem; \"ipm\", the primal-dual "
                     "interior-point method on it; these four to solver.merit_tolerance (docs/model/"
                     "contact_problems.md). A bounded normal force (contact.model = \"crushing\"; the edge of "
                     "level ice with fracture.mode = \"analytic\") needs \"apgd\", \"newton\" or \"pgs_cone\""));
  k.push_back(real("solver.merit_tolerance", "-", 1e-3, 1e-14, 1.0,
                   "solver.method other than \"pgs\": an island is solved when its natural-map residual, the "
                   "merit every contact method is judged by (docs/model/contact_problems.md), is below this"));
  k.push_back(choice("solver.merit", "siconos", {"siconos", "impulse"},
                     "what solver.merit_tolerance bounds: \"siconos\", Siconos' relative natural map, the "
                     "contact-problem library's common measure, whose scale holds the gap-closing speeds of "
                     "untouching contacts and so loosens with a smaller step; \"impulse\", the natural map in "
                     "impulse units (each contact's velocity error times its effective mass) relative to the "
                     "island's impulses or its contacts' weights over the step: the forces' error relative to "
                     "the forces, the same at any step (dem/contact/merit.hpp, docs/model/convergence.md)"));
  k.push_back(real("solver.joint_merit_tolerance", "-", 1e-4, 1e-14, 1.0,
                   "solver.method other than \"pgs\": the merit an island with joints (a lattice's) is solved "
                   "to, if below solver.merit_tolerance: a joint's load is its elements' relative motion over "
                   "its compliance, so a loose solve's error reaches the joints' failure ratios magnified (one "
                   "seed of the 0.15 m lattices broke 10 joints at 1e-3, none at 1e-4 or 1e-5; "
                   "docs/model/convergence.md)"));
  k.push_back(real("solver.structure_merit_tolerance", "-", 1e-3, 1e-14, 1.0,
                   "solver.method other than \"pgs\": the merit an island touching the structure is solved "
                   "to, if below solver.merit_tolerance: the structure's load is read off that island's "
                   "impulses, and a loose solve leaves it low along the force chains (on the paper's "
                   "small-floe run, 3-5 % low at 1e-3; docs/model/convergence.md)"));
  k.push_back(real("solver.breaking_merit_tolerance", "-", 3e-6, 1e-14, 1.0,
                   "solver.method other than \"pgs\": an island whose answer puts a joint's failure ratio within "
                   "1 - solver.breaking_ratio of 1 is solved again, from that answer, to this merit "
                   "(after solver.breaking_check_tolerance): "
                   "whether the joint breaks is then decided on loads within about 0.5 % of its bending capacity, "
                   "where the merit of 1e-4 leaves up to 5 % (on the lattices' breaking steps; "
                   "docs/model/contact_problems.md). Not below solver.joint_merit_tolerance: off"));
  k.push_back(real("solver.breaking_ratio", "-", 0.9, 0.0, 10.0,
                   "solver.method other than \"pgs\": an island is solved again to solver.breaking_merit_tolerance "
                   "when a joint's failure ratio (its load over its capacity, eqs. 1-3) lies within 1 - this of 1: "
                   "0.9 to 1.1 at 0.9, twice the 5 % the joint merit tolerance's error may reach; a joint farther "
                   "from 1 breaks, or does not, whatever a tighter solve says"));
  k.push_back(real("solver.breaking_check_tolerance", "-", 1e-5, 0.0, 1.0,
                   "solver.method other than \"pgs\": an island solved again for a joint near its capacity is "
                   "first solved to this merit, and stops there if every joint's failure ratio is then farther "
                   "than solver.breaking_check_band from 1 (each break decided: at 1e-5 the joints' loads are "
                   "within 2 % of the bending capacity on the lattices' breaking steps, docs/model/"
                   "contact_problems.md); else it goes on to solver.breaking_merit_tolerance. Not above that "
                   "merit (0, say): off"));
  k.push_back(real("solver.breaking_check_band", "-", 0.04, 0.0, 10.0,
                   "solver.method other than \"pgs\": how far from 1 every joint's failure ratio must be at "
                   "solver.breaking_check_tolerance for the solve to stop there: 0.04, twice the 2 % that "
                   "merit's error reached"));
  k.push_back(integer("solver.breaking_iterations", 3000, 1, 1000000,
                      "solver.method other than \"pgs\": cap of the method's iterations in each stage of an island "
                      "solved again for a joint near its capacity (solver.breaking_check_tolerance, then "
                      "solver.breaking_merit_tolerance; the gradient method needs a median of 1000-3000 on the "
                      "lattices' breaking steps, and far more on a level sheet's); what it leaves above that merit, "
                      "solver.handover_method finishes (the Newton method with \"none\"; at most 1000 of its "
                      "iterations)"));
  std::vector<std::string> handover{"none"};
  for (const std::string& name : contact_method_names(true))
    if (name != kBulletSweeps) handover.push_back(name);
  k.push_back(choice("solver.handover_method", "ipm", handover,
                     "solver.method other than \"pgs\": an island the method leaves at solver.method_iterations "
                     "above its merit goes on from that answer with this method, for at most "
                     "solver.handover_iterations of its iterations; it also finishes an island solved again for a "
                     "joint near its capacity that the method left above solver.breaking_merit_tolerance (at most "
                     "1000 iterations). \"ipm\", the interior-point method, whose count of iterations hardly grows "
                     "with the stiffness of a lattice's joints: on a level sheet's islands it reaches the joints' "
                     "merit in about 10 iterations from the gradient method's capped answer where that method "
                     "takes 16,000 steps; over 50 s of level ice it left 0.8 % of the steps capped where 32 % were, "
                     "at 1.09 times the CPU (docs/model/contact_problems.md). An island with crushing contacts, which "
                     "the interior-point method does not take, goes on with the Newton method instead. \"none\": the "
                     "island stays capped, labelled, and the Newton method finishes the breaking solves (as before "
                     "2026-11-28)"));
  k.push_back(integer("solver.handover_iterations", 100, 1, 100000,
                      "solver.method other than \"pgs\": cap of solver.handover_method's iterations on an island "
                      "handed over at solver.method_iterations"));
  k.push_back(integer("solver.method_iterations", 1000, 1, 100000,
                      "solver.method other than \"pgs\": cap of the method's iterations per island and Bullet "
                      "step (Newton steps, or sweeps); the paper's small-floe run needs at most 589 gradient steps "
                      "(1022 on one island in one build), where a higher cap costs its multiple in CPU"));
  k.push_back(integer("solver.position_iterations", 30, 1, 100000,
                      "(profile) cap of the split-impulse position sweeps per island and Bullet step: they push "
                      "penetrating contacts apart by solver.contact_erp of their depth, apart from the contact "
                      "impulses the loads are read from, and stop earlier at solver.tolerance; what they leave is "
                      "pushed again the next step (/diagnostics/max_contact_penetration shows the depth)"));
  k.push_back(choice("solver.broadphase", "dbvt", {"dbvt", "sap"},
                     "Bullet broadphase: dynamic AABB tree, or 3-axis sweep and prune over the tank"));
  k.push_back(boolean("solver.split_impulse", true,
                      "correct contact penetration with a separate position impulse, so measured "
                      "contact impulses carry no Baumgarte push (docs/model/physics.md, load cell)"));
  k.push_back(real("solver.contact_erp", "-", 0.2, 0.0, 1.0,
                   "fraction of contact penetration corrected per step"));

  // structure
  k.push_back(choice("structure.motion", "towed", {"towed", "moored"},
                     "\"towed\": the structure moves with the carriage at structure.speed (the paper's); \"moored\": it "
                     "floats, in six degrees of freedom, held by a mooring (mooring.*) whose attachment moves with the "
                     "carriage (docs/model/mooring.md)"));
  k.push_back(real("structure.speed", "m/s", 0.07, 0.0, 10.0,
                   "prescribed surge speed of the carriage (paper: 0.07 m/s); moored: the speed of the mooring's "
                   "attachment"));
  k.push_back(real("structure.start_x", "m", 2.0, -1.0e4, 1.0e4,
                   "x of the structure axis at t = 0 (paper: 2 m)"));
  k.push_back(real("structure.start_z", "m", 0.0, -1.0e4, 1.0e4, "z of the structure axis"));
  {
    // Table 2: waterline breadth 1.228 m, maximum 1.472 m at depth-moulded 0.565 m
    // (0.122 m above the waterline), draft 0.443 m -> a 45-degree cone; below the
    // waterline it is continued straight to the keel (docs/model/validation_targets.md §4a, [U]).
    KeySpec p{"structure.profile", KeyType::kPairList, "m",
              PairList{{-0.443, 0.171}, {0.0, 0.614}, {0.122, 0.736}}, 0.0, 100.0, false, {},
              "hull profile as [height y, radius] stations from keel to deck (Table 2 cone)"};
    p.min = -100.0;
    k.push_back(p);
  }
  k.push_back(integer("structure.segments", 48, 8, 720,
                      "polygon sides approximating each circular station of the hull"));
  k.push_back(positive("structure.collision_margin", "m", 0.001, 0.1,
                       "Bullet's collision margin of the hull's pieces, which rounds them and grows them by "
                       "it (Bullet's own default: 0.04 m)"));
  // a moored structure's body (structure.motion = "moored"; dem/mooring/floating_structure.hpp)
  k.push_back(real("structure.mass", "kg", 0.0, 0.0, 1.0e9,
                   "moored: the structure's mass; 0: the mass that floats at the still-water line with its mooring's "
                   "pull, the water the hull displaces there less the lines' vertical pull over g (237.2 kg for the "
                   "default hull and linear mooring)"));
  // -0.05662 m: the default hull's centroid as a uniform solid (tests/physics/test_moored_structure.cpp
  // checks it against dem/mooring/floating_structure.cpp's hull_solid)
  k.push_back(real("structure.gravity_centre_y", "m", -0.05662, -100.0, 100.0,
                   "moored: height of the centre of gravity on the axis above the waterline (the default hull as a "
                   "uniform solid from keel to deck; `icedem check` prints a changed hull's)"));
  k.push_back(vector3("structure.inertia", "kg m^2", {0.0, 0.0, 0.0}, 0.0, 1.0e12,
                      "moored: moments of inertia about the centre of gravity, about x (roll), y (yaw) and z (pitch); "
                      "0: those of the hull as a uniform solid of structure.mass"));
  k.push_back(vector3("structure.added_mass", "kg", {-1.0, -1.0, -1.0}, -1.0, 1.0e12,
                      "moored: the water's added mass in surge (x), heave (y) and sway (z), constant; a negative "
                      "component: the estimate (surge and sway: strips of circles, the water the hull displaces; "
                      "heave: half the open-water disc of the waterline radius, (4/3) rho a^3)"));
  k.push_back(vector3("structure.added_inertia", "kg m^2", {-1.0, -1.0, -1.0}, -1.0, 1.0e12,
                      "moored: the water's added moment of inertia in roll (x), yaw (y) and pitch (z), constant; a "
                      "negative component: the estimate (the strips' added mass moving about the centre of gravity, "
                      "and the waterline disc's (8/45) rho a^5; none in yaw, the hull being round)"));
  k.push_back(vector3("structure.damping_ratio", "-", {0.05, 0.05, 0.05}, 0.0, 10.0,
                      "moored: linear damping in surge, heave and sway as a fraction of each motion's critical "
                      "damping 2 sqrt(k (m + m_a)), k the hydrostatic or mooring stiffness (an assumed value: set it "
                      "from a decay test or a radiation solver's damping)"));
  k.push_back(vector3("structure.angular_damping_ratio", "-", {0.05, 0.05, 0.05}, 0.0, 10.0,
                      "moored: the same in roll, yaw and pitch"));

  // mooring (structure.motion = "moored"; dem/mooring/)
  k.push_back(choice("mooring.model", "linear", {"linear", "catenary"},
                     "\"linear\": springs of mooring.stiffness and mooring.angular_stiffness between the structure's "
                     "attachment point and the carriage; \"catenary\": mooring.lines elastic catenary lines from "
                     "anchors on the tank's floor, moving with the carriage, to fairleads on the hull, quasi-static"));
  // 935 N/m: the static offset under the fixed cone's mean load on the paper's small floes (11.5 N, the
  // grid's records at f_ii 0.5, f_is 0.2) is then 1 % of the waterline diameter (12.3 mm), the
  // middle of the study's range (docs/model/mooring.md)
  k.push_back(vector3("mooring.stiffness", "N/m", {935.0, 0.0, 935.0}, 0.0, 1.0e12,
                      "linear: the mooring's stiffness along x (surge), y (heave) and z (sway) at its attachment point "
                      "(935 N/m: the fixed cone's mean load on the paper's small floes, 11.5 N, moves it 1 % of the "
                      "waterline diameter)"));
  k.push_back(vector3("mooring.angular_stiffness", "N m/rad", {0.0, 352.0, 0.0}, 0.0, 1.0e12,
                      "linear: about x (roll), y (yaw) and z (pitch); yaw 352: the surge stiffness spread at the "
                      "waterline radius, 935 x 0.614^2"));
  k.push_back(real("mooring.attachment_y", "m", 0.0, -100.0, 100.0,
                   "linear: height of the attachment point on the axis above the waterline"));
  k.push_back(integer("mooring.lines", 4, 1, 64, "catenary: number of lines, spread evenly around the axis"));
  k.push_back(real("mooring.first_line_angle", "deg", 45.0, -360.0, 360.0,
                   "catenary: direction of the first line from the axis, from +x towards +z"));
  k.push_back(positive("mooring.fairlead_radius", "m", 0.4, 100.0, "catenary: fairleads' distance from the axis"));
  k.push_back(real("mooring.fairlead_y", "m", -0.2, -100.0, 100.0, "catenary: fairleads' height above the waterline"));
  k.push_back(positive("mooring.anchor_radius", "m", 4.0, 1.0e4,
                       "catenary: anchors' distance from the axis, on the tank's floor (tank.depth)"));
  // the default lines: 0.21 m of each on the floor at rest, a spread about as stiff in surge as the
  // linear mooring's default (docs/model/mooring.md)
  k.push_back(positive("mooring.line_length", "m", 4.06, 1.0e4, "catenary: each line's unstretched length"));
  k.push_back(positive("mooring.line_weight", "N/m", 20.0, 1.0e6, "catenary: each line's submerged weight per metre"));
  k.push_back(positive("mooring.line_stiffness", "N", 1.0e5, 1.0e12, "catenary: each line's axial stiffness EA"));
  k.push_back(real("mooring.seabed_friction", "-", 0.0, 0.0, 10.0,
                   "catenary: friction of the part of a line lying on the floor"));

  // channel and tank
  k.push_back(real("channel.start_x", "m", 6.0, -1.0e4, 1.0e4,
                   "x where the floe field begins (paper: floes in x >= 6 m)"));
  k.push_back(positive("channel.length", "m", 24.0, 1.0e5,
                       "length of the floe field (paper: ~24 m; 24 km holds about 10^6 small floes)"));
  k.push_back(positive("channel.width", "m", 4.8, 1.0e3,
                       "width between the mother-ice edges, centred on z = 0 (paper: 4.8 m)"));
  k.push_back(boolean("channel.end_wall", true, "mother ice closes the far end of the channel"));
  k.push_back(real("channel.edge_friction_factor", "-", 1.0, 0.0, 10.0,
                   "friction of the floes on the mother ice (the channel's edges and end wall) as a multiple of "
                   "friction.ice_ice (1: ice on ice; the tank's edges may be cut smoother or rougher)"));
  k.push_back(positive("tank.width", "m", 6.0, 1.0e3, "tank breadth (Table 1: 6 m)"));
  k.push_back(real("tank.depth", "m", 1.8, 0.05, 1.0e3, "water depth (Table 1: 1.8 m)"));

  // ice
  k.push_back(choice("ice.cover", "floes", {"floes", "level"},
                     "what covers the channel: \"floes\" (a field of floes, ice.floe_size and ice.concentration, "
                     "or layout.file) or \"level\" (one continuous sheet over the channel's length and width: "
                     "with fracture.mode = \"on\" a lattice of breakable elements that moves within "
                     "fracture.lattice_radius of the structure axis and is held where it lies beyond, as the sheet "
                     "far from the structure is, dem/fracture/level_ice.hpp; with fracture.mode = \"analytic\" one "
                     "held sheet from which the structure's load breaks wedges at their closed-form breaking load, "
                     "the pieces rigid floes, dem/fracture/analytic_sheet.hpp)"));
  k.push_back(positive("ice.floe_size", "m", 0.3, 100.0, "side of the square floes (paper: 0.3 / 0.6 m)"));
  k.push_back(real("ice.thickness", "m", 0.033, 0.001, 10.0, "ice thickness (Table 3: 0.033 m)"));
  k.push_back(real("ice.concentration", "-", 0.75, 0.0, 0.9,
                   "area fraction of the channel covered by floes (paper: 0.75)", true));
  k.push_back(positive("ice.density", "kg/m^3", 930.0, 1.0e4, "ice density (Table 3)"));
  k.push_back(positive("ice.elastic_modulus", "Pa", 60.0e6, 1.0e12, "elastic modulus (Table 3)"));
  k.push_back(positive("ice.bending_strength", "Pa", 36.4e3, 1.0e9, "bending strength (Table 3)"));
  k.push_back(positive("ice.compressive_strength", "Pa", 145.6e3, 1.0e9,
                       "compressive strength (Table 3: 4 x bending)"));
  k.push_back(positive("ice.shear_strength", "Pa", 72.8e3, 1.0e9, "shear strength (Table 3: 2 x bending)"));
  k.push_back(real("ice.poisson_ratio", "-", 0.33, 0.0, 0.5, "Poisson ratio (characteristic length)"));
  k.push_back(boolean("ice.contact_crushing", false,
                      "limit the normal force of each contact (a floe pair, or a floe and the structure or "
                      "the mother ice) to the crushing force ice.compressive_strength x ice.thickness^2: "
                      "ice crushing over a patch as wide as the ice is thick. Off in the paper"));

  // layout
  k.push_back(text("layout.file", "",
                   "CSV or JSON file of floes (centre, yaw, polygon); empty: generate square floes. "
                   "Relative paths are relative to the scenario file"));
  k.push_back(real("layout.max_yaw_deg", "deg", 15.0, 0.0, 45.0,
                   "largest floe rotation about the vertical in a generated layout"));
  k.push_back(integer("layout.sweeps", 30, 0, 100000,
                      "Monte-Carlo relaxation sweeps that randomise a generated layout (30 suffice; at most "
                      "5e7 moves, sweeps x floes, about 25 s of set-up)"));
  k.push_back(real("layout.size_spread", "-", 0.0, 0.0, 0.9,
                   "generated floes' sides drawn uniformly from ice.floe_size (1 +- spread), as many as fill "
                   "ice.concentration (rigid floes only); 0: all alike"));
  k.push_back(real("layout.min_gap", "m", 0.002, 0.0, 1.0,
                   "smallest clearance between generated floes (keeps them out of contact at t = 0)"));
  k.push_back(integer("layout.layers", 1, 1, 10,
                      "rafted ice: a generated field repeated in this many layers, each its own "
                      "arrangement (seed + layer), layer k starting k ice thicknesses (plus "
                      "layout.min_gap) above the floating one; concentration is per layer"));

  // contact law (docs/model/crushing.md)
  k.push_back(choice("contact.model", "rigid", {"rigid", "crushing"},
                     "how the ice's contacts bear load: \"rigid\", a contact that does not yield (the "
                     "paper's); \"crushing\", the ice crushes at the contact at ice.compressive_strength over "
                     "a nominal contact area that grows with the overlap (Daley's pressure-area), so that an "
                     "impact lasts a finite time (dem/contact/crushing.hpp; needs solver.method = \"apgd\", "
                     "\"newton\" or \"pgs_cone\")"));
  k.push_back(choice("contact.crushing_contacts", "structure", {"structure", "structure_and_sheet", "all"},
                     "contact.model = \"crushing\": which contacts of ice crush: \"structure\", the ice "
                     "against the structure, those between floes and with the boundaries rigid; "
                     "\"structure_and_sheet\", also a floe against the held level sheet's edge (ice.cover = "
                     "\"level\", fracture.mode = \"analytic\"; docs/model/crushing.md, \"Against the level "
                     "sheet\"); \"all\", every contact of ice. In a locked pack the contacts between floes "
                     "crush on and their overlap passes the ice's thickness, where it no longer stands for crushed "
                     "ice: the floes pass through each other (docs/model/crushing.md, \"Between floes\")"));
  k.push_back(real("contact.pressure_area_exponent", "-", 0.0, -0.9, 0.0,
                   "contact.model = \"crushing\": ex in the crushing pressure sigma_c (A / h^2)^ex over the "
                   "nominal contact area A (Daley's pressure-area relation; 0: a constant pressure, the "
                   "compressive strength; field data give -0.1 (ship rules) to -0.7 (small areas))"));

  // friction (Coulomb; combined by material pair, not Bullet's product rule)
  k.push_back(real("friction.ice_ice", "-", 0.5, 0.0, 5.0,
                   "ice-ice friction f_ii, also floe against mother ice (paper: 0.3/0.5/0.7)"));
  k.push_back(real("friction.ice_structure", "-", 0.2, 0.0, 5.0,
                   "ice-structure friction f_is (paper: 0.1/0.2/0.3)"));
  k.push_back(real("friction.ice_ice_static", "-", 0.0, 0.0, 5.0,
                   "static ice-ice friction of contacts that stick (slip slower than friction.stick_speed), "
                   "at least friction.ice_ice; 0: none, friction.ice_ice throughout"));
  k.push_back(real("friction.ice_structure_static", "-", 0.0, 0.0, 5.0,
                   "static ice-structure friction of contacts that stick, at least friction.ice_structure; "
                   "0: none"));
  k.push_back(positive("friction.stick_speed", "m/s", 1.0e-3, 1.0,
                       "slip speed below which a contact sticks (takes the static coefficient)"));

  // water
  k.push_back(positive("water.density", "kg/m^3", 1000.0, 1.0e4, "water density (Table 3)"));
  k.push_back(positive("water.gravity", "m/s^2", 9.81, 100.0, "gravitational acceleration"));
  k.push_back(real("water.drag_coefficient", "-", 1.0, 0.0, 10.0,
                   "form drag C_d of wetted faces facing the relative flow (bluff edge, "
                   "docs/model/validation_targets.md §5)"));
  k.push_back(real("water.skin_friction_coefficient", "-", 0.0092, 0.0, 1.0,
                   "skin friction C_f of wetted faces (laminar Blasius 1.328/sqrt(Re), Re = 2.1e4)"));
  k.push_back(real("water.heave_damping_ratio", "-", 0.5, 0.0, 10.0,
                   "heave damping as a fraction of critical (radiation damping; assumption)"));
  k.push_back(real("water.roll_pitch_damping_ratio", "-", 0.5, 0.0, 10.0,
                   "roll and pitch damping as a fraction of critical (assumption)"));
  k.push_back(boolean("water.added_mass", false,
                      "give each floe the water's added mass in heave, roll and pitch: a disc of equal area, "
                      "impulsive limit (dem/water/added_mass.hpp; a 0.6 m floe's heave added mass is 4.7 times "
                      "its mass)"));
  k.push_back(choice("water.buoyancy", "exact", {"exact", "linear"},
                     "exact: Archimedes on the clipped body (the reaction stops growing once the ice is "
                     "under); linear: an ablation, the water under the ice pushing up in proportion to its "
                     "depth however deep, as a floating beam's Winkler foundation assumes (the water on top "
                     "of a submerged face presses on nothing)"));

  // flow
  k.push_back(choice("flow.model", "potential", {"still", "uniform", "potential", "coupled"},
                     "water velocity model: still water, uniform current, potential flow around the "
                     "structure (cylinder of the local radius), or coupled OpenFOAM"));
  {
    KeySpec v{"flow.velocity", KeyType::kVector3, "m/s", Vector3Value{0.0, 0.0, 0.0}, -100.0, 100.0,
              false, {}, "current velocity [x, y, z] for flow.model = \"uniform\""};
    k.push_back(v);
  }

  // coupling: the OpenFOAM potential-flow case (flow.model = "coupled")
  k.push_back(choice("coupling.mode", "field", {"field", "probe"},
                     "field: the solved velocity sampled once on a grid that the DEM interpolates every "
                     "step; probe: OpenFOAM samples the flow at the floes at every exchange"));
  k.push_back(choice("coupling.mesh", "coarse", {"coarse", "medium", "fine"},
                     "OpenFOAM mesh: background cells 0.2 / 0.1 / 0.1 m, refined at the hull to 0.05 / "
                     "0.025 / 0.0125 m"));
  k.push_back(text("coupling.cache_dir", "",
                   "where solved cases are kept, one directory per hash of the case inputs; empty: "
                   "$ICEDEM_FOAM_CACHE, else ~/.cache/icedem/foam. Relative paths are relative to the "
                   "scenario file"));
  k.push_back(real("coupling.domain_length", "m", 10.0, 2.0, 1000.0,
                   "length of the OpenFOAM domain along x, centred on the structure axis (the width "
                   "and depth are the tank's)"));
  k.push_back(real("coupling.grid_spacing", "m", 0.05, 0.005, 1.0,
                   "spacing of the grid the velocity is sampled on (field mode)"));
  k.push_back(integer("coupling.exchange_steps", 50, 1, 1000000,
                      "probe mode: steps between exchanges with the OpenFOAM partner (the drag is held "
                      "between them)"));
  k.push_back(positive("coupling.timeout", "s", 120.0, 1.0e5,
                       "probe mode: longest wait for the partner's hello or a response before the run "
                       "stops with an error (the HDF5 file keeps the run so far)"));
  k.push_back(text("coupling.exchange_dir", "",
                   "probe mode: the exchange directory (coupling/PROTOCOL.md); empty: a new temporary "
                   "directory. Relative paths are relative to the scenario file"));
  k.push_back(choice("coupling.partner", "spawn", {"spawn", "external"},
                     "probe mode: spawn the OpenFOAM partner (coupling/foam_partner.py) as a child "
                     "process, or wait for one started separately on coupling.exchange_dir"));
  k.push_back(real("coupling.grid_depth", "m", 0.6, 0.05, 100.0,
                   "the sampled grid spans y from -grid_depth to the still-water line; deeper points "
                   "take the deepest level"));

  // fracture
  k.push_back(choice("fracture.mode", "off", {"off", "on", "auto", "analytic"},
                     "breakable ice elements: off (rigid floes), on, or auto (only floes larger "
                     "than the characteristic length); analytic: rigid floes that split in two when "
                     "the structure's load normal to a floe reaches the breaking edge load of a "
                     "floating beam, and level ice (ice.cover = \"level\") cut by closed forms "
                     "(docs/model/breakage.md)"));
  k.push_back(real("fracture.element_size", "m", 0.15, 0.01, 100.0,
                       "side of the square ice elements (paper: 0.15 / 0.20 m); for hexagons, the distance "
                       "between neighbouring elements' centres (their width across flats)"));
  k.push_back(choice("fracture.element_shape", "square", {"square", "hexagon"},
                     "the ice elements' shape: \"square\" (the paper's) or \"hexagon\". A floe that is a "
                     "rectangle a whole number of squares across is cut into them; any other outline (a photo's, "
                     "a layout file's) and every hexagonal lattice is filled with elements cut at the outline, "
                     "joined across the faces they share, each joint's capacities and springs scaled by its "
                     "face's length (docs/model/breakage.md)"));
  k.push_back(choice("fracture.tiling", "corner", {"corner", "fitted"},
                     "where the element tiling of an outline lattice (fracture.element_shape) is anchored: "
                     "\"corner\", at the outline's lower corner; \"fitted\", shifted to where it cuts the fewest "
                     "parts below a quarter and below half a cell (a small part's joints have the capacities of "
                     "its short faces, and broke 1.8-3.5 times as often as whole hexagons' on the paper's floes; "
                     "docs/model/breakage.md). A rectangle of whole squares keeps the corner"));
  k.push_back(real("fracture.strength_scale", "-", 1.0, 1.0e-3, 1.0e3,
                   "factor on every joint's bending capacity (eq. 3, each face's): 1 for squares, whose lattice "
                   "breaks at the bending strength along its grid (the cantilevers); a hexagonal lattice is "
                   "stronger in bending across any line than its faces' capacities say (the wide cantilever: "
                   "1.20-1.40 times at 0.15 m), and its calibrated scale brings its bending strength to the ice's "
                   "in every direction. Compression and shear (eqs. 1-2) are not scaled: in the plate's plane "
                   "the unscaled hexagons break at the compressive strength along x as the squares do "
                   "(docs/model/breakage.md, \"Strength by direction\")"));
  k.push_back(real("fracture.lattice_angle", "deg", 0.0, -180.0, 180.0,
                   "turn of the element grid from each breakable floe's principal axes, about the vertical as a "
                   "yaw: 0 lays the grid along them (the paper's); any other angle makes every breakable floe an "
                   "outline lattice, its elements cut at the outline. The wide cantilever measures a lattice's "
                   "strength by the direction of its load with it (docs/model/breakage.md)"));
  k.push_back(real("fracture.cfm", "-", 1.0e-10, 0.0, 1.0,
                   "constraint force mixing of the element joints (Bullet units); the joints' "
                   "stiffness depends on it and on the step: recalibrate (icedem calibrate) when "
                   "time.dt or time.substeps change"));
  k.push_back(real("fracture.erp", "-", 0.8, 0.0, 1.0,
                   "error reduction of the element joints (paper: 0.8); fracture.joint_stiffness = \"cfm\" only"));
  k.push_back(choice("fracture.joint_stiffness", "elastic", {"cfm", "elastic"},
                     "what sets the element joints' stiffness: \"cfm\", fracture.cfm and fracture.erp in Bullet's "
                     "units (the stiffness then grows as 1/step^2); \"elastic\", each joint row a spring of the "
                     "ice between two element centres (ice.elastic_modulus, ice.poisson_ratio, ice.thickness, "
                     "fracture.element_size; docs/model/breakage.md), the same at any step"));
  k.push_back(real("fracture.stiffness_scale", "-", 1.0, 1.0e-3, 1.0e3,
                   "fracture.joint_stiffness = \"elastic\": factor on every joint row's stiffness, calibrated "
                   "once per element size on the plate-deflection test (icedem calibrate; 0.751 for 0.15 m, "
                   "0.621 for 0.20 m elements: a lattice of rigid squares is stiffer than the plate it stands for)"));
  k.push_back(integer("fracture.joint_iterations", 0, 0, 100000,
                      "PGS iterations for the element joints (Bullet's per-constraint override; "
                      "contacts keep solver.iterations); 0: solver.iterations"));
  k.push_back(real("fracture.lattice_radius", "m", 0.0, 0.0, 1.0e4,
                   "a breakable floe is its element lattice while some part of it is within this "
                   "horizontal distance of the structure axis, else one rigid body (an intact "
                   "lattice turns back 0.5 m beyond it; a broken one stays); 0: lattices always. Level ice "
                   "(ice.cover = \"level\"): the sheet moves within this distance and is held where it lies "
                   "beyond it (required)"));
  k.push_back(real("fracture.load_filter_time", "s", 0.0, 0.0, 100.0,
                   "time constant of a first-order low-pass on each joint's loads before the "
                   "failure check (damps one-step PGS spikes); 0: the raw per-step loads"));

  // activation (skip what the scene does not need)
  k.push_back(boolean("activation.sleeping", true,
                      "let bodies at rest sleep (no solve, no water forces) until touched"));
  k.push_back(choice("activation.islands", "contact", {"contact", "bullet"},
                     "how sleeping islands are built: from touching contacts, or Bullet's "
                     "bounding-box overlap (which makes a 75 % field one island)"));
  k.push_back(boolean("activation.skip_asleep", true,
                      "water forces and joint failure checks only on awake bodies (a sleeping body is "
                      "not integrated and its joint feedback is stale); false computes them for every "
                      "body, to measure what the skip saves (scripts/ladder)"));
  k.push_back(positive("activation.linear_threshold", "m/s", 0.005, 10.0,
                       "speed below which a body may fall asleep (Bullet default 0.8 is for games)"));
  k.push_back(positive("activation.angular_threshold", "rad/s", 0.02, 100.0,
                       "angular speed below which a body may fall asleep"));
  k.push_back(positive("activation.time", "s", 1.0, 1.0e4,
                       "time below both thresholds before a body sleeps"));

  k.push_back(boolean("activation.unreached_out_of_world", true,
                      "floes at rest that no moving body has come near stay out of Bullet's world until "
                      "one does (dem/world/unreached_floes.hpp): a field's cost follows the disturbed ice, "
                      "results as with them in it; needs activation.sleeping and islands = \"contact\""));
  k.push_back(boolean("activation.freeze_outside_region", false,
                      "resting floes outside the activation region become fixed obstacles until "
                      "struck or reached (dem/activation/activation.hpp): 2-3x faster, but the frozen field "
                      "cannot creep, which shortens peak spacing and raises peaks (docs/model/physics.md)"));
  k.push_back(real("activation.region_ahead", "m", 3.0, 0.0, 1.0e4,
                   "activation region: distance ahead of the structure axis where no floe is frozen"));
  k.push_back(real("activation.region_behind", "m", 2.0, 0.0, 1.0e4,
                   "activation region: distance behind the structure axis where no floe is frozen"));
  k.push_back(real("activation.leave_behind", "m", 0.0, 0.0, 1.0e4,
                   "rigid floes lying wholly farther than this behind the structure axis leave the run for good "
                   "(dem/activation/left_behind.hpp): the channel far behind costs nothing, but beyond it "
                   "pushes nothing back; 0: none leaves (docs/model/breakage.md, \"The jam\": how far is far enough)"));

  // output
  k.push_back(real("output.snapshot_interval", "s", 1.0, 0.0, 1.0e6,
                   "interval of body-pose snapshots in the HDF5 file; 0: none"));
  k.push_back(real("output.checkpoint_interval", "s", 30.0, 0.0, 1.0e6,
                   "simulated time between two checkpoints (OUT.h5.checkpoint), from which `icedem resume` "
                   "continues a killed run; 0: none. Not written for validation cases, runs exchanging drag with "
                   "OpenFOAM (coupling.mode = \"probe\") and --export-problems runs"));
  k.push_back(real("output.stop_grace", "s", 20.0, 0.0, 1.0e6,
                   "wall time a run asked to stop (SIGINT, SIGTERM: Ctrl-C, a Slurm preemption) may take to reach "
                   "its next checkpoint, judged from its pace so far: if it can, it goes on and stops there, so "
                   "that `icedem resume` loses nothing and still ends bit for bit as the uninterrupted run; if "
                   "not, it stops at once (resumable from the checkpoint before). A second signal stops it at "
                   "once; 0: always at once"));

  // statistics
  k.push_back(real("stats.window_start_travel", "m", 2.456, 0.0, 1.0e4,
                   "analysis window starts after the structure travels this far beyond its first "
                   "ice contact (default 2 waterline breadths)"));
  k.push_back(real("stats.window_end_travel", "m", 0.0, 0.0, 1.0e4,
                   "window ends this far beyond first contact; 0: at the end of the run"));
  k.push_back(real("stats.lowpass_hz", "Hz", 0.0, 0.0, 1.0e3,
                   "low-pass cut-off applied to the surge load before statistics; 0: none"));
  k.push_back(boolean("stats.include_squeeze", false,
                      "keep in the statistics the steps where the structure squeezes the ice against the channel's "
                      "end wall (the rig's load, not the ice's: dem/input/structure_path.hpp); false ends the "
                      "analysis window where the squeeze begins"));

  // validation cases (scenarios/validation/)
  k.push_back(choice("validation.case", "none", {"none", "plate_deflection", "cantilever", "wide_cantilever"},
                     "validation case: plate_deflection, a floating plate of elements under a central "
                     "point load (seed paper Fig. 6) against Hertz's plate; cantilever, a clamped beam "
                     "of elements in air loaded at its tip until it breaks (Fig. 7, eq. 6); wide_cantilever, "
                     "a plate of any elements (validation.beam_length x beam_width, the grid turned by "
                     "fracture.lattice_angle) clamped along one edge in air and loaded along the other until "
                     "it breaks: its bending strength across the grid in that direction"));
  k.push_back(integer("validation.beam_elements", 4, 2, 100, "cantilever: elements along the beam, root included"));
  k.push_back(positive("validation.beam_length", "m", 0.9, 100.0,
                       "wide_cantilever: the plate's length along x, from its clamped edge to its loaded one"));
  k.push_back(positive("validation.beam_width", "m", 0.45, 100.0,
                       "wide_cantilever: the plate's width along z, the length of the line that breaks"));
  k.push_back(positive("validation.load_rate", "N/s", 0.2, 1.0e4, "cantilever: growth rate of the tip load"));
  k.push_back(choice("validation.plate_load", "down", {"down", "along"},
                     "wide_cantilever: down, the far edge's load bends the plate (its bending strength); along, "
                     "it pushes the plate towards its clamped edge in its plane (its compressive strength, "
                     "the first joint to break in compression or shear)"));
  k.push_back(real("validation.tip_speed", "m/s", 0.0, 0.0, 10.0,
                   "cantilever: > 0 floats the beam and pushes its tip down at this speed (the "
                   "paper's test, eq. 6 with the fragment's buoyancy); 0: a load ramp in air"));
  k.push_back(positive("validation.plate_size", "m", 2.7, 100.0, "side of the square plate (paper: 2.7 / 5.4 m)"));
  k.push_back(positive("validation.load", "N", 10.0, 1.0e4, "downward point load at the plate centre"));
  k.push_back(positive("validation.tolerance", "-", 0.05, 10.0,
                       "accepted relative error of the validation metric (docs/model/validation_targets.md: 5 %)"));
  return k;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t subst = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, subst});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string format_number(double v) {
  // shortest text that reads back to the same double
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

}  // namespace

const std::vector<KeySpec>& scenario_keys() {
  static const std::vector<KeySpec> keys = make_keys();
  return keys;
}

const KeySpec* find_key(const std::string& path) {
  for (const KeySpec& k : scenario_keys())
    if (k.path == path) return &k;
  return nullptr;
}

bool is_section(const std::string& path) {
  const std::string prefix = path + ".";
  for (const KeySpec& k : scenario_keys())
    if (k.path.compare(0, prefix.size(), prefix) == 0) return true;
  return false;
}

std::string nearest_key(const std::string& path) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  auto consider = [&](const std::string& candidate) {
    const std::size_t d = edit_distance(path, candidate);
    if (d < best_d) best_d = d, best = candidate;
  };
  for (const KeySpec& k : scenario_keys()) {
    consider(k.path);
    const auto dot = k.path.find('.');
    if (dot != std::string::npos) consider(k.path.substr(0, dot));
  }
  // a hint is only useful when it is close: allow a third of the length, at least 2 edits
  const std::size_t allowed = std::max<std::size_t>(2, path.size() / 3);
  return best_d <= allowed ? best : "";
}

std::string describe_expected(const KeySpec& s) {
  std::string range;
  const bool has_min = std::isfinite(s.min), has_max = std::isfinite(s.max);
  if (has_min && has_max)
    range = fmt::format(" in {}{}, {}]", s.min_exclusive ? "(" : "[", s.min, s.max);
  else if (has_min)
    range = fmt::format(" {} {}", s.min_exclusive ? ">" : ">=", s.min);
  const std::string unit = s.unit.empty() || s.unit == "-" ? "" : " (" + s.unit + ")";
  switch (s.type) {
    case KeyType::kReal: return "a number" + range + unit;
    case KeyType::kInteger: return "a whole number" + range;
    case KeyType::kBoolean: return "true or false";
    case KeyType::kString: return "a string";
    case KeyType::kChoice: {
      std::string list;
      for (const auto& c : s.choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
      return "one of " + list;
    }
    case KeyType::kVector3: return "an array of 3 numbers [x, y, z]" + range + unit;
    case KeyType::kPairList: return "an array of at least 2 [a, b] number pairs" + range + unit;
  }
  return "";
}

std::string format_value(const KeyValue& value) {
  struct Visitor {
    std::string operator()(double v) const { return format_number(v); }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const {
      std::string out = "\"";
      for (char c : v) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      return out + "\"";
    }
    std::string operator()(const Vector3Value& v) const {
      return "[" + format_number(v[0]) + ", " + format_number(v[1]) + ", " + format_number(v[2]) + "]";
    }
    std::string operator()(const PairList& v) const {
      std::string out = "[";
      for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? ", [" : "[") + format_number(v[i][0]) + ", " + format_number(v[i][1]) + "]";
      return out + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

std::string keys_markdown() {
  std::ostringstream out;
  out << "# Scenario keys\n\n"
      << "Generated by `icedem keys` from dem/input/scenario_keys.cpp; do not edit by hand.\n"
      << "Every key is optional; a scenario file overrides the defaults below, and\n"
      << "`icedem run FILE --set key.path=value` overrides the file.\n\n"
      << "| key | unit | default | allowed | meaning |\n|---|---|---|---|---|\n";
  for (const KeySpec& k : scenario_keys()) {
    std::string value = format_value(k.default_value);
    out << "| `" << k.path << "` | " << (k.unit.empty() ? "" : k.unit) << " | `" << value
        << "` | " << describe_expected(k) << " | " << k.doc << " |\n";
  }
  return out.str();
}

}  // namespace icedem
