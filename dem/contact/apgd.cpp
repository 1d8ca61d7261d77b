#include "dem/contact/apgd.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "dem/contact/lattice_mass.hpp"

namespace icedem {
namespace {

// steps between two evaluations of the merit (it costs about as much as a step's
// products; on the problem library every 4th step took 20 % less CPU than every step)
constexpr int kCheckEvery = 4;

// R rows of J on their one or two bodies (-1: none): a joint row (R = 1) or a contact's
// side kept apart (ContactRows below, R = 3). Plain arrays of six, one per row, so that
// the products are short loops the compiler unrolls (Eigen's small fixed-size products
// over blocks of a dynamic vector were not inlined and took a third of a jammed run's CPU
// time), and only J: M^-1 is applied per body, between the two passes, which halves the
// memory a pass streams through
template <int R>
struct Blocks {
  int a, b;
  double ja[R][6], jb[R][6];          // J's rows on a and on b
  double diagonal_a[R], diagonal_b[R];  // each side's part of the diagonal of J M^-1 J^T

  Blocks(int a_, int b_, const Eigen::Matrix<double, R, 6>& ja_, const Eigen::Matrix<double, R, 6>& jb_,
         const std::vector<Eigen::Matrix<double, 6, 6>>& inv_mass)
      : a(a_), b(b_) {
    for (int r = 0; r < R; ++r) {
      diagonal_a[r] = a >= 0 ? ja_.row(r).dot(inv_mass[a] * ja_.row(r).transpose()) : 0.0;
      diagonal_b[r] = b >= 0 ? jb_.row(r).dot(inv_mass[b] * jb_.row(r).transpose()) : 0.0;
      for (int k = 0; k < 6; ++k) ja[r][k] = ja_(r, k), jb[r][k] = jb_(r, k);
    }
  }
  double diagonal(int r) const { return diagonal_a[r] + diagonal_b[r]; }
};

// out += J^T x of R rows j on one body: the rows summed first, so that the body's six
// values are read and written once, not once per row
template <int R>
inline void add_rows(const double (&j)[R][6], const double* x, double* out) {
  double sum[6];
  for (int k = 0; k < 6; ++k) sum[k] = x[0] * j[0][k];
  for (int r = 1; r < R; ++r)
    for (int k = 0; k < 6; ++k) sum[k] += x[r] * j[r][k];
  for (int k = 0; k < 6; ++k) out[k] += sum[k];
}

// j v of one row on one body, summed as three independent pairs: a chain of six dependent
// additions per row held a pass up by the adder's latency
inline double row_dot(const double (&j)[6], const double* v) {
  return (j[0] * v[0] + j[1] * v[1]) + (j[2] * v[2] + j[3] * v[3]) + (j[4] * v[4] + j[5] * v[5]);
}

// body += J^T x over the blocks, whose rows start at x; body stacked per body
template <int R>
void add_body_impulses(const std::vector<Blocks<R>>& blocks, const double* x, double* body) {
  for (const Blocks<R>& k : blocks) {
    if (k.a >= 0) add_rows<R>(k.ja, x, body + 6 * k.a);
    if (k.b >= 0) add_rows<R>(k.jb, x, body + 6 * k.b);
    x += R;
  }
}

// rows = free + J v over the blocks, whose rows start at rows (and free); v stacked per body
template <int R>
void row_products(const std::vector<Blocks<R>>& blocks, const double* free, const double* v, double* rows) {
  for (const Blocks<R>& k : blocks) {
    double on_a[R], on_b[R];
    for (int r = 0; r < R; ++r) {
      on_a[r] = k.a >= 0 ? row_dot(k.ja[r], v + 6 * k.a) : 0.0;
      on_b[r] = k.b >= 0 ? row_dot(k.jb[r], v + 6 * k.b) : 0.0;
    }
    for (int r = 0; r < R; ++r) rows[r] = free[r] + (on_a[r] + on_b[r]);
    free += R, rows += R;
  }
}

// A contact's three rows (normal, two tangents) on its one or two bodies. Bullet's rows
// act along the same directions on both bodies, opposite: J_a = [L A_a], J_b = [-L A_b],
// so L is kept once, 27 values where two blocks of J hold 36. On a jammed island's
// thousands of contacts the two passes a step makes over them stream from beyond the L2
// cache, and their time follows the bytes. A contact whose sides are not opposite (none of
// Bullet's) keeps its b side apart, as a SideRows.
struct ContactRows {
  int a, b;                         // -1: no body (or b kept apart)
  double lin[3][3];                 // the rows' linear part on a; on b, its negative
  double ang_a[3][3], ang_b[3][3];  // the rows' angular parts on a and on b
};

struct SideRows {
  int contact, body;
  double j[3][6];
};

inline double dot3(const double (&p)[3], const double* q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }

// body += J^T x over the contacts; body stacked per body
void add_contact_impulses(const std::vector<ContactRows>& contacts, const std::vector<SideRows>& sides,
                          const double* x, double* body) {
  const double* xc = x;
  for (const ContactRows& k : contacts) {
    // at the answer of a jammed island about half the contacts carry nothing (the
    // manifolds' points not touching), and so do their projected iterates
    if (xc[0] == 0.0 && xc[1] == 0.0 && xc[2] == 0.0) {
      xc += 3;
      continue;
    }
    double l[3];
    for (int i = 0; i < 3; ++i) l[i] = xc[0] * k.lin[0][i] + xc[1] * k.lin[1][i] + xc[2] * k.lin[2][i];
    if (k.a >= 0) {
      double* o = body + 6 * k.a;
      for (int i = 0; i < 3; ++i) o[i] += l[i];
      for (int i = 0; i < 3; ++i) o[3 + i] += xc[0] * k.ang_a[0][i] + xc[1] * k.ang_a[1][i] + xc[2] * k.ang_a[2][i];
    }
    if (k.b >= 0) {
      double* o = body + 6 * k.b;
      for (int i = 0; i < 3; ++i) o[i] -= l[i];
      for (int i = 0; i < 3; ++i) o[3 + i] += xc[0] * k.ang_b[0][i] + xc[1] * k.ang_b[1][i] + xc[2] * k.ang_b[2][i];
    }
    xc += 3;
  }
  for (const SideRows& s : sides) add_rows<3>(s.j, x + 3 * s.contact, body + 6 * s.body);
}

// rows = free + J v over the contacts (rows may be free); v stacked per body
void contact_products(const std::vector<ContactRows>& contacts, const std::vector<SideRows>& sides,
                      const double* free, const double* v, double* rows) {
  double* out = rows;
  for (const ContactRows& k : contacts) {
    double rel[3] = {0.0, 0.0, 0.0}, on_a[3] = {0.0, 0.0, 0.0}, on_b[3] = {0.0, 0.0, 0.0};
    if (k.a >= 0) {
      const double* va = v + 6 * k.a;
      for (int i = 0; i < 3; ++i) rel[i] = va[i];
      for (int r = 0; r < 3; ++r) on_a[r] = dot3(k.ang_a[r], va + 3);
    }
    if (k.b >= 0) {
      const double* vb = v + 6 * k.b;
      for (int i = 0; i < 3; ++i) rel[i] -= vb[i];
      for (int r = 0; r < 3; ++r) on_b[r] = dot3(k.ang_b[r], vb + 3);
    }
    for (int r = 0; r < 3; ++r) out[r] = free[r] + (dot3(k.lin[r], rel) + (on_a[r] + on_b[r]));
    free += 3, out += 3;
  }
  for (const SideRows& s : sides)
    for (int r = 0; r < 3; ++r) rows[3 * s.contact + r] += row_dot(s.j[r], v + 6 * s.body);
}

// The problem's operators on the stacked impulses x: the contacts' r and, unless the
// joints are folded, the joint rows' l.
//
// Soft joints (every lattice's) are folded into the mass matrix of the lattice they join:
// Mt = M + Jj^T C^-1 Jj and ft = M v_free - Jj^T C^-1 b over each group of bodies joined by
// joints (a floe's elements), factorised once per island (dem/contact/lattice_mass.hpp: dense
// for small lattices, sparse for large ones). The iteration then runs on the contacts
// alone, and each joint row's impulse follows from the velocities, l = -(Jj v + b) / C.
// Stiff springs beside the contacts were what the iteration converged slowly on: on islands
// of the 0.20 m lattices the rows as unknowns took 180-350 steps to a merit of 1e-3, the
// folded form 5-49. A rigid joint row (compliance 0) cannot be folded: then every row
// stays an unknown.
class DualProblem {
 public:
  DualProblem(const ContactProblem& p, MeritKind merit_kind, LatticePatterns& patterns)
      : nb_(static_cast<int>(p.bodies.size())), nc_(static_cast<int>(p.contacts.size())), nj_all_(p.joint_rows()) {
    inv_mass_.resize(nb_);
    for (int i = 0; i < nb_; ++i) inv_mass_[i] = inverse_mass(p.bodies[i]);
    body_velocity_.resize(6 * nb_);
    body_impulse_.resize(6 * nb_);
    for (int i = 0; i < nb_; ++i) body_velocity_.segment<6>(6 * i) = p.bodies[i].free_velocity;
    const bool soft = nj_all_ > 0 && std::all_of(p.joints.begin(), p.joints.end(),
                                                 [](const ProblemJointRow& j) { return j.compliance > 0; });
    folded_ = soft && fold(p, patterns);  // also puts each folded body's v_free_t in body_velocity_
    nj_ = folded_ ? 0 : nj_all_;
    start_velocity_ = body_velocity_;
    // the inverse masses the contacts' scaling sees: a folded body's block of Mt^-1 (a copy
    // only for islands with folded lattices; every island of every step pays this set-up),
    // for the bodies a contact touches (a sparse factor solves for each block)
    std::vector<Eigen::Matrix<double, 6, 6>> folded_inv_mass;
    if (!groups_.empty()) {
      restrict_to_contacts(p);
      folded_inv_mass = inv_mass_;
      for (const Group& g : groups_)
        for (std::size_t t = 0; t < g.touched.size(); ++t) {
          const int body = g.bodies[g.touched[t]];
          folded_inv_mass[body] = g.restricted ? Eigen::Matrix<double, 6, 6>(g.w.block<6, 6>(6 * t, 6 * t))
                                               : g.mass.inverse_block(g.touched[t]);
        }
    }
    const auto& scaling = groups_.empty() ? inv_mass_ : folded_inv_mass;
    // J kept as each contact's rows (ContactRows) and each joint row's 1x6 blocks on its
    // one or two bodies (Blocks): this set-up, paid on every island of every step, is a copy
    contacts_.reserve(nc_);
    joints_.reserve(nj_all_);
    contact_diagonal_.reserve(nc_);
    for (int c = 0; c < nc_; ++c) add_contact(c, p.contacts[c], scaling);
    for (const ProblemJointRow& from : p.joints) joints_.emplace_back(from.a, from.b, from.ja, from.jb, inv_mass_);
    rows_free_.resize(size());
    mu_.resize(nc_);
    for (int c = 0; c < nc_; ++c) {
      rows_free_.segment<3>(3 * c) = p.contacts[c].w;
      mu_(c) = p.contacts[c].mu;
    }
    compliance_.resize(nj_);  // the iterated rows' (none when folded)
    all_compliance_.resize(nj_all_);
    bias_.resize(nj_all_);
    row_mass_.resize(nj_);
    for (int r = 0; r < nj_all_; ++r) {
      const ProblemJointRow& from = p.joints[r];
      if (!folded_) {
        row_mass_(r) = 1.0 / (joints_[r].diagonal(0) + from.compliance);
        rows_free_(3 * nc_ + r) = from.bias;
        compliance_(r) = from.compliance;
      }
      all_compliance_(r) = from.compliance;
      bias_(r) = from.bias;
    }
    if (has_crushing(p)) caps_ = normal_caps(p);
    set_step_scale(p);
    // the rows' velocities at x = 0
    gather(rows_free_, rows_free_);
    // the merit's q: the contacts' free velocity, the joints folded (the local form's q;
    // with a rigid joint row, without them)
    if (nj_)
      merit_.emplace(merit_kind, p, local_q(global_form(p)), mu_);
    else
      merit_.emplace(merit_kind, p, rows_free_.head(3 * nc_), mu_);
  }

