// The contact methods' cost per iteration on real islands (dem/contact/): the accelerated
// projected gradient's step (two passes over the contacts' rows and M^-1 per body, the
// projection, every 4th step the merit) and the Newton method's step (a sparse Cholesky
// factorisation and a line search), each run for a fixed number of iterations from the
// run's warm start on the two jams of the paper's small-floe run kept as test data
// (tests/physics/data/contact/: 59 and 73 contacts). A figure per iteration to track as the
// kernels change (docs/model/contact_problems.md, "Its speed"): the time over the counter
// `iterations` (per solve) is one iteration's.
#include <benchmark/benchmark.h>

#include <string>

#include "dem/contact/registry.hpp"
#include "dem/contact/problem_file.hpp"

using namespace icedem;

namespace {

const char* const kProblems[] = {"small_floes_t052.9.hdf5", "small_floes_t124.5.hdf5"};

const ContactProblem& problem(int which) {
  static const ContactProblem p[] = {
      read_problem_file(std::string(ICEDEM_SOURCE_DIR) + "/tests/physics/data/contact/" + kProblems[0]).problem,
      read_problem_file(std::string(ICEDEM_SOURCE_DIR) + "/tests/physics/data/contact/" + kProblems[1]).problem};
  return p[which];
}

// `iterations` of `method` from the warm start, the tolerance out of reach so that every
// solve takes them all
void run(benchmark::State& s, const char* method, int iterations) {
  const ContactProblem& p = problem(static_cast<int>(s.range(0)));
  auto m = make_contact_method(method);
  MethodOptions options;
  options.tolerance = 0.0;
  options.max_iterations = iterations;
  long done = 0;
  for (auto _ : s) {
    const SolverAnswer a = m->solve(p, options);
    done += a.sweeps;
    benchmark::DoNotOptimize(a.residual);
  }
  // the method's iterations per solve (backtracking trials count): the time over it is one's cost
  s.counters["iterations"] = benchmark::Counter(static_cast<double>(done), benchmark::Counter::kAvgIterations);
  s.SetLabel(std::string(kProblems[s.range(0)]) + ", " + std::to_string(p.contacts.size()) + " contacts");
}

void BM_ApgdIterations(benchmark::State& s) { run(s, "apgd", 200); }
void BM_NewtonIterations(benchmark::State& s) { run(s, "newton", 20); }

}  // namespace

BENCHMARK(BM_ApgdIterations)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NewtonIterations)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
