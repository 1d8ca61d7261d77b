#include "dem/contact/merit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "dem/core/constants.hpp"

namespace icedem {

MeritKind merit_kind(const std::string& name) {
  if (name == "impulse") return MeritKind::kImpulse;
  if (name == "siconos") return MeritKind::kSiconos;
  throw std::invalid_argument("unknown merit \"" + name + "\" (impulse or siconos)");
}

const char* merit_name(MeritKind kind) { return kind == MeritKind::kImpulse ? "impulse" : "siconos"; }

Eigen::VectorXd contact_masses(const ContactProblem& p) {
  const int nc = static_cast<int>(p.contacts.size());
  Eigen::VectorXd masses(nc);
  std::vector<Eigen::Matrix<double, 6, 6>> inv(p.bodies.size());
  for (std::size_t i = 0; i < p.bodies.size(); ++i) inv[i] = inverse_mass(p.bodies[i]);
  for (int c = 0; c < nc; ++c) {
    const ProblemContact& k = p.contacts[c];
    double trace = 0.0;
    if (k.a >= 0) trace += (k.ja * inv[k.a] * k.ja.transpose()).trace();
    if (k.b >= 0) trace += (k.jb * inv[k.b] * k.jb.transpose()).trace();
    // a contact between two bodies without unknown velocity moves nothing: weigh it as 1 kg
    masses(c) = trace > 0 ? 3.0 / trace : 1.0;
  }
  return masses;
}

Merit::Merit(MeritKind kind, const Eigen::Ref<const Eigen::VectorXd>& q, Eigen::VectorXd masses,
             const Eigen::VectorXd& mu, double dt)
    : kind_(kind), masses_(kind == MeritKind::kImpulse ? std::move(masses) : Eigen::VectorXd()), mu_(mu) {
  q_norm_ = q.norm();
  if (kind_ != MeritKind::kImpulse) return;
  double approach = 0.0;
  for (int c = 0; c < mu_.size(); ++c) {
    const double stop = masses_(c) * std::max(-q(3 * c), 0.0);
    approach += stop * stop;
  }
  floor_ = std::max(std::sqrt(approach), kMeritGravity * dt * masses_.norm());
}

double Merit::with_joints(const Eigen::Ref<const Eigen::VectorXd>& r, const Eigen::Ref<const Eigen::VectorXd>& u,
                          double joint_norm) const {
  const double numerator = std::sqrt(natural_map_squared(r, u, mu_, masses_, cap_) + joint_norm * joint_norm);
  const double scale = kind_ == MeritKind::kImpulse ? std::max(r.norm(), floor_)
                                                    : std::max({q_norm_, r.norm(), u.norm()});
  // as Siconos: divide only by a scale above round-off
  return scale > std::numeric_limits<double>::epsilon() ? numerator / scale : numerator;
}

}  // namespace icedem