  bool folded() const { return folded_; }

  // the joint rows' impulses that go with the contacts' r when the joints are folded:
  // l = -(Jj v + b) / C at v = v_free_t + Mt^-1 Jc^T r
  Eigen::VectorXd joint_impulses(const Eigen::VectorXd& r) const {
    Eigen::VectorXd rows(size());
    row_velocities(r, rows, Velocities::kEveryBody);
    const Eigen::VectorXd v = start_velocity_ + body_velocity_;
    Eigen::VectorXd joint_rows(nj_all_);
    row_products(joints_, bias_.data(), v.data(), joint_rows.data());
    return -joint_rows.cwiseQuotient(all_compliance_);
  }

  int contacts() const { return nc_; }
  int joint_rows() const { return nj_; }
  int size() const { return 3 * nc_ + nj_; }
  double mu(int c) const { return mu_(c); }
  const Eigen::VectorXd& scale() const { return step_; }
  const Eigen::VectorXd& inverse_scale() const { return inverse_step_; }
  const Eigen::VectorXd& rows_free() const { return rows_free_; }
  const Eigen::VectorXd& compliance() const { return compliance_; }

  // which bodies' velocities row_velocities() updates: those the contacts touch (all an
  // iteration reads), or every body (the folded joints' impulses read them all)
  enum class Velocities { kTouched, kEveryBody };

