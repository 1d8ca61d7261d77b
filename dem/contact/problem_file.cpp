#include "dem/contact/problem_file.hpp"

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "dem/core/errors.hpp"
#include "dem/core/hdf5_io.hpp"

extern "C" {
#include <fclib.h>
}

namespace icedem {
namespace {

// HDF5's file locking off while it lives (HDF5 reads HDF5_USE_FILE_LOCKING at every open), for
// libfclib's opens, which take no file access list
class ReadWithoutLocking {
 public:
  ReadWithoutLocking() {
    if (const char* v = std::getenv(kVariable)) previous_ = v;
    setenv(kVariable, "FALSE", 1);
  }
  ~ReadWithoutLocking() {
    if (previous_) setenv(kVariable, previous_->c_str(), 1);
    else unsetenv(kVariable);
  }
  ReadWithoutLocking(const ReadWithoutLocking&) = delete;
  ReadWithoutLocking& operator=(const ReadWithoutLocking&) = delete;

 private:
  static constexpr const char* kVariable = "HDF5_USE_FILE_LOCKING";
  std::optional<std::string> previous_;
};

using SparseMatrix = Eigen::SparseMatrix<double>;

// an Eigen matrix in FCLIB's compressed-column form; the arrays live as long as this
struct FclibMatrix {
  explicit FclibMatrix(SparseMatrix a) : matrix(std::move(a)) {
    matrix.makeCompressed();
    m.m = static_cast<int>(matrix.rows());
    m.n = static_cast<int>(matrix.cols());
    m.nzmax = static_cast<int>(matrix.nonZeros());
    m.nz = -1;  // compressed columns
    m.p = matrix.outerIndexPtr();
    m.i = matrix.innerIndexPtr();
    m.x = matrix.valuePtr();
    m.info = nullptr;
  }
  SparseMatrix matrix;
  fclib_matrix m{};
};

// an FCLIB matrix (compressed columns or rows, or triplets) as an Eigen matrix
SparseMatrix from_fclib(const fclib_matrix& a) {
  std::vector<Eigen::Triplet<double>> t;
  if (a.nz >= 0) {
    for (int k = 0; k < a.nz; ++k) t.emplace_back(a.p[k], a.i[k], a.x[k]);
  } else if (a.nz == -1) {
    for (int col = 0; col < a.n; ++col)
      for (int k = a.p[col]; k < a.p[col + 1]; ++k) t.emplace_back(a.i[k], col, a.x[k]);
  } else {
    for (int row = 0; row < a.m; ++row)
      for (int k = a.p[row]; k < a.p[row + 1]; ++k) t.emplace_back(row, a.i[k], a.x[k]);
  }
  SparseMatrix out(a.m, a.n);
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

// the problem's soft joint rows: each gets one extra velocity in the global form
std::vector<int> soft_rows(const ContactProblem& p) {
  std::vector<int> soft;
  for (int r = 0; r < p.joint_rows(); ++r)
    if (p.joints[r].compliance > 0) soft.push_back(r);
  return soft;
}

template <typename T>
void write_vector(const H5::Group& group, const std::string& name, const std::vector<T>& data,
                  const H5::PredType& type, std::vector<hsize_t> dims, const std::string& units,
                  const std::string& description) {
  write_fixed(group, name, type, type, dims, data.data(), units, description);
}

template <typename T>
std::vector<T> read_vector(const H5::Group& group, const std::string& name, const H5::PredType& type) {
  H5::DataSet d = group.openDataSet(name);
  const hssize_t n = d.getSpace().getSimpleExtentNpoints();
  std::vector<T> out(static_cast<std::size_t>(n));
  if (n > 0) d.read(out.data(), type);
  return out;
}

std::vector<double> to_std(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

double read_double_attr(const H5::H5Object& obj, const std::string& name) {
  double v = 0;
  obj.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &v);
  return v;
}

std::string read_string_attr(const H5::H5Object& obj, const std::string& name) {
  std::string v;
  H5::Attribute a = obj.openAttribute(name);
  a.read(a.getStrType(), v);
  return v;
}

}  // namespace

void write_problem_file(const std::string& path, const ContactProblem& p, const std::optional<SolverAnswer>& answer) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);  // libfclib will not replace existing groups

  const GlobalForm g = global_form(p);
  const int n = p.dofs(), m = p.contact_rows(), k = p.joint_rows();
  const std::vector<int> soft = soft_rows(p);
  const int na = n + static_cast<int>(soft.size());

