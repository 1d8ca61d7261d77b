// The contact problem of one island in one Bullet step, as data: what every
// contact solver method solves, what a problem file holds, and what the merit
// function judges.
//
// Velocities are per body (v, w): linear m/s and angular rad/s in the tank
// frame; impulses are N s over the step. For the unknown body velocities v
// (bodies with finite mass only; fixed, frozen and kinematic bodies are data),
// contact impulses r (per contact: normal, tangent 1, tangent 2) and joint
// multipliers l, the problem is (FCLIB's global form, with compliant joints):
//
//   M v = M v_free + J_c^T r + J_j^T l                   momentum over the step
//   u   = J_c v + w                                      contact velocities
//   J_j v + b + C l = 0                                  joint rows, compliance C
//   K* contains u + (mu |u_T|, 0, 0)  _|_  r in K        Coulomb's law (De Saxce)
//
// with K = { |r_T| <= mu r_N } per contact. u_N >= 0 is separation, and w holds
// what the step's geometry asks of the velocities (a gap closing this step, a
// moving structure). The joint rows are soft: C > 0 is a spring and damper
// (dem/world/contact_capture.cpp says how Bullet's ERP and CFM map onto b and C).
// A crushing contact (dem/contact/crushing.hpp) carries at most the normal impulse c
// its overlap can bear: its set is K cut at r_N <= c (rigid below c).
//
// Eliminating v and l gives the local (dual) form, the Delassus problem
//   u = W r + q,  W = J_c Mt^-1 J_c^T,  q = J_c Mt^-1 ft + w,
//   Mt = M + J_j^T C^-1 J_j,  ft = M v_free - J_j^T C^-1 b,
// in which the joints are folded into Mt.
#pragma once