  // the rows' velocities J v(x) + (w, b), v(x) = v_free + M^-1 J^T x: the contacts' u,
  // then the joint rows' J v + b
  void row_velocities(const Eigen::VectorXd& x, Eigen::VectorXd& rows,
                      Velocities which = Velocities::kTouched) const {
    body_impulse_.setZero();  // J^T x
    add_contact_impulses(contacts_, sides_, x.data(), body_impulse_.data());
    if (!folded_) add_body_impulses(joints_, x.data() + 3 * nc_, body_impulse_.data());
    for (int i = 0; i < nb_; ++i)
      if (group_of_.empty() || group_of_[i] < 0)
        body_velocity_.segment<6>(6 * i).noalias() = inv_mass_[i] * body_impulse_.segment<6>(6 * i);
    for (const Group& g : groups_) {
      if (g.restricted && which == Velocities::kTouched) {
        // the impulses fall on the touched elements alone: W, their block of Mt^-1
        const int t = static_cast<int>(g.touched.size());
        for (int e = 0; e < t; ++e) g.impulse.segment<6>(6 * e) = body_impulse_.segment<6>(6 * g.bodies[g.touched[e]]);
        g.velocity.head(6 * t).noalias() = g.w * g.impulse.head(6 * t);
        for (int e = 0; e < t; ++e) body_velocity_.segment<6>(6 * g.bodies[g.touched[e]]) = g.velocity.segment<6>(6 * e);
        continue;
      }
      const int k = static_cast<int>(g.bodies.size());
      for (int b = 0; b < k; ++b) g.impulse.segment<6>(6 * b) = body_impulse_.segment<6>(6 * g.bodies[b]);
      if (which == Velocities::kTouched) {
        // the solve over the touched elements' reach in the factor, their velocities read
        g.mass.solve_on(g.reach, g.impulse, g.velocity);
        for (int e : g.touched) body_velocity_.segment<6>(6 * g.bodies[e]) = g.velocity.segment<6>(6 * e);
        continue;
      }
      g.mass.solve(g.impulse, g.velocity);
      for (int b = 0; b < k; ++b) body_velocity_.segment<6>(6 * g.bodies[b]) = g.velocity.segment<6>(6 * b);
    }
    gather(rows_free_, rows);
  }

