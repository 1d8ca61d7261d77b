#include "dem/contact/registry.hpp"

#include <algorithm>
#include <stdexcept>

#include "dem/contact/apgd.hpp"
#include "dem/contact/interior_point.hpp"
#include "dem/contact/newton.hpp"
#include "dem/contact/pgs.hpp"

namespace icedem {
namespace {

template <typename Method, typename... Args>
std::function<std::unique_ptr<ContactMethod>()> maker(Args... args) {
  return [args...] { return std::make_unique<Method>(args...); };
}

std::vector<ContactMethodEntry>& registry() {
  static std::vector<ContactMethodEntry> methods{
      {kBulletSweeps,
       "projected Gauss-Seidel sweeps over Bullet's rows, friction clamped per direction (a square), in the run's "
       "own solver (dem/world/contact_solver.hpp)",
       nullptr, true},
      {"pgs_cone", "projected Gauss-Seidel on the island's problem, friction projected onto Coulomb's disc",
       maker<ProjectedGaussSeidel>(true), true, true},
      {"newton", "primal Newton on the island's whole problem, joints included (dem/contact/newton.hpp)",
       maker<PrimalNewton>(), true, true},
      {"apgd", "accelerated projected gradient on the island's problem, as Project Chrono's (dem/contact/apgd.hpp)",
       maker<AcceleratedProjectedGradient>(), true, true},
      {"ipm",
       "primal-dual interior-point method on the island's whole problem, joints included "
       "(dem/contact/interior_point.hpp)",
       maker<InteriorPoint>(), true},
      {"pgs_square",
       "projected Gauss-Seidel on the island's problem, friction clamped per direction as Bullet's rows: the "
       "in-run sweeps' twin on a problem file",
       maker<ProjectedGaussSeidel>(false), false, true},
  };
  return methods;
}

const ContactMethodEntry* find(const std::string& name) {
  for (const ContactMethodEntry& e : registry())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace

const std::vector<ContactMethodEntry>& contact_methods() { return registry(); }

void register_contact_method(ContactMethodEntry entry) {
  if (find(entry.name)) throw std::invalid_argument("contact method \"" + entry.name + "\" is registered already");
  registry().push_back(std::move(entry));
}

std::vector<std::string> contact_method_names(bool runs_only) {
  std::vector<std::string> names;
  for (const ContactMethodEntry& e : registry())
    if (e.in_runs || !runs_only) names.push_back(e.name);
  return names;
}

bool takes_crushing(const std::string& name) {
  const ContactMethodEntry* e = find(name);
  return e && e->takes_crushing;
}

std::unique_ptr<ContactMethod> make_contact_method(const std::string& name) {
  const ContactMethodEntry* e = find(name);
  if (!e) throw std::invalid_argument("unknown contact method \"" + name + "\"");
  if (!e->make)
    throw std::invalid_argument("contact method \"" + name + "\" sweeps Bullet's rows in the run's solver; it is "
                                "not a method on a contact problem (pgs_square is its twin there)");
  return e->make();
}

}  // namespace icedem
