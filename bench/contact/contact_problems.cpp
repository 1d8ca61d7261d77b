// contact_problems: tools on contact problem files (dem/contact/problem_file.hpp).
//
//   contact_problems solve FILE... [--method M ...] [--tolerance T] [--merit K] [--max-iterations N] [--cold]
//       solve each problem with each method to the tolerance on merit K (siconos, the default, or
//       impulse, what a run stops on); print iterations, both merits and CPU time. A method
//       "A+B" is the run's island solve with A for at most --first-iterations (default 1000),
//       then B from A's answer where A stopped there above the tolerance (iterations printed
//       as A's+B's)
//   contact_problems reference FILE...
//       solve each problem to a merit of 1e-10 with Siconos numerics, cross-check the
//       answer with a second method, and write it into the file as FCLIB's /solution
//       with /icedem/reference saying how it was found (or why none was)
//   contact_problems extract FILE --body ID -o OUT
//       the problem of one body (run index ID) and its contacts with fixed bodies, cut out of
//       FILE's island with their warm starts: a small test problem of what held it (a free
//       element wedged between held pieces, tests/physics/data/contact/)
//   contact_problems errors FILE... [--method M] [--merit K] [--tolerance T ...] [--first-iterations N] [--csv F] [--loaded-only]
//       the physical error of the run's answer and of a method's at each tolerance against
//       a tight one (newton to 1e-10, else apgd to 1e-9, then ipm): the load on the structure (N) and
//       the joints' forces (N) and moments (N m), impulses over the step
//
// The merit is natural_map_residual on the Delassus form (dem/contact/problem.hpp),
// the same for every method.
#include <algorithm>
#include <ctime>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <H5Cpp.h>
#include <fmt/format.h>

#include "dem/contact/island_solve.hpp"
#include "dem/contact/problem_file.hpp"
#include "dem/contact/registry.hpp"
#include "dem/contact/siconos.hpp"
#include "dem/core/errors.hpp"
#include "dem/core/hdf5_io.hpp"

extern "C" {
#include <fclib.h>
}

using namespace icedem;