  // each contact onto its cone (cut at its normal cap where it crushes); joint rows unchanged
  void project(Eigen::VectorXd& x) const {
    if (caps_.size()) {
      for (int c = 0; c < nc_; ++c) x.segment<3>(3 * c) = project_on_contact(x.segment<3>(3 * c), mu_(c), caps_(c));
      return;
    }
    for (int c = 0; c < nc_; ++c) x.segment<3>(3 * c) = project_on_cone(x.segment<3>(3 * c), mu_(c));
  }

  // the merit of impulses x with row velocities `rows` (dem/contact/merit.hpp): the
  // contacts' natural map and the residual of the joint rows that are unknowns,
  // J v + b + C l = 0 (in impulses for the impulse merit: each row's times 1 / (its
  // diagonal + C), row_mass_)
  double merit(const Eigen::VectorXd& x, const Eigen::VectorXd& rows) const {
    if (!nj_) return (*merit_)(x.head(3 * nc_), rows.head(3 * nc_));
    Eigen::VectorXd joints = rows.tail(nj_) + compliance_.cwiseProduct(x.tail(nj_));
    if (merit_->kind() == MeritKind::kImpulse) joints = joints.cwiseProduct(row_mass_);
    return merit_->with_joints(x.head(3 * nc_), rows.head(3 * nc_), joints.norm());
  }

