#include "dem/contact/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

namespace icedem {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// the 6x6 mass matrix of a body: m on the linear, the inertia tensor on the angular block
Eigen::Matrix<double, 6, 6> body_mass(const ProblemBody& body) {
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  m.topLeftCorner<3, 3>().diagonal() = Eigen::Vector3d::Constant(body.mass) + body.added_mass;
  m.bottomRightCorner<3, 3>() = body.inertia;
  return m;
}

template <typename Block>
void add_block(Triplets& t, int row, int col, const Block& block) {
  for (int i = 0; i < block.rows(); ++i)
    for (int j = 0; j < block.cols(); ++j)
      if (block(i, j) != 0.0) t.emplace_back(row + i, col + j, block(i, j));
}

// bodies joined by joint rows, as groups (their folded mass matrix is one dense block)
std::vector<std::vector<int>> joined_groups(const ContactProblem& p) {
  const int n = static_cast<int>(p.bodies.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const ProblemJointRow& j : p.joints)
    if (j.a >= 0 && j.b >= 0) parent[find(j.a)] = find(j.b);
  std::vector<std::vector<int>> groups;
  std::vector<int> group_of(n, -1);
  for (int i = 0; i < n; ++i) {
    const int root = find(i);
    if (group_of[root] < 0) {
      group_of[root] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[group_of[root]].push_back(i);
  }
  return groups;
}

}  // namespace

ContactProblem started_from(const ContactProblem& p, const SolverAnswer& a) {
  ContactProblem from = p;
  for (std::size_t c = 0; c < from.contacts.size(); ++c) from.contacts[c].guess = a.r.segment<3>(3 * c);
  for (std::size_t j = 0; j < from.joints.size(); ++j) from.joints[j].guess = a.l(static_cast<int>(j));
  return from;
}

Eigen::Matrix<double, 6, 6> inverse_mass(const ProblemBody& body) {
  Eigen::Matrix<double, 6, 6> inv = Eigen::Matrix<double, 6, 6>::Zero();
  inv.topLeftCorner<3, 3>().diagonal() = (Eigen::Vector3d::Constant(body.mass) + body.added_mass).cwiseInverse();
  inv.bottomRightCorner<3, 3>() = body.inertia.inverse();
  return inv;
}

Eigen::VectorXd contact_guess(const ContactProblem& p) {
  Eigen::VectorXd g(p.contact_rows());
  for (int c = 0; c < static_cast<int>(p.contacts.size()); ++c) g.segment<3>(3 * c) = p.contacts[c].guess;
  return g;
}

Eigen::VectorXd joint_guess(const ContactProblem& p) {
  Eigen::VectorXd g(p.joint_rows());
  for (int r = 0; r < p.joint_rows(); ++r) g(r) = p.joints[r].guess;
  return g;
}

GlobalForm global_form(const ContactProblem& p) {
  GlobalForm g;
  const int n = p.dofs(), m = p.contact_rows(), k = p.joint_rows();
  Triplets t;
  g.v_free.resize(n);
  for (int i = 0; i < static_cast<int>(p.bodies.size()); ++i) {
    add_block(t, 6 * i, 6 * i, body_mass(p.bodies[i]));
    g.v_free.segment<6>(6 * i) = p.bodies[i].free_velocity;
  }
  g.M.resize(n, n);
  g.M.setFromTriplets(t.begin(), t.end());

  t.clear();
  g.w.resize(m);
  g.mu.resize(static_cast<int>(p.contacts.size()));
  for (int c = 0; c < static_cast<int>(p.contacts.size()); ++c) {
    const ProblemContact& contact = p.contacts[c];
    if (contact.a >= 0) add_block(t, 3 * c, 6 * contact.a, contact.ja);
    if (contact.b >= 0) add_block(t, 3 * c, 6 * contact.b, contact.jb);
    g.w.segment<3>(3 * c) = contact.w;
    g.mu(c) = contact.mu;
  }
  g.Jc.resize(m, n);
  g.Jc.setFromTriplets(t.begin(), t.end());

  t.clear();
  g.b.resize(k);
  g.compliance.resize(k);
  for (int r = 0; r < k; ++r) {
    const ProblemJointRow& row = p.joints[r];
    if (row.a >= 0) add_block(t, r, 6 * row.a, row.ja);
    if (row.b >= 0) add_block(t, r, 6 * row.b, row.jb);
    g.b(r) = row.bias;
    g.compliance(r) = row.compliance;
  }
  g.Jj.resize(k, n);
  g.Jj.setFromTriplets(t.begin(), t.end());
  return g;
}

FoldedMassMatrix folded_mass_matrix(const GlobalForm& g) {
  for (int r = 0; r < g.compliance.size(); ++r)
    if (!(g.compliance(r) > 0.0))
      throw std::invalid_argument("joint row " + std::to_string(r) +
                                  " is rigid (compliance 0); only soft joints fold into the mass matrix");
  const Eigen::VectorXd c_inv = g.compliance.cwiseInverse();
  const Eigen::SparseMatrix<double> Jj_t = g.Jj.transpose();
  return {g.M + Jj_t * c_inv.asDiagonal() * g.Jj, g.M * g.v_free - Jj_t * c_inv.cwiseProduct(g.b)};
}

FoldedMass fold_joints(const ContactProblem& p, const GlobalForm& g) {
  const FoldedMassMatrix sparse = folded_mass_matrix(g);
  const Eigen::SparseMatrix<double>& Mt = sparse.Mt;
  FoldedMass folded;
  folded.ft = sparse.ft;

  // Mt is block diagonal over groups of jointed bodies: its inverse is too
  Triplets t;
  for (const std::vector<int>& group : joined_groups(p)) {
    const int size = 6 * static_cast<int>(group.size());
    Eigen::MatrixXd block(size, size);
    for (int i = 0; i < static_cast<int>(group.size()); ++i)
      for (int j = 0; j < static_cast<int>(group.size()); ++j)
        block.block<6, 6>(6 * i, 6 * j) = Eigen::MatrixXd(Mt.block(6 * group[i], 6 * group[j], 6, 6));
    const Eigen::MatrixXd inverse = block.ldlt().solve(Eigen::MatrixXd::Identity(size, size));
    for (int i = 0; i < static_cast<int>(group.size()); ++i)
      for (int j = 0; j < static_cast<int>(group.size()); ++j)
        add_block(t, 6 * group[i], 6 * group[j], inverse.block<6, 6>(6 * i, 6 * j));
  }
  folded.Mt_inv.resize(p.dofs(), p.dofs());
  folded.Mt_inv.setFromTriplets(t.begin(), t.end());
  return folded;
}

Eigen::VectorXd joint_impulses(const ContactProblem& p, const Eigen::VectorXd& r) {
  if (p.joints.empty()) return Eigen::VectorXd();
  const GlobalForm g = global_form(p);
  const FoldedMass folded = fold_joints(p, g);
  const Eigen::VectorXd v = folded.Mt_inv * (g.Jc.transpose() * r + folded.ft);
  return -(g.Jj * v + g.b).cwiseQuotient(g.compliance);
}

LocalForm local_form(const ContactProblem& p) {
  const GlobalForm g = global_form(p);
  const FoldedMass folded = fold_joints(p, g);
  LocalForm local;
  const Eigen::SparseMatrix<double> JcMinv = g.Jc * folded.Mt_inv;
  local.W = JcMinv * g.Jc.transpose();
  // exactly symmetric (the product's round-off is not)
  local.W = 0.5 * (local.W + Eigen::SparseMatrix<double>(local.W.transpose()));
  local.q = JcMinv * folded.ft + g.w;
  local.mu = g.mu;
  if (has_crushing(p)) local.cap = normal_caps(p);
  return local;
}

Eigen::Vector3d structure_impulse(const ContactProblem& p, const Eigen::VectorXd& r) {
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (int c = 0; c < static_cast<int>(p.contacts.size()); ++c) {
    const ProblemContact& contact = p.contacts[c];
    if (!contact.on_structure) continue;
    // the floe's side of the contact: its rows' linear parts are the contact frame
    const ContactJacobian& floe = contact.a >= 0 ? contact.ja : contact.jb;
    total -= floe.leftCols<3>().transpose() * r.segment<3>(3 * c);
  }
  return total;
}

bool touches_structure(const ContactProblem& p) {
  return std::any_of(p.contacts.begin(), p.contacts.end(), [](const ProblemContact& c) { return c.on_structure; });
}

double local_q_norm(const ContactProblem& p) { return local_q_norm(global_form(p)); }

double local_q_norm(const GlobalForm& g) { return g.Jc.rows() == 0 ? 0.0 : local_q(g).norm(); }

Eigen::VectorXd local_q(const GlobalForm& g) {
  if (g.Jc.rows() == 0) return Eigen::VectorXd();
  // rigid joint rows (a clamp, compliance 0) have no folded form: q is then the contacts'
  // free velocity with the joints left out, as without joints
  if (g.Jj.rows() == 0 || (g.compliance.array() <= 0).any()) return g.Jc * g.v_free + g.w;
  // Mt^-1 ft by a sparse factorisation of Mt, not by folding the joints into a dense
  // inverse per lattice (fold_joints), which costs the cube of its size
  const FoldedMassMatrix folded = folded_mass_matrix(g);
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> factor(folded.Mt);
  return g.Jc * factor.solve(folded.ft) + g.w;
}

Eigen::VectorXd velocities(const GlobalForm& g, const Eigen::VectorXd& r, const Eigen::VectorXd& l) {
  Eigen::VectorXd impulse = g.Jc.transpose() * r;
  if (l.size()) impulse += g.Jj.transpose() * l;
  // M is block diagonal: solve body by body
  Eigen::VectorXd v = g.v_free;
  for (int i = 0; i < g.M.rows(); i += 6) {
    const Eigen::Matrix<double, 6, 6> block = Eigen::MatrixXd(g.M.block(i, i, 6, 6));
    v.segment<6>(i) += block.ldlt().solve(impulse.segment<6>(i));
  }
  return v;
}

double natural_map_squared(const Eigen::Ref<const Eigen::VectorXd>& r, const Eigen::Ref<const Eigen::VectorXd>& u,
                           const Eigen::VectorXd& mu, const Eigen::VectorXd& rho, const Eigen::VectorXd& cap) {
  double sum = 0.0;
  for (int c = 0; c < mu.size(); ++c) {
    // a contact without impulse and not closing adds nothing: -(u_N + mu |u_T|, u_T) lies in
    // the polar cone exactly when u_N >= 0 (about half a jam's contacts, spared two roots)
    if (u(3 * c) >= 0 && r(3 * c) == 0 && r(3 * c + 1) == 0 && r(3 * c + 2) == 0) continue;
    const Eigen::Vector3d rc = r.segment<3>(3 * c), uc = u.segment<3>(3 * c);
    Eigen::Vector3d shifted = uc;
    shifted(0) += mu(c) * tangential_norm(uc(1), uc(2));
    if (rho.size()) shifted *= rho(c);
    sum += (rc - (cap.size() ? project_on_contact(rc - shifted, mu(c), cap(c)) : project_on_cone(rc - shifted, mu(c))))
               .squaredNorm();
  }
  return sum;
}

double natural_map_residual(const Eigen::Ref<const Eigen::VectorXd>& r, const Eigen::Ref<const Eigen::VectorXd>& u,
                            const Eigen::VectorXd& mu, double q_norm, const Eigen::VectorXd& cap) {
  const double sum = natural_map_squared(r, u, mu, Eigen::VectorXd(), cap);
  const double scale = std::max({q_norm, r.norm(), u.norm()});
  // Siconos divides only by a scale above round-off
  return scale > std::numeric_limits<double>::epsilon() ? std::sqrt(sum) / scale : std::sqrt(sum);
}

bool has_crushing(const ContactProblem& p) {
  return std::any_of(p.contacts.begin(), p.contacts.end(),
                     [](const ProblemContact& c) { return !std::isinf(c.normal_cap); });
}

Eigen::VectorXd normal_caps(const ContactProblem& p) {
  Eigen::VectorXd caps(p.contacts.size());
  for (std::size_t c = 0; c < p.contacts.size(); ++c) caps(static_cast<Eigen::Index>(c)) = p.contacts[c].normal_cap;
  return caps;
}

double natural_map_residual(const LocalForm& local, const Eigen::VectorXd& r) {
  const Eigen::VectorXd u = local.W * r + local.q;
  return natural_map_residual(r, u, local.mu, local.q.norm(), local.cap);
}

}  // namespace icedem