namespace {

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// `name`'s answer: a method, or "A+B", the run's island solve (dem/contact/island_solve.hpp)
// with solver.method A capped at `first` iterations and solver.handover_method B from A's
// answer (at most o.max_iterations), to o.tolerance whatever the island holds, without a
// breaking solve (iterations printed as A's+B's, the hand-over counted if any)
SolverAnswer solve_with(const std::string& name, const ContactProblem& p, const MethodOptions& o, int first,
                        std::string& iterations) {
  const auto plus = name.find('+');
  if (plus == std::string::npos) {
    const SolverAnswer a = make_contact_method(name)->solve(p, o);
    iterations = std::to_string(a.sweeps);
    return a;
  }
  SolverSettings s{};
  s.method = name.substr(0, plus);
  s.handover_method = name.substr(plus + 1);
  s.merit = merit_name(o.merit);
  s.merit_tolerance = s.joint_merit_tolerance = s.structure_merit_tolerance = o.tolerance;
  s.breaking_merit_tolerance = 0.0;
  s.method_iterations = first;
  s.handover_iterations = o.max_iterations;
  SolverReport report;
  // the island solve starts from the problem's warm start: a cold solve starts from zero
  const SolverAnswer a = IslandSolve(s).solve(o.warm_start ? p : started_from(p, SolverAnswer{
      Eigen::VectorXd::Zero(p.contact_rows()), Eigen::VectorXd::Zero(p.joint_rows())}), report);
  // a hand-over starts only where A used all its `first` iterations
  iterations = report.counts.handovers > 0 ? fmt::format("{}+{}", first, a.sweeps - first) : std::to_string(a.sweeps);
  return a;
}

int solve_command(const std::vector<std::string>& files, std::vector<std::string> methods, double tolerance,
                  MeritKind merit, int max_iterations, bool cold, int first_iterations) {
  if (methods.empty())  // every method on a problem (the in-run sweeps are not one)
    for (const ContactMethodEntry& e : contact_methods())
      if (e.make) methods.push_back(e.name);
  std::cout << fmt::format("{:<40} {:>7} {:>6} {:<16} {:>7} {:>10} {:>10} {:>9}\n", "problem", "contacts", "joints",
                           "method", "iters", "merit", "impulse", "cpu ms");
  for (const std::string& path : files) {
    const ProblemFile file = read_problem_file(path);
    const ContactProblem& p = file.problem;
    const LocalForm local = local_form(p);
    const Merit impulse(MeritKind::kImpulse, p, local.q, local.mu);
    for (const std::string& name : methods) {
      MethodOptions o;
      o.tolerance = tolerance;
      o.merit = merit;
      o.max_iterations = max_iterations;
      o.warm_start = !cold;
      const double t0 = cpu_seconds();
      std::string iterations;
      const SolverAnswer a = solve_with(name, p, o, first_iterations, iterations);
      const double cpu = cpu_seconds() - t0;
      std::cout << fmt::format("{:<40} {:>7} {:>6} {:<16} {:>7} {:>10.3e} {:>10.3e} {:>9.2f}\n",
                               std::filesystem::path(path).filename().string(), p.contacts.size(), p.joint_rows(), name,
                               iterations, natural_map_residual(local, a.r),
                               impulse(a.r, local.W * a.r + local.q), 1e3 * cpu);
    }
  }
  return 0;
}

// The reference of one problem: Siconos' proximal point method (semismooth Newton
// inside; it copes with the rank-deficient W of faces touching at several points), then
// semismooth Newton (Alart-Curnier, Fischer-Burmeister), then NSGS with a large cap, to a
// merit of 1e-10. The best answer is kept and cross-checked against every other method
// that reached 1e-8: the contact impulses of a face are not unique, so the check compares
// what is: the bodies' velocities and the impulse on the structure.
struct Reference {
  std::string status;        // "solved" or "unsolved"
  std::string method;        // the method whose answer is kept
  double merit = 0;          // of the kept answer
  double cpu = 0;            // s, of the kept answer
  std::string check;         // the cross-checking methods, "" if none reached 1e-8
  double velocity_difference = 0;  // largest |v - v_check| / |v|
  double load_difference = 0;      // largest |P - P_check| / max(|P|, 1e-9 N s), P the structure impulse
  Eigen::VectorXd r;
};

Reference reference_of(const ContactProblem& p) {
  constexpr double kTarget = 1e-10, kCheck = 1e-8;
  const LocalForm local = local_form(p);
  const GlobalForm g = global_form(p);
  const Eigen::VectorXd guess = contact_guess(p);
  struct Try {
    const char* name;
    int id, iterations;
  };
  const Try tries[] = {{"siconos_prox", SiconosMethod::kProx, 1000},
                       {"siconos_nsn_ac", SiconosMethod::kNsnAc, 500},
                       {"siconos_nsn_fb", SiconosMethod::kNsnFb, 500},
                       {"siconos_nsgs", SiconosMethod::kNsgs, 5000}};
  Reference ref;
  ref.status = "unsolved";
  std::vector<std::pair<std::string, Eigen::VectorXd>> reached;  // answers at kCheck or better
  double best = std::numeric_limits<double>::infinity();
  for (const Try& t : tries) {
    MethodOptions o;
    o.tolerance = kTarget;
    o.max_iterations = t.iterations;
    const double t0 = cpu_seconds();
    const SolverAnswer a = SiconosMethod(t.id).solve_local(local, guess, o);
    const double cpu = cpu_seconds() - t0;
    const double merit = natural_map_residual(local, a.r);
    if (merit < best) best = merit, ref.method = t.name, ref.merit = merit, ref.r = a.r, ref.cpu = cpu;
    if (merit <= kCheck) reached.emplace_back(t.name, a.r);
    if (merit <= kTarget && reached.size() >= 2) break;  // solved and cross-checked
  }
  if (ref.merit <= kTarget) ref.status = "solved";
  const Eigen::VectorXd v = velocities(g, ref.r, joint_impulses(p, ref.r));
  const Eigen::Vector3d load = structure_impulse(p, ref.r);
  for (const auto& [name, r] : reached) {
    if (name == ref.method) continue;
    ref.check += (ref.check.empty() ? "" : ",") + name;
    const Eigen::VectorXd v_check = velocities(g, r, joint_impulses(p, r));
    ref.velocity_difference = std::max(ref.velocity_difference, (v_check - v).norm() / std::max(v.norm(), 1e-300));
    ref.load_difference =
        std::max(ref.load_difference, (structure_impulse(p, r) - load).norm() / std::max(load.norm(), 1e-9));
  }
  return ref;
}

int reference_command(const std::vector<std::string>& files) {
  std::cout << fmt::format("{:<40} {:>7} {:>6} {:<9} {:<15} {:>9} {:>8} {:<30} {:>9} {:>9}\n", "problem", "contacts",
                           "joints", "status", "method", "merit", "cpu s", "checked by", "dv/v", "dP/P");
  for (const std::string& path : files) {
    const ProblemFile file = read_problem_file(path);
    const ContactProblem& p = file.problem;
    const Reference ref = reference_of(p);
    // FCLIB's /solution: v, u, r, l of the kept answer (l and v from the folded joints)
    const GlobalForm g = global_form(p);
    const Eigen::VectorXd l = joint_impulses(p, ref.r);
    const Eigen::VectorXd v_bodies = velocities(g, ref.r, l);
    Eigen::VectorXd v(v_bodies.size() + l.size());
    v << v_bodies, Eigen::VectorXd::Zero(l.size());
    for (int s = 0, row = 0; row < p.joint_rows(); ++row)
      if (p.joints[row].compliance > 0) v(v_bodies.size() + s++) = p.joints[row].compliance * l(row);
    Eigen::VectorXd u = g.Jc * v_bodies + g.w;
    Eigen::VectorXd r = ref.r, lj = l;
    {
      QuietHdf5 quiet;
      H5::H5File f(path, H5F_ACC_RDWR);
      if (f.nameExists("/solution")) f.unlink("/solution");
      if (f.nameExists("/icedem/reference")) f.unlink("/icedem/reference");
    }
    fclib_solution s{v.data(), u.data(), r.data(), lj.size() ? lj.data() : nullptr};
    if (!fclib_write_solution(&s, path.c_str())) throw OutputError(path + ": libfclib could not write /solution");
    {
      QuietHdf5 quiet;
      H5::H5File f(path, H5F_ACC_RDWR);
      H5::Group g = f.createGroup("/icedem/reference");
      write_attr(g, "status", ref.status);
      write_attr(g, "method", ref.method);
      write_attr(g, "merit", ref.merit);
      write_attr(g, "cpu_s", ref.cpu);
      write_attr(g, "checked_by", ref.check);
      write_attr(g, "velocity_difference", ref.velocity_difference);
      write_attr(g, "load_difference", ref.load_difference);
    }
    std::cout << fmt::format("{:<40} {:>7} {:>6} {:<9} {:<15} {:>9.2e} {:>8.2f} {:<30} {:>9.2e} {:>9.2e}",
                             std::filesystem::path(path).filename().string(), p.contacts.size(), p.joint_rows(),
                             ref.status, ref.method, ref.merit, ref.cpu, ref.check.empty() ? "-" : ref.check,
                             ref.velocity_difference, ref.load_difference)
              << std::endl;
  }
  return 0;
}

// the physical loads of an answer: the structure's (N) and each joint row's (N or N m),
// impulses over the step
struct Loads {
  Eigen::Vector3d structure;
  Eigen::VectorXd joints;
};
Loads loads_of(const ContactProblem& p, const Eigen::VectorXd& r) {
  Loads l;
  l.structure = structure_impulse(p, r) / p.dt;
  l.joints = p.joints.empty() ? Eigen::VectorXd() : Eigen::VectorXd(joint_impulses(p, r) / p.dt);
  return l;
}

// a joint row is linear (a force) when its Jacobian has a linear part
bool linear_row(const ProblemJointRow& j) {
  return (j.a >= 0 && j.ja.leftCols<3>().norm() > 0) || (j.b >= 0 && j.jb.leftCols<3>().norm() > 0);
}

// the tight answer the errors are measured against: newton to 1e-10 (at most 500 steps),
// else (a lattice island it stalls on) apgd to 1e-9 (at most 20000), whichever ends lower, and
// if that is still above 1e-8 (a level sheet's islands: 1.4e-6 to 6.3e-6) the interior-point
// method from it (at most 1000 iterations; not on crushing contacts, which it does not take)
SolverAnswer tight_answer(const ContactProblem& p, const LocalForm& local, double& merit) {
  MethodOptions o;
  o.tolerance = 1e-10;
  o.max_iterations = 500;
  SolverAnswer best = make_contact_method("newton")->solve(p, o);
  merit = natural_map_residual(local, best.r);
  const auto keep_lower = [&](const SolverAnswer& a) {
    const double m = natural_map_residual(local, a.r);
    if (m < merit) best = a, merit = m;
  };
  if (merit > 1e-8) {
    o.tolerance = 1e-9;
    o.max_iterations = 20000;
    keep_lower(make_contact_method("apgd")->solve(p, o));
  }
  if (merit > 1e-8 && !has_crushing(p)) {  // the interior-point method takes no crushing contacts
    o.max_iterations = 1000;
    keep_lower(make_contact_method("ipm")->solve(started_from(p, best), o));
  }
  return best;
}

int errors_command(const std::vector<std::string>& files, const std::string& method, MeritKind merit,
                   const std::vector<double>& tolerances, int max_iterations, int first_iterations,
                   const std::string& csv_path, bool loaded_only) {
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    if (!csv) throw OutputError(csv_path + ": cannot write");
    csv << "problem,time,step,island,dt,contacts,joint_rows,answer,merit,impulse_merit,iterations,load_x,load_y,load_z,"
           "load_error_n,joint_force_n,joint_force_error_n,joint_moment_nm,joint_moment_error_nm\n";
  }
  std::cout << fmt::format("{:<34} {:>6} {:>6} {:>8} {:>9} {:>9} {:>7} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}\n",
                           "problem", "dt", "contacts", "answer", "merit", "impulse", "iters", "load N", "dload N", "jointF N",
                           "dF N", "jointM Nm", "dM Nm");
  for (const std::string& path : files) {
    const ProblemFile file = read_problem_file(path);
    const ContactProblem& p = file.problem;
    // an island that neither touches the structure nor holds a joint reaches no reported load
    if (loaded_only && p.joints.empty() && !touches_structure(p)) continue;
    const LocalForm local = local_form(p);
    const Merit impulse(MeritKind::kImpulse, p, local.q, local.mu);  // with its crushing caps
    double ref_merit = 0;
    const SolverAnswer ref = tight_answer(p, local, ref_merit);
    const Loads exact = loads_of(p, ref.r);
    std::vector<bool> linear(p.joints.size());
    double max_f = 0, max_m = 0;
    for (std::size_t j = 0; j < p.joints.size(); ++j) {
      linear[j] = linear_row(p.joints[j]);
      double& top = linear[j] ? max_f : max_m;
      top = std::max(top, std::abs(exact.joints(j)));
    }
    const std::string name = std::filesystem::path(path).filename().string();
    // `iterations`: the answer's, "A+B" for a method that handed over (the CSV has their sum,
    // a.sweeps)
    auto row = [&](const std::string& label, const SolverAnswer& a, const std::string& iterations) {
      const Loads got = loads_of(p, a.r);
      double df = 0, dm = 0;
      for (std::size_t j = 0; j < p.joints.size(); ++j) {
        double& worst = linear[j] ? df : dm;
        worst = std::max(worst, std::abs(got.joints(j) - exact.joints(j)));
      }
      const double merit = natural_map_residual(local, a.r), dload = (got.structure - exact.structure).norm();
      const double impulse_merit = impulse(a.r, local.W * a.r + local.q);
      std::cout << fmt::format("{:<34} {:>6.4f} {:>6} {:>8} {:>9.2e} {:>9.2e} {:>7} {:>9.3f} {:>9.3f} {:>9.3f} {:>9.3f} {:>9.4f} {:>9.4f}\n",
                               name, p.dt, p.contacts.size(), label, merit, impulse_merit, iterations, got.structure.norm(), dload,
                               max_f, df, max_m, dm);
      if (csv)
        csv << fmt::format("{},{:.6f},{},{},{},{},{},{},{:.6e},{:.6e},{},{:.9g},{:.9g},{:.9g},{:.6e},{:.6e},{:.6e},{:.6e},{:.6e}\n",
                           name, p.time, p.step, p.island, p.dt, p.contacts.size(), p.joint_rows(), label, merit,
                           impulse_merit, a.sweeps, got.structure.x(), got.structure.y(), got.structure.z(), dload, max_f, df,
                           max_m, dm);
    };
    row("tight", ref, std::to_string(ref.sweeps));
    if (file.answer) row("run", *file.answer, std::to_string(file.answer->sweeps));
    for (double tol : tolerances) {
      MethodOptions o;
      o.tolerance = tol;
      o.max_iterations = max_iterations;
      o.merit = merit;
      std::string iterations;
      const SolverAnswer a = solve_with(method, p, o, first_iterations, iterations);
      row(fmt::format("{:.0e}", tol), a, iterations);
    }
  }
  return 0;
}