 private:
  // D, the gradient step's scaling: 1 / sum over the row's bodies of k d, where d is the
  // body's part of the row's diagonal of J M^-1 J^T and k the number of the iterated row
  // blocks (contacts, joint rows) on the body, or on its folded lattice (whose Mt^-1 couples
  // them); + C for a joint row. One value per contact, the mean of its three rows, so that
  // the cone is unchanged by it. Since (sum of k terms)^2 <= k (sum of squares), D^-1 bounds
  // J M^-1 J^T + C from above (mass splitting): the step is about as long at a floe with two
  // neighbours as at one with twenty, where the plain diagonal let the most crowded body
  // set a short step for all. On 237 islands of the paper's small-floe run (2536 contacts on
  // average) it took 14 % fewer gradient steps to a merit of 1e-3.
  void set_step_scale(const ContactProblem& problem) {
    std::vector<int> blocks(nb_, 0);
    auto count = [&](int a, int b) {  // a row block between two bodies of one lattice counts once
      const bool one = a >= 0 && b >= 0 &&
                       (a == b || (!group_of_.empty() && group_of_[a] >= 0 && group_of_[a] == group_of_[b]));
      if (a >= 0) ++blocks[a];
      if (b >= 0 && !one) ++blocks[b];
    };
    for (const ProblemContact& k : problem.contacts) count(k.a, k.b);
    if (!folded_)
      for (const Blocks<1>& k : joints_) count(k.a, k.b);
    // a folded lattice's bodies share their count: their velocities answer every impulse on it
    if (!group_of_.empty()) {
      std::vector<int> in_group(groups_.size(), 0);
      for (int i = 0; i < nb_; ++i)
        if (group_of_[i] >= 0) in_group[group_of_[i]] += blocks[i];
      for (int i = 0; i < nb_; ++i)
        if (group_of_[i] >= 0) blocks[i] = in_group[group_of_[i]];
    }
    auto split = [&](int a, int b, double on_a, double on_b) {
      return (a >= 0 ? blocks[a] * on_a : 0.0) + (b >= 0 ? blocks[b] * on_b : 0.0);
    };
    step_.resize(size());
    for (int c = 0; c < nc_; ++c) {
      const ProblemContact& k = problem.contacts[c];
      const auto& d = contact_diagonal_[c];
      step_.segment<3>(3 * c).setConstant(3.0 / split(k.a, k.b, d[0], d[1]));
    }
    for (int r = 0; r < nj_; ++r) {
      const Blocks<1>& k = joints_[r];
      step_(3 * nc_ + r) = 1.0 / (split(k.a, k.b, k.diagonal_a[0], k.diagonal_b[0]) + compliance_(r));
    }
    inverse_step_ = step_.cwiseInverse();
  }

  // contact c's rows as ContactRows (its b side apart if not opposite to a's), and each
  // side's part of the trace of its block of J M^-1 J^T
  void add_contact(int c, const ProblemContact& from, const std::vector<Eigen::Matrix<double, 6, 6>>& inv_mass) {
    ContactRows k;
    k.a = from.a;
    k.b = from.b;
    const bool opposite = from.a < 0 || from.b < 0 || from.ja.leftCols<3>() == -from.jb.leftCols<3>();
    for (int r = 0; r < 3; ++r)
      for (int i = 0; i < 3; ++i) {
        k.lin[r][i] = from.a >= 0 ? from.ja(r, i) : -from.jb(r, i);
        k.ang_a[r][i] = from.ja(r, 3 + i);
        k.ang_b[r][i] = from.jb(r, 3 + i);
      }
    if (!opposite) {
      SideRows side;
      side.contact = c;
      side.body = from.b;
      for (int r = 0; r < 3; ++r)
        for (int i = 0; i < 6; ++i) side.j[r][i] = from.jb(r, i);
      sides_.push_back(side);
      k.b = -1;
    }
    contacts_.push_back(k);
    contact_diagonal_.push_back({from.a >= 0 ? (from.ja * inv_mass[from.a] * from.ja.transpose()).trace() : 0.0,
                                 from.b >= 0 ? (from.jb * inv_mass[from.b] * from.jb.transpose()).trace() : 0.0});
  }

  // rows = free + J body_velocity_ (rows may be free)
  void gather(const Eigen::VectorXd& free, Eigen::VectorXd& rows) const {
    contact_products(contacts_, sides_, free.data(), body_velocity_.data(), rows.data());
    if (!folded_) row_products(joints_, free.data() + 3 * nc_, body_velocity_.data(), rows.data() + 3 * nc_);
  }

  // Mt, factorised, and v_free_t = Mt^-1 ft of each group of bodies joined by joints
  struct Group {
    std::vector<int> bodies;
    LatticeMass mass{0};                         // Mt over the group's bodies
    std::vector<int> touched;                    // the group's elements a contact touches (local indices)
    bool restricted = false;                     // iterated through w, not a solve over the group
    Eigen::MatrixXd w;                           // Mt^-1 on the touched elements (restricted)
    std::vector<int> reach;                      // what a solve for the touched elements needs (not restricted)
    mutable Eigen::VectorXd impulse, velocity;  // scratch of row_velocities
  };