  // M with the soft rows' extra velocities (mass 1/c), H = Jc^T, G = (Jj^T; unit entries)
  std::vector<Eigen::Triplet<double>> t;
  for (int col = 0; col < g.M.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(g.M, col); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  for (int s = 0; s < static_cast<int>(soft.size()); ++s) t.emplace_back(n + s, n + s, 1.0 / p.joints[soft[s]].compliance);
  SparseMatrix M(na, na);
  M.setFromTriplets(t.begin(), t.end());
  SparseMatrix H = g.Jc.transpose();
  H.conservativeResize(na, m);
  t.clear();
  const SparseMatrix Jj_t = g.Jj.transpose();
  for (int col = 0; col < Jj_t.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(Jj_t, col); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  for (int s = 0; s < static_cast<int>(soft.size()); ++s) t.emplace_back(n + s, soft[s], 1.0);
  SparseMatrix G(na, k);
  G.setFromTriplets(t.begin(), t.end());

  Eigen::VectorXd f = Eigen::VectorXd::Zero(na);
  f.head(n) = g.M * g.v_free;
  Eigen::VectorXd w = g.w, b = g.b, mu = g.mu;

  const std::string title = fmt::format("icedem island {} at t = {:.4f} s", p.island, p.time);
  const std::string description =
      fmt::format("{}: {} bodies, {} contacts, {} joint rows; step {} of {:.4g} s", p.source.empty() ? "icedem" : p.source,
                  p.bodies.size(), p.contacts.size(), k, p.step, p.dt);
  const std::string math_info =
      "soft joint rows as one extra velocity of mass 1/c each (see /icedem); Coulomb cone; restitution 0";
  fclib_info info{const_cast<char*>(title.c_str()), const_cast<char*>(description.c_str()),
                  const_cast<char*>(math_info.c_str())};

  auto fail = [&](const std::string& what) {
    throw OutputError(fmt::format("could not write the contact problem file {}: {}", path, what));
  };
  {
    FclibMatrix fM(M), fH(H), fG(G);
    fclib_global global{};
    global.M = &fM.m;
    global.H = &fH.m;
    global.G = k > 0 ? &fG.m : nullptr;
    global.mu = mu.data();
    global.f = f.data();
    global.b = k > 0 ? b.data() : nullptr;
    global.w = w.data();
    global.spacedim = 3;
    global.info = &info;
    if (!fclib_write_global(&global, path.c_str())) fail("libfclib failed on the global form");
  }
  if (m > 0 && soft.size() == static_cast<std::size_t>(k)) {
    LocalForm local = local_form(p);
    FclibMatrix fW(local.W);
    fclib_local l{};
    l.W = &fW.m;
    l.mu = local.mu.data();
    l.q = local.q.data();
    l.spacedim = 3;
    l.info = &info;
    if (!fclib_write_local(&l, path.c_str())) fail("libfclib failed on the local form");
  }

  // the guess: the warm start, with the velocities it gives
  auto solution_of = [&](const Eigen::VectorXd& r, const Eigen::VectorXd& l) {
    Eigen::VectorXd v(na);
    v.head(n) = velocities(g, r, l);
    for (int s = 0; s < static_cast<int>(soft.size()); ++s) v(n + s) = p.joints[soft[s]].compliance * l(soft[s]);
    return std::make_pair(v, Eigen::VectorXd(g.Jc * v.head(n) + g.w));
  };
  Eigen::VectorXd r0 = contact_guess(p), l0 = joint_guess(p);
  auto [v0, u0] = solution_of(r0, l0);
  fclib_solution guess{v0.data(), u0.data(), r0.data(), k > 0 ? l0.data() : nullptr};
  if (m > 0 && !fclib_write_guesses(1, &guess, path.c_str())) fail("libfclib failed on the guess");

  QuietHdf5 quiet;
  try {
    H5::H5File file(path, H5F_ACC_RDWR);
    H5::Group icedem = file.createGroup("/icedem");
    write_attr(icedem, "source", p.source);
    write_attr(icedem, "time", p.time);
    write_attr(icedem, "dt", p.dt);
    write_attr(icedem, "step", static_cast<uint64_t>(p.step));
    write_attr(icedem, "island", p.island);
    write_attr(icedem, "body_dofs", n);
    write_attr(icedem, "box_friction", p.box_friction ? 1 : 0);
    write_attr(icedem, "description",
               "contact and joint rows' bodies (-1: fixed or kinematic), run indices, and the run solver's answer; "
               "the first body_dofs velocities of /fclib_global are the bodies' (v, w)");
    const auto nc = static_cast<hsize_t>(p.contacts.size()), nb = static_cast<hsize_t>(p.bodies.size());
    std::vector<int> body_ids, contact_bodies, on_structure, joint_bodies, joint_ids;
    for (const ProblemBody& body : p.bodies) body_ids.push_back(body.id);
    for (const ProblemContact& c : p.contacts) {
      contact_bodies.push_back(c.a);
      contact_bodies.push_back(c.b);
      on_structure.push_back(c.on_structure ? 1 : 0);
    }
    for (const ProblemJointRow& j : p.joints) {
      joint_bodies.push_back(j.a);
      joint_bodies.push_back(j.b);
      joint_ids.push_back(j.joint);
    }
    const H5::PredType& i32 = H5::PredType::NATIVE_INT;
    write_vector(icedem, "body_ids", body_ids, i32, {nb}, "-", "each body's index among the run's bodies");
    write_vector(icedem, "contact_bodies", contact_bodies, i32, {nc, 2}, "-", "the bodies of each contact (a, b)");
    write_vector(icedem, "contact_on_structure", on_structure, i32, {nc}, "-", "1 if the contact is on the structure");
    write_vector(icedem, "joint_bodies", joint_bodies, i32, {static_cast<hsize_t>(k), 2}, "-",
                 "the bodies of each joint row (a, b)");
    write_vector(icedem, "joint_ids", joint_ids, i32, {static_cast<hsize_t>(k)}, "-", "each joint row's joint in the run");
    if (has_crushing(p)) {  // FCLIB has no crushing contact: its caps beside (dem/contact/crushing.hpp)
      const Eigen::VectorXd caps = normal_caps(p);
      write_vector(icedem, "contact_normal_cap", to_std(caps), H5::PredType::NATIVE_DOUBLE, {nc}, "N s",
                   "each contact's largest normal impulse: a crushing contact's h F(delta); inf for a rigid one");
    }
    if (answer) {
      H5::Group a = icedem.createGroup("run_answer");
      write_attr(a, "sweeps", answer->sweeps);
      write_attr(a, "residual", answer->residual);
      write_attr(a, "capped", answer->capped ? 1 : 0);
      const H5::PredType& f64 = H5::PredType::NATIVE_DOUBLE;
      write_vector(a, "r", to_std(answer->r), f64, {static_cast<hsize_t>(answer->r.size())}, "N s",
                   "contact impulses the run's solver ended with (normal, t1, t2)");
      write_vector(a, "l", to_std(answer->l), f64, {static_cast<hsize_t>(answer->l.size())}, "N s",
                   "joint row impulses the run's solver ended with");
    }
  } catch (const H5::Exception& e) {
    fail(hdf5_reason(e));
  }
}

ProblemFile read_problem_file(const std::string& path) {
  auto bad = [&](const std::string& what) {
    return InputError(fmt::format("{}: not an icedem contact problem file ({})", path, what));
  };
  if (!std::filesystem::exists(path)) throw InputError(fmt::format("{}: no such file", path));
  // libfclib opens the file itself, and read-write even to read it; HDF5 then locks it, and two
  // processes reading one problem (the benchmark, the tests run in parallel) refused each other.
  // Its reads run with HDF5's file locking off: they only read.
  std::optional<ReadWithoutLocking> unlocked(std::in_place);
  std::unique_ptr<fclib_global, void (*)(fclib_global*)> global(fclib_read_global(path.c_str()), fclib_delete_global);
  if (!global) throw bad("libfclib cannot read /fclib_global");
  // read its guess before HDF5 holds the file open here
  int guesses = 0;
  std::unique_ptr<fclib_solution, std::function<void(fclib_solution*)>> guess(
      fclib_read_guesses(path.c_str(), &guesses), [&](fclib_solution* g) { fclib_delete_solutions(g, guesses); });
  unlocked.reset();

  ProblemFile out;
  ContactProblem& p = out.problem;
  QuietHdf5 quiet;
  try {
    H5::H5File file(path, H5F_ACC_RDONLY, H5::FileCreatPropList::DEFAULT, unlocked_access());
    if (!file.nameExists("/icedem")) throw bad("no /icedem group");
    H5::Group icedem = file.openGroup("/icedem");
    p.source = read_string_attr(icedem, "source");
    p.time = read_double_attr(icedem, "time");
    p.dt = read_double_attr(icedem, "dt");
    p.step = static_cast<long>(read_double_attr(icedem, "step"));
    p.island = static_cast<int>(read_double_attr(icedem, "island"));
    p.box_friction = read_double_attr(icedem, "box_friction") != 0;
    const int n = static_cast<int>(read_double_attr(icedem, "body_dofs"));
    const H5::PredType& i32 = H5::PredType::NATIVE_INT;
    const auto body_ids = read_vector<int>(icedem, "body_ids", i32);
    const auto contact_bodies = read_vector<int>(icedem, "contact_bodies", i32);
    const auto on_structure = read_vector<int>(icedem, "contact_on_structure", i32);
    const auto joint_bodies = read_vector<int>(icedem, "joint_bodies", i32);
    const auto joint_ids = read_vector<int>(icedem, "joint_ids", i32);

    const SparseMatrix M = from_fclib(*global->M);
    const SparseMatrix Jc = from_fclib(*global->H).transpose();
    const SparseMatrix Jj = global->G ? SparseMatrix(from_fclib(*global->G).transpose()) : SparseMatrix(0, M.rows());
    if (n != 6 * static_cast<int>(body_ids.size()) || M.rows() < n) throw bad("body_dofs does not match M");
    const Eigen::Map<const Eigen::VectorXd> f(global->f, M.rows());

    for (int i = 0; i < n / 6; ++i) {
      ProblemBody b;
      const Eigen::Matrix<double, 6, 6> block = Eigen::MatrixXd(M.block(6 * i, 6 * i, 6, 6));
      b.mass = block(0, 0);  // surge: no added mass (dem/water/added_mass.hpp)
      b.added_mass = block.topLeftCorner<3, 3>().diagonal() - Eigen::Vector3d::Constant(b.mass);
      b.inertia = block.bottomRightCorner<3, 3>();
      b.free_velocity = block.ldlt().solve(f.segment<6>(6 * i));
      b.id = body_ids[i];
      p.bodies.push_back(b);
    }
    const Eigen::MatrixXd Jc_dense = Jc.leftCols(n);
    for (int c = 0; c < Jc.rows() / 3; ++c) {
      ProblemContact contact;
      contact.a = contact_bodies[2 * c];
      contact.b = contact_bodies[2 * c + 1];
      if (contact.a >= 0) contact.ja = Jc_dense.block<3, 6>(3 * c, 6 * contact.a);
      if (contact.b >= 0) contact.jb = Jc_dense.block<3, 6>(3 * c, 6 * contact.b);
      contact.w = Eigen::Map<const Eigen::Vector3d>(global->w + 3 * c);
      contact.mu = global->mu[c];
      contact.on_structure = on_structure[c] != 0;
      p.contacts.push_back(contact);
    }
    const Eigen::MatrixXd Jj_dense = Jj;
    int extra = n;  // the soft rows' extra velocities follow the bodies', in row order
    for (int r = 0; r < Jj.rows(); ++r) {
      ProblemJointRow row;
      row.a = joint_bodies[2 * r];
      row.b = joint_bodies[2 * r + 1];
      if (row.a >= 0) row.ja = Jj_dense.block<1, 6>(r, 6 * row.a);
      if (row.b >= 0) row.jb = Jj_dense.block<1, 6>(r, 6 * row.b);
      row.bias = global->b[r];
      if (extra < M.rows() && Jj_dense(r, extra) == 1.0) row.compliance = 1.0 / M.coeff(extra, extra), ++extra;
      row.joint = joint_ids[r];
      p.joints.push_back(row);
    }

    if (icedem.nameExists("contact_normal_cap")) {
      const auto caps = read_vector<double>(icedem, "contact_normal_cap", H5::PredType::NATIVE_DOUBLE);
      if (caps.size() != p.contacts.size()) throw bad("contact_normal_cap does not match the contacts");
      for (std::size_t c = 0; c < p.contacts.size(); ++c) p.contacts[c].normal_cap = caps[c];
    }

    if (guess && guesses > 0) {
      for (int c = 0; c < static_cast<int>(p.contacts.size()); ++c)
        p.contacts[c].guess = Eigen::Map<const Eigen::Vector3d>(guess.get()[0].r + 3 * c);
      for (int r = 0; r < p.joint_rows() && guess.get()[0].l; ++r) p.joints[r].guess = guess.get()[0].l[r];
    }

    if (icedem.nameExists("run_answer")) {
      H5::Group a = icedem.openGroup("run_answer");
      SolverAnswer answer;
      const auto r = read_vector<double>(a, "r", H5::PredType::NATIVE_DOUBLE);
      const auto l = read_vector<double>(a, "l", H5::PredType::NATIVE_DOUBLE);
      answer.r = Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<int>(r.size()));
      answer.l = Eigen::Map<const Eigen::VectorXd>(l.data(), static_cast<int>(l.size()));
      answer.sweeps = static_cast<int>(read_double_attr(a, "sweeps"));
      answer.residual = read_double_attr(a, "residual");
      answer.capped = read_double_attr(a, "capped") != 0;
      out.answer = answer;
    }
  } catch (const H5::Exception& e) {
    throw bad(hdf5_reason(e));
  }
  return out;
}

}  // namespace icedem