#include <cmath>

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace icedem {

using Vector6d = Eigen::Matrix<double, 6, 1>;
/// Rows normal, tangent 1, tangent 2 of a contact on one body; columns (v, w).
using ContactJacobian = Eigen::Matrix<double, 3, 6>;
/// One joint row on one body; columns (v, w).
using RowJacobian = Eigen::Matrix<double, 1, 6>;

struct ProblemBody {
  double mass = 0;                              // kg
  // kg along the tank's axes, on top of `mass`: the water's added mass (dem/water/added_mass.hpp)
  Eigen::Vector3d added_mass = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // kg m^2 about the centre of mass, tank frame (added included)
  Vector6d free_velocity = Vector6d::Zero();    // (v, w) after the step's applied forces, before contact
  int id = -1;                                  // the body's index in World::floes(), -1 if none
};

struct ProblemContact {
  int a = -1, b = -1;       // problem bodies; -1: a body without unknown velocity
  ContactJacobian ja = ContactJacobian::Zero(), jb = ContactJacobian::Zero();
  Eigen::Vector3d w = Eigen::Vector3d::Zero();      // m/s, u = ja v_a + jb v_b + w
  double mu = 0;                                    // Coulomb friction coefficient
  Eigen::Vector3d guess = Eigen::Vector3d::Zero();  // N s, warm start (normal, t1, t2)
  bool on_structure = false;                        // one side is the structure
  // N s, the largest normal impulse: a crushing contact's h F(delta) (dem/contact/crushing.hpp);
  // infinite for a rigid contact
  double normal_cap = std::numeric_limits<double>::infinity();
};

struct ProblemJointRow {
  int a = -1, b = -1;
  RowJacobian ja = RowJacobian::Zero(), jb = RowJacobian::Zero();
  double bias = 0;        // m/s (or rad/s), b in J v + b + C l = 0
  double compliance = 0;  // (m/s)/(N s), C
  double guess = 0;       // N s, warm start
  int joint = -1;         // index in World::joints(), -1 if none
};

struct ContactProblem {
  std::vector<ProblemBody> bodies;
  std::vector<ProblemContact> contacts;
  std::vector<ProblemJointRow> joints;
  // where it came from
  double time = 0;        // s, end of the Bullet step
  double dt = 0;          // s, the Bullet step
  long step = 0;          // run step
  int island = 0;         // solve group within the Bullet step
  std::string source;     // scenario or test that made it
  bool box_friction = false;  // Bullet's rows clamp each tangent to mu r_N on its own

  int dofs() const { return 6 * static_cast<int>(bodies.size()); }
  int contact_rows() const { return 3 * static_cast<int>(contacts.size()); }
  int joint_rows() const { return static_cast<int>(joints.size()); }
};

/// What a solver made of a problem: its impulses and how its iterations ended.
struct SolverAnswer {
  Eigen::VectorXd r;      // contact impulses, N s (normal, t1, t2 per contact)
  Eigen::VectorXd l;      // joint row impulses, N s
  int sweeps = 0;
  double residual = 0;    // the sweep solver's own estimate (dem/world/contact_solver.hpp)
  bool capped = false;    // stopped at the cap above its tolerance
};

/// `p` with `a`'s impulses as its warm start: a method goes on from another's answer.
ContactProblem started_from(const ContactProblem& p, const SolverAnswer& a);

/// A body's 6x6 inverse mass matrix: 1/m on the linear block, the inverse inertia on the angular.
Eigen::Matrix<double, 6, 6> inverse_mass(const ProblemBody& body);

/// The warm start of the contacts (normal, t1, t2 per contact) and of the joint rows, N s.
Eigen::VectorXd contact_guess(const ContactProblem& p);
Eigen::VectorXd joint_guess(const ContactProblem& p);

/// The sparse matrices and vectors of the global form.
struct GlobalForm {
  Eigen::SparseMatrix<double> M;   // dofs x dofs, block diagonal
  Eigen::SparseMatrix<double> Jc;  // contact_rows x dofs (FCLIB's H^T)
  Eigen::SparseMatrix<double> Jj;  // joint_rows x dofs (FCLIB's G^T)
  Eigen::VectorXd v_free, w, b, compliance, mu;
};
GlobalForm global_form(const ContactProblem& p);

/// The soft joints folded into the mass matrix, sparse: Mt = M + Jj^T C^-1 Jj and
/// ft = M v_free - Jj^T C^-1 b. Throws std::invalid_argument if a joint row is rigid.
struct FoldedMassMatrix {
  Eigen::SparseMatrix<double> Mt;
  Eigen::VectorXd ft;
};
FoldedMassMatrix folded_mass_matrix(const GlobalForm& g);

/// The soft joints folded into the mass matrix: Mt^-1 (block diagonal over groups of
/// jointed bodies) and ft. Throws std::invalid_argument if a joint row is rigid.
struct FoldedMass {
  Eigen::SparseMatrix<double> Mt_inv;
  Eigen::VectorXd ft;
};
FoldedMass fold_joints(const ContactProblem& p, const GlobalForm& g);

/// The joint impulses that go with contact impulses r when the joints are folded:
/// l = -(Jj v + b) / C with v = Mt^-1 (Jc^T r + ft).
Eigen::VectorXd joint_impulses(const ContactProblem& p, const Eigen::VectorXd& r);

/// The Delassus form u = W r + q with the joints folded in. Throws std::invalid_argument
/// if a joint row is rigid (compliance 0): it cannot be folded.
struct LocalForm {
  Eigen::SparseMatrix<double> W;  // contact_rows x contact_rows, symmetric
  Eigen::VectorXd q, mu;
  Eigen::VectorXd cap;  // the contacts' normal caps where some crush (normal_caps), else empty
};
LocalForm local_form(const ContactProblem& p);

/// |q| of the local form, computed without forming W (the merit's scale). With a rigid
/// joint row (no local form) |J_c v_free + w|, the joints left out.
double local_q_norm(const ContactProblem& p);
double local_q_norm(const GlobalForm& g);
/// q itself (3 per contact), as local_q_norm computes it.
Eigen::VectorXd local_q(const GlobalForm& g);

/// Whether a contact of the problem crushes (has a finite normal_cap).
bool has_crushing(const ContactProblem& p);

/// Each contact's normal_cap (infinity for a rigid contact).
Eigen::VectorXd normal_caps(const ContactProblem& p);

/// Whether a contact of the problem is on the structure (its impulses make the load).
bool touches_structure(const ContactProblem& p);

/// The impulse the contacts on the structure give it over the step, N s, tank frame:
/// the ice load times the step.
Eigen::Vector3d structure_impulse(const ContactProblem& p, const Eigen::VectorXd& r);

/// Body velocities, stacked (v, w) per body, after impulses r (contacts) and l (joint rows).
Eigen::VectorXd velocities(const GlobalForm& g, const Eigen::VectorXd& r, const Eigen::VectorXd& l);

/// The merit every solver is judged by: the natural-map residual of Coulomb's law
/// in De Saxce's form, |r - P_K(r - u - (mu |u_T|, 0, 0))| over all contacts,
/// relative to max(|q|, |r|, |u|) as Siconos numerics 4.4 computes it
/// (fc3d_compute_error). Dimensionless; 0 at a solution.
/// `cap` (empty: none) bounds each contact's normal impulse (normal_caps).
double natural_map_residual(const Eigen::Ref<const Eigen::VectorXd>& r, const Eigen::Ref<const Eigen::VectorXd>& u,
                            const Eigen::VectorXd& mu, double q_norm, const Eigen::VectorXd& cap = Eigen::VectorXd());
/// The same on the local form, with u = W r + q.
double natural_map_residual(const LocalForm& local, const Eigen::VectorXd& r);
/// The natural map's squared norm before any normalisation, |r - P_K(r - rho (u + (mu |u_T|, 0, 0)))|^2
/// summed over the contacts, rho per contact (empty: 1, Siconos' map).
double natural_map_squared(const Eigen::Ref<const Eigen::VectorXd>& r, const Eigen::Ref<const Eigen::VectorXd>& u,
                           const Eigen::VectorXd& mu, const Eigen::VectorXd& rho,
                           const Eigen::VectorXd& cap = Eigen::VectorXd());

/// |(t1, t2)|. Not std::hypot: its guard against overflow (at 1e154) costs about ten
/// times the square root, and it was 12 % of a run's CPU in the contact methods;
/// impulses and velocities are nowhere near its range.
inline double tangential_norm(double t1, double t2) { return std::sqrt(t1 * t1 + t2 * t2); }

/// Projection of x = (normal, t1, t2) onto the cone |x_T| <= mu x_N (inline: the
/// methods call it for every contact in every iteration). The two tests compare squares,
/// so that only a point projected onto the cone's surface pays for a square root.
inline Eigen::Vector3d project_on_cone(const Eigen::Vector3d& x, double mu) {
  const double tangent2 = x(1) * x(1) + x(2) * x(2), normal2 = mu * mu * x(0) * x(0);
  if (x(0) <= 0 && tangent2 * mu * mu <= x(0) * x(0)) return Eigen::Vector3d::Zero();  // in the polar cone
  if (x(0) >= 0 && tangent2 <= normal2) return x;                                      // inside
  const double tangent = std::sqrt(tangent2);
  const double normal = (mu * tangent + x(0)) / (mu * mu + 1.0);
  return {normal, mu * normal * x(1) / tangent, mu * normal * x(2) / tangent};
}

/// Projection of x = (normal, t1, t2) onto the cone cut at x_N = cap (the set of a crushing
/// contact): the cone's projection where its normal is at most
/// the cap, else the nearest point of the cut's disc, (cap, x_T clipped to mu cap): the cone's
/// nearest point being above the cut, the truncated cone's is on the cut (the distance to the
/// cone's surface grows along its generators away from that point).
inline Eigen::Vector3d project_on_contact(const Eigen::Vector3d& x, double mu, double cap) {
  const Eigen::Vector3d p = project_on_cone(x, mu);
  if (p(0) <= cap) return p;
  const double tangent = tangential_norm(x(1), x(2)), radius = mu * cap;
  const double s = tangent > radius ? radius / tangent : 1.0;
  return {cap, s * x(1), s * x(2)};
}

}  // namespace icedem