  // Whether a lattice is iterated through its touched block W or through a solve, by their
  // cost over an island's gradient steps (kTypicalSteps: the lattice runs take 90-180 a step;
  // a level sheet's islands take thousands, where only the per-step terms count). A solve for
  // the touched elements costs about 4 nnz of L in their reach a step (the factor's columns it
  // needs, LatticeMass::reach); W costs 2 nnz of that reach per column once (6 t columns for t
  // touched elements) and 2 (6 t)^2 a step. The solve's flops are dearer than W's dense
  // products: kSolveFlop, measured by bench/micro/lattice_mass.cpp (2026-11-28: a solve of 324
  // elements 5.2 Gflop/s, W of 16 touched 8.8). So a floe of 16 elements (nnz(L) 1,848)
  // takes W up to 8 touched elements, and a level sheet touched at a hundred takes the solve:
  // its W would be 600 rows a side. A dense lattice always takes W: its solve is a product
  // with (6 n)^2 entries as well.
  static constexpr double kTypicalSteps = 100, kSolveFlop = 1.7;
  static bool iterate_through_w(const LatticeMass& mass, int touched, long long reach_nonzeros) {
    if (!mass.sparse()) return true;
    const double nnz = static_cast<double>(reach_nonzeros), columns = 6.0 * touched;
    return 2 * nnz * columns + kTypicalSteps * 2 * columns * columns < kTypicalSteps * kSolveFlop * 4 * nnz;
  }

  // each group's touched elements, and W where it pays: a 0.6 m floe of 0.15 m squares (16
  // elements, 96 rows) in contact at two or three of them is iterated through 12-18 rows
  // in place of 96, and a lattice no contact touches costs nothing in the iteration
  void restrict_to_contacts(const ContactProblem& p) {
    std::vector<char> seen(nb_, 0);
    auto touch = [&](int body) {
      if (body < 0 || group_of_[body] < 0 || seen[body]) return;
      seen[body] = 1;
      groups_[group_of_[body]].touched.push_back(local_[body]);
    };
    for (const ProblemContact& k : p.contacts) touch(k.a), touch(k.b);
    for (Group& g : groups_) {
      std::sort(g.touched.begin(), g.touched.end());  // the elements' order, not the contacts'
      if (g.mass.sparse()) g.reach = g.mass.reach(g.touched);
      g.restricted = iterate_through_w(g.mass, static_cast<int>(g.touched.size()),
                                       g.mass.sparse() ? g.mass.reach_nonzeros(g.reach) : 0);
      if (g.restricted) g.w = g.mass.restricted_inverse(g.touched), g.reach.clear();
    }
  }
  // false (and nothing folded) if a group's Mt is not positive definite
  bool fold(const ContactProblem& p, LatticePatterns& patterns) {
    // the groups: bodies joined by joint rows (union-find)
    std::vector<int> parent(nb_);
    for (int i = 0; i < nb_; ++i) parent[i] = i;
    auto root = [&](int i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    std::vector<char> jointed(nb_, 0);
    for (const ProblemJointRow& j : p.joints) {
      if (j.a >= 0) jointed[j.a] = 1;
      if (j.b >= 0) jointed[j.b] = 1;
      if (j.a >= 0 && j.b >= 0) parent[root(j.a)] = root(j.b);
    }
    group_of_.assign(nb_, -1);
    local_.assign(nb_, -1);
    std::vector<int> group_of_root(nb_, -1);
    for (int i = 0; i < nb_; ++i) {
      if (!jointed[i]) continue;
      int& g = group_of_root[root(i)];
      if (g < 0) g = static_cast<int>(groups_.size()), groups_.emplace_back();
      group_of_[i] = g;
      groups_[g].bodies.push_back(i);
    }
    // a group's bodies in the order of their index in the run (the elements'), not of the
    // island's, which follows Bullet's arrays: a world rebuilt from a checkpoint then
    // factorises the same matrix in the same order, bit for bit
    for (Group& group : groups_) {
      std::stable_sort(group.bodies.begin(), group.bodies.end(),
                       [&](int a, int b) { return p.bodies[a].id < p.bodies[b].id; });
      for (std::size_t k = 0; k < group.bodies.size(); ++k) local_[group.bodies[k]] = static_cast<int>(k);
    }
    std::vector<Eigen::VectorXd> ft(groups_.size());
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      const int n = static_cast<int>(groups_[g].bodies.size());
      groups_[g].mass = LatticeMass(n);
      ft[g].resize(6 * n);
      for (int k = 0; k < n; ++k) {
        const ProblemBody& body = p.bodies[groups_[g].bodies[k]];
        Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
        M.topLeftCorner<3, 3>() = (Eigen::Vector3d::Constant(body.mass) + body.added_mass).asDiagonal();
        M.bottomRightCorner<3, 3>() = body.inertia;
        groups_[g].mass.add(k, k, M);
        ft[g].segment<6>(6 * k) = M * body.free_velocity;
      }
    }
    for (const ProblemJointRow& j : p.joints) {
      const int body = j.a >= 0 ? j.a : j.b;
      const int g = group_of_[body];
      // the row's J over the group's elements: at most two blocks of six
      const int ia = j.a >= 0 ? local_[j.a] : -1, ib = j.b >= 0 ? local_[j.b] : -1;
      const double c = 1.0 / j.compliance;
      for (int u = 0; u < 2; ++u) {
        const int iu = u == 0 ? ia : ib;
        if (iu < 0) continue;
        const RowJacobian& Ju = u == 0 ? j.ja : j.jb;
        ft[g].segment<6>(6 * iu) -= c * j.bias * Ju.transpose();
        for (int w = 0; w < 2; ++w) {
          const int iw = w == 0 ? ia : ib;
          if (iw < 0) continue;
          const RowJacobian& Jw = w == 0 ? j.ja : j.jb;
          groups_[g].mass.add(iu, iw, c * Ju.transpose() * Jw);
        }
      }
    }
    // a lattice is known between solves by its first element's id (its bodies are in
    // the order of their ids); a problem without ids (-1), or two lattices under one
    // (a problem file's), factorises afresh, since a kept factor serves one lattice at a time
    std::vector<long long> keys;
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      const long long key = p.bodies[groups_[g].bodies.front()].id;
      const bool keyed = key >= 0 && std::find(keys.begin(), keys.end(), key) == keys.end();
      if (keyed) keys.push_back(key);
      if (!groups_[g].mass.factorise(keyed ? &patterns : nullptr, key)) {
        groups_.clear();
        group_of_.clear();
        local_.clear();
        return false;
      }
    }
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      Group& group = groups_[g];
      Eigen::VectorXd v(ft[g].size());
      group.mass.solve(ft[g], v);
      for (std::size_t k = 0; k < group.bodies.size(); ++k)
        body_velocity_.segment<6>(6 * group.bodies[k]) = v.segment<6>(6 * k);
      group.impulse.resize(ft[g].size());
      group.velocity.resize(ft[g].size());
    }
    return true;
  }