int extract_command(const std::string& path, int body_id, const std::string& out) {
  const ContactProblem p = read_problem_file(path).problem;
  int k = -1;
  for (std::size_t i = 0; i < p.bodies.size(); ++i)
    if (p.bodies[i].id == body_id) k = static_cast<int>(i);
  if (k < 0) throw InputError(fmt::format("{}: no body with run index {}", path, body_id));
  ContactProblem q;
  q.bodies = {p.bodies[k]};
  for (ProblemContact c : p.contacts) {
    if (!((c.a == k && c.b < 0) || (c.b == k && c.a < 0))) continue;
    c.a = c.a == k ? 0 : -1;
    c.b = c.b == k ? 0 : -1;
    q.contacts.push_back(c);
  }
  q.time = p.time;
  q.dt = p.dt;
  q.step = p.step;
  q.island = p.island;
  q.source = fmt::format("{} (body {} and its contacts with fixed bodies)", p.source, body_id);
  q.box_friction = p.box_friction;
  write_problem_file(out, q);
  std::cout << fmt::format("{}: body {}, {} contacts with fixed bodies\n", out, body_id, q.contacts.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  register_siconos_methods();
  CLI::App app{"contact_problems: reference solutions and solves of contact problem files"};
  app.require_subcommand(1);
  std::vector<std::string> files, methods;
  double tolerance = 1e-6;
  int max_iterations = 200;
  bool cold = false;
  CLI::App* solve = app.add_subcommand("solve", "solve problems with contact methods");
  solve->add_option("files", files, "problem files")->required();
  solve->add_option("--method", methods, "methods (default: all)")->take_all();
  solve->add_option("--tolerance", tolerance, "merit to stop at (default 1e-6)");
  solve->add_option("--max-iterations", max_iterations, "iteration cap (default 200)");
  solve->add_flag("--cold", cold, "start from zero, not the warm start");
  std::string solve_merit = "siconos";
  solve->add_option("--merit", solve_merit, "the merit the tolerance bounds: siconos (default) or impulse");
  int first_iterations = 1000;
  solve->add_option("--first-iterations", first_iterations, "cap of A in a method A+B (default 1000)");
  CLI::App* reference = app.add_subcommand("reference", "write reference solutions into problem files");
  reference->add_option("files", files, "problem files")->required();
  CLI::App* errors = app.add_subcommand("errors", "load errors of a method's answers against a tight solution");
  std::string method = "apgd";
  std::vector<double> tolerances{1e-3, 1e-4, 1e-5};
  errors->add_option("files", files, "problem files")->required();
  errors->add_option("--method", method, "method, or A+B (default apgd)");
  errors->add_option("--first-iterations", first_iterations, "cap of A in a method A+B (default 1000)");
  errors->add_option("--tolerance", tolerances, "merits to stop at (default 1e-3 1e-4 1e-5)")->take_all();
  errors->add_option("--max-iterations", max_iterations, "iteration cap (default 200)");
  std::string csv_path;
  errors->add_option("--csv", csv_path, "also write every answer's errors to this CSV file");
  std::string merit_name = "siconos";
  errors->add_option("--merit", merit_name, "the merit the tolerances bound: siconos (default) or impulse");
  bool loaded_only = false;
  errors->add_flag("--loaded-only", loaded_only, "only islands that touch the structure or hold joints");
  CLI::App* extract = app.add_subcommand("extract", "one body and its contacts with fixed bodies, as a problem file");
  std::string extract_file, extract_out;
  int body_id = -1;
  extract->add_option("file", extract_file, "problem file")->required();
  extract->add_option("--body", body_id, "the body's run index (/icedem/body_ids)")->required();
  extract->add_option("-o,--output", extract_out, "the new problem file")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    if (*extract) return extract_command(extract_file, body_id, extract_out);
    if (*solve)
      return solve_command(files, methods, tolerance, merit_kind(solve_merit), max_iterations, cold, first_iterations);
    if (*errors)
      return errors_command(files, method, merit_kind(merit_name), tolerances, max_iterations, first_iterations, csv_path,
                            loaded_only);
    return reference_command(files);
  } catch (const std::exception& e) {
    std::cerr << "contact_problems: " << e.what() << "\n";
    return 2;
  }
}
