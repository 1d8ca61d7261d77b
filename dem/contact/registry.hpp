// The contact methods by name: one row each, what `solver.method` offers (dem/input/scenario_keys),
// what the benchmark and the tests make by name. A new method is a file pair in dem/contact/ and
// a row in registry.cpp (docs/model/architecture.md, "How to add a contact method").
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dem/contact/method.hpp"

namespace icedem {

/// The name of the in-run sweeps: projected Gauss-Seidel over the rows Bullet set up
/// (dem/world/contact_solver.hpp), the one method that is not a ContactMethod on the problem.
inline constexpr const char* kBulletSweeps = "pgs";

struct ContactMethodEntry {
  std::string name;
  std::string description;  // one line: what it is
  // makes the method; null for kBulletSweeps, which the world's contact solver runs itself
  std::function<std::unique_ptr<ContactMethod>()> make;
  bool in_runs = false;  // a choice of solver.method; else the benchmark's and the tests' only
  // solves crushing contacts (a normal bounded by its cap, dem/contact/crushing.hpp); the others
  // throw on them (refuse_crushing)
  bool takes_crushing = false;
};

/// Every method, the ones of runs first. Siconos numerics' methods are added by the benchmark
/// and the tests (register_siconos_methods, dem/contact/siconos.hpp), not linked into runs.
const std::vector<ContactMethodEntry>& contact_methods();

/// Adds `entry` to the registry. Throws std::invalid_argument if its name is taken.
void register_contact_method(ContactMethodEntry entry);

/// The names of the methods (all, or the choices of solver.method).
std::vector<std::string> contact_method_names(bool runs_only = false);

/// Whether the method `name` takes crushing contacts (false for an unknown name and for
/// kBulletSweeps).
bool takes_crushing(const std::string& name);

/// The method `name` makes. Throws std::invalid_argument for an unknown name or for
/// kBulletSweeps (not a method on the problem).
std::unique_ptr<ContactMethod> make_contact_method(const std::string& name);

}  // namespace icedem