  int nb_, nc_, nj_all_, nj_ = 0;  // nj_: joint rows among the unknowns (0 when folded)
  bool folded_ = false;
  std::vector<Group> groups_;
  std::vector<int> group_of_;             // each body's group, -1 if it has no joint
  std::vector<int> local_;                // each body's index in its group
  Eigen::VectorXd start_velocity_, bias_, all_compliance_;  // v_free (v_free_t if folded); every joint row's b, C
  std::vector<ContactRows> contacts_;
  std::vector<SideRows> sides_;                          // b sides not opposite to a (none of Bullet's)
  std::vector<std::array<double, 2>> contact_diagonal_;  // on a, on b: trace of J M^-1 J^T
  std::vector<Blocks<1>> joints_;
  Eigen::VectorXd compliance_, rows_free_, mu_;  // compliance_: the joint rows' C
  Eigen::VectorXd row_mass_;                     // the iterated joint rows' 1 / (J M^-1 J^T + C)
  Eigen::VectorXd step_, inverse_step_;          // D of the gradient step, and 1 / D
  Eigen::VectorXd caps_;                         // the contacts' normal caps (crushing); empty: none
  std::optional<Merit> merit_;
  std::vector<Eigen::Matrix<double, 6, 6>> inv_mass_;  // per body
  // J^T x and M^-1 J^T x (v_free while set up), scratch of row_velocities
  mutable Eigen::VectorXd body_impulse_, body_velocity_;
};

}  // namespace

