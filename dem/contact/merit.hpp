// The merit a contact method stops on: how far an island's impulses are from
// Coulomb's law (dem/contact/problem.hpp has the problem).
//
// Two measures, both the natural map of De Saxce's form, r - P_K(r - rho (u + (mu |u_T|, 0, 0))),
// zero at a solution:
//
//  - "siconos": rho = 1 and the norm over all contacts divided by max(|q|, |r|, |u|),
//    exactly as Siconos numerics 4.4 (natural_map_residual). The common measure of the
//    contact-problem library and the literature: bench/contact/ ranks methods by it.
//    It mixes units (impulses, N s, with velocities, m/s), and |q| and |u| hold the
//    gap-closing speed gap / h of every manifold point that is not touching: on the
//    0.20 m lattices at h = 0.01 s they were 90 % of |q| and |q| was ten times |r|. So
//    the same number is a looser solve at a smaller step: relative to the loads, the
//    error it allows grows as 1 / h^2 (|q| ~ 1 / h, |r| ~ h). At dt/2 the 0.20 m lattices
//    solved to 1e-3 / 1e-4 broke 26 joints in 2 of 5 seeds, at dt 3 joints in 1 of 5, and
//    at dt/2 to 1e-5 none (docs/model/convergence.md, "The merit").
//
//  - "impulse" (what a run stops on): rho_c = the contact's effective mass
//    3 / trace(J_c M^-1 J_c^T), so every component is an impulse (a velocity error times
//    the mass it moves), and the norm is divided by the island's impulses,
//    max(|r|, |rho q_N^-|, g h |rho|): q_N^- the normal free velocity of each approaching
//    contact (|rho q_N^-| the impulses that stop them: the scale of an impact; an open gap,
//    q_N > 0, adds nothing), and g h |rho| the impulses of the contacts' effective weights
//    over the step (a floor: a force error far below the weight of the ice a contact moves
//    is none that matters, and islands of floes resting on each other carry almost
//    nothing). Each term is an impulse over the step, so the value is the forces' error
//    relative to the forces (or to those weights), the same at any step.
#pragma once

#include <string>

#include <Eigen/Core>

#include "dem/contact/problem.hpp"

namespace icedem {

enum class MeritKind { kImpulse, kSiconos };

/// "impulse" or "siconos"; throws std::invalid_argument otherwise.
MeritKind merit_kind(const std::string& name);
const char* merit_name(MeritKind kind);

/// Each contact's effective mass, kg: 3 / trace(J_c M^-1 J_c^T), with the bodies' own
/// masses (joints not folded in, so that every method computes the same).
Eigen::VectorXd contact_masses(const ContactProblem& p);

class Merit {
 public:
  /// `q`: the contacts' velocities at zero impulse (the local form's q, joints folded in);
  /// `masses`: contact_masses (unused by "siconos": may be empty); `mu` per contact; `dt`:
  /// the step, s.
  /// `mu` is kept by reference: it must outlive the merit.
  Merit(MeritKind kind, const Eigen::Ref<const Eigen::VectorXd>& q, Eigen::VectorXd masses, const Eigen::VectorXd& mu,
        double dt);
  /// The merit of problem p's contacts: the masses computed only where the kind uses them
  /// (every island of every step builds one), each crushing contact's normal bounded by its cap
  /// (normal_caps: the set of a crushing contact, dem/contact/crushing.hpp).
  Merit(MeritKind kind, const ContactProblem& p, const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::VectorXd& mu)
      : Merit(kind, q, kind == MeritKind::kImpulse ? contact_masses(p) : Eigen::VectorXd(), mu, p.dt) {
    if (has_crushing(p)) cap_ = normal_caps(p);
  }

  MeritKind kind() const { return kind_; }

  /// The merit of contact impulses r with contact velocities u (3 per contact).
  double operator()(const Eigen::Ref<const Eigen::VectorXd>& r, const Eigen::Ref<const Eigen::VectorXd>& u) const {
    return with_joints(r, u, 0.0);
  }

  /// The same with the residual of joint rows that are unknowns beside the contacts
  /// (J v + b + C l per row): `joint_norm` is its norm in m/s for "siconos", and in N s
  /// (each row's times 1 / (J M^-1 J^T + C)) for "impulse".
  double with_joints(const Eigen::Ref<const Eigen::VectorXd>& r, const Eigen::Ref<const Eigen::VectorXd>& u,
                     double joint_norm) const;

 private:
  MeritKind kind_;
  double q_norm_ = 0;    // siconos: |q|
  double floor_ = 0;     // impulse: max(|rho q_N^-|, g h |rho|), N s
  Eigen::VectorXd masses_;  // impulse: each contact's rho; empty for siconos (rho = 1)
  Eigen::VectorXd cap_;     // each contact's bound on its normal impulse; empty: none
  const Eigen::VectorXd& mu_;
};

}  // namespace icedem
