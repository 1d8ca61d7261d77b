#include "dem/contact/siconos.hpp"

#include <cstdlib>
#include <cstring>
#include <memory>

#include <Eigen/SparseCore>

#include "dem/contact/registry.hpp"

// Siconos' headers declare C functions inside their own extern "C" blocks
#include <siconos/numerics/FrictionContactProblem.h>
#include <siconos/numerics/NonSmoothDrivers.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/SolverOptions.h>

namespace icedem {
namespace {

// Siconos frees what a problem holds with free(): give it malloc'd copies
double* malloc_copy(const Eigen::VectorXd& v) {
  auto* out = static_cast<double*>(std::malloc(sizeof(double) * std::max<Eigen::Index>(v.size(), 1)));
  if (v.size()) std::memcpy(out, v.data(), sizeof(double) * v.size());
  return out;
}

}  // namespace

SolverAnswer SiconosMethod::solve_local(const LocalForm& local, const Eigen::VectorXd& guess,
                                        const MethodOptions& options) {
  const int m = static_cast<int>(local.q.size());
  SolverAnswer answer;
  answer.r = Eigen::VectorXd::Zero(m);
  if (m == 0) return answer;
  if (options.warm_start) answer.r = guess;

  NumericsMatrix* W = NM_create(NM_SPARSE, m, m);
  NM_triplet_alloc(W, local.W.nonZeros());
  for (int col = 0; col < local.W.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(local.W, col); it; ++it)
      NM_entry(W, static_cast<int>(it.row()), static_cast<int>(it.col()), it.value());
  NM_csc(W);
  FrictionContactProblem* problem =
      frictionContactProblem_new_with_data(3, m / 3, W, malloc_copy(local.q), malloc_copy(local.mu));
  SolverOptions* so = solver_options_create(solver_);
  so->dparam[SICONOS_DPARAM_TOL] = options.tolerance;
  so->iparam[SICONOS_IPARAM_MAX_ITER] = options.max_iterations;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(m);
  const int info = fc3d_driver(problem, answer.r.data(), u.data(), so);
  answer.sweeps = so->iparam[SICONOS_IPARAM_ITER_DONE];
  answer.residual = so->dparam[SICONOS_DPARAM_RESIDU];
  answer.capped = info != 0;
  solver_options_delete(so);
  frictionContactProblem_free(problem);
  return answer;
}

SolverAnswer SiconosMethod::solve(const ContactProblem& p, const MethodOptions& options) {
  refuse_crushing(p, "siconos");
  SolverAnswer answer = solve_local(local_form(p), contact_guess(p), options);
  answer.l = joint_impulses(p, answer.r);
  return answer;
}

void register_siconos_methods() {
  static const bool registered = [] {
    const struct {
      const char* name;
      int solver;
      const char* description;
    } methods[] = {
        {"siconos_nsgs", SiconosMethod::kNsgs, "Siconos numerics' nonsmooth Gauss-Seidel on the Delassus form"},
        {"siconos_nsn_ac", SiconosMethod::kNsnAc, "Siconos numerics' semismooth Newton, Alart-Curnier"},
        {"siconos_nsn_fb", SiconosMethod::kNsnFb, "Siconos numerics' semismooth Newton, Fischer-Burmeister"},
        {"siconos_prox", SiconosMethod::kProx, "Siconos numerics' proximal point (semismooth Newton inside)"},
        {"siconos_admm", SiconosMethod::kAdmm, "Siconos numerics' ADMM"},
    };
    for (const auto& m : methods) {
      const int solver = m.solver;
      register_contact_method({m.name, m.description, [solver] { return std::make_unique<SiconosMethod>(solver); },
                               false});
    }
    return true;
  }();
  (void)registered;
}

}  // namespace icedem