namespace {

// De Saxce's shift at the rows' velocities: mu |u_T|, one per contact
void shift(const DualProblem& dual, const Eigen::VectorXd& rows, Eigen::VectorXd& s) {
  for (int c = 0; c < dual.contacts(); ++c) s(c) = dual.mu(c) * tangential_norm(rows(3 * c + 1), rows(3 * c + 2));
}

// gradient of f for a fixed shift s: J v(x) + (w, b) + C x + (s on the normals)
void gradient(const DualProblem& dual, const Eigen::VectorXd& x, const Eigen::VectorXd& rows, const Eigen::VectorXd& s,
              Eigen::VectorXd& grad) {
  const int nc = dual.contacts(), nj = dual.joint_rows();
  grad.head(3 * nc) = rows.head(3 * nc);
  for (int c = 0; c < nc; ++c) grad(3 * c) += s(c);
  grad.tail(nj) = rows.tail(nj) + dual.compliance().cwiseProduct(x.tail(nj));
}

// the projected gradient step from y with step 1/L, into next, and change = next - y
void gradient_step(const DualProblem& dual, const Eigen::VectorXd& y, const Eigen::VectorXd& grad_y, double L,
                   Eigen::VectorXd& next, Eigen::VectorXd& change) {
  next = y - (1.0 / L) * dual.scale().cwiseProduct(grad_y);
  dual.project(next);
  change = next - y;
}

// whether the quadratic model with L lies above f at the new point, f(next) <= f(y) +
// g(y).d + L/2 |d|^2 in D^-1's metric, d = next - y. For the fixed shift f(x) = 1/2 x^T (J
// M^-1 J^T + C) x + x^T (rows_free + s) is quadratic, so f(next) - f(y) - g(y).d =
// 1/2 d^T (J M^-1 J^T + C) d, and J M^-1 J^T d is rows_next - rows_y (the rows are affine
// in the impulses): the test is d.(rows_next - rows_y) + d.C d <= L |d|^2, two reductions
// Eigen vectorises, where evaluating f at both points cost a pass each and a difference
// of two large numbers
bool model_above(const DualProblem& dual, const Eigen::VectorXd& change, const Eigen::VectorXd& rows_next,
                 const Eigen::VectorXd& rows_y, double L) {
  const int nj = dual.joint_rows();
  const double curvature = change.dot(rows_next - rows_y) +
                           change.tail(nj).dot(dual.compliance().cwiseProduct(change.tail(nj)));
  const double bound = L * change.cwiseAbs2().dot(dual.inverse_scale());
  return curvature <= bound * (1.0 + 1e-12);
}

}  // namespace

SolverAnswer AcceleratedProjectedGradient::solve(const ContactProblem& p, const MethodOptions& options) {
  lattice_patterns_.next_solve();
  const DualProblem dual(p, options.merit, lattice_patterns_);
  const int n = dual.size(), nc = dual.contacts();

  Eigen::VectorXd x(n);
  if (!options.warm_start)
    x.setZero();
  else if (dual.folded())
    x = contact_guess(p);
  else
    x << contact_guess(p), joint_guess(p);
  dual.project(x);

  SolverAnswer answer;
  Eigen::VectorXd rows(n);
  dual.row_velocities(x, rows);
  answer.residual = dual.merit(x, rows);
  Eigen::VectorXd best = x;
  // Lipschitz estimate of the scaled gradient: with D it is of order 1 (1 for a single
  // row); the backtracking corrects it
  double L = 1.0, theta = 1.0;
  // y, the extrapolated point, and the rows' velocities there: they are affine in the
  // impulses, so the extrapolation carries them along without a product
  Eigen::VectorXd y = x, rows_y = rows;
  Eigen::VectorXd s(nc), grad_y(n), next(n), rows_next(n), change(n);
  int steps = 0, iteration = 0;
  while (answer.residual > options.tolerance && steps < options.max_iterations) {
    shift(dual, rows_y, s);
    gradient(dual, y, rows_y, s, grad_y);
    // backtracking: the quadratic model with L must lie above f at the new point
    for (int trial = 0; trial < 30; ++trial) {
      gradient_step(dual, y, grad_y, L, next, change);
      dual.row_velocities(next, rows_next);
      ++steps;
      if (model_above(dual, change, rows_next, rows_y, L)) break;
      L *= 2.0;
    }
    if (++iteration % kCheckEvery == 0 || steps >= options.max_iterations) {
      const double merit = dual.merit(next, rows_next);
      if (merit < answer.residual) answer.residual = merit, best = next;
    }

    // Nesterov's extrapolation, restarted when the step went uphill on the gradient at y
    // (O'Donoghue and Candes' test, g(y).(x+ - x) > 0: a dot product; the gradient at x+,
    // as first written, cost a pass with a root per contact for its shift, and on 237
    // islands of the paper run 5 % more CPU for 0.1 % fewer steps)
    const double theta_next = 0.5 * (-theta * theta + theta * std::sqrt(theta * theta + 4.0));
    const double beta = theta * (1.0 - theta) / (theta * theta + theta_next);
    if (grad_y.dot(next - x) > 0) {
      y = next, rows_y = rows_next;
      theta = 1.0;
    } else {
      y = next + beta * (next - x);
      rows_y = rows_next + beta * (rows_next - rows);
      theta = theta_next;
    }
    x.swap(next), rows.swap(rows_next);
    L *= 0.9;  // let the step grow again where the problem allows it
  }
  answer.sweeps = steps;
  answer.capped = answer.residual > options.tolerance;
  answer.r = best.head(3 * nc);
  answer.l = dual.folded() ? dual.joint_impulses(best) : Eigen::VectorXd(best.tail(n - 3 * nc));
  return answer;
}

}  // namespace icedem
