// A bound on the normal impulse of chosen contacts that a stage other than the contact law sets, inside the solve.
//
// The contact law says what a contact bears (rigid, or crushing: dem/contact/crushing.hpp). Some bodies fail under
// less: the analytic level sheet's edge breaks at its closed-form breaking load (dem/fracture/sheet_edge_bound.hpp).
// Read only after the step, such a failure comes a step late: the solve lets a piece locked between the moving
// structure and the held sheet bear whatever the structure's contact carries (up to thirty times the edge's
// breaking load at one step of the crushing tows), and that step is the tow's largest load. So the stage bounds the
// rows it owns before the solve, as the crushing law bounds its own (each row's normal impulse in [0, cap], a row at
// its cap gives way), and reads after the step which rows reached their bound. A bound on a sum of rows (a patch's
// load, shared by its points) is not a row's: the stage bounds each row by the whole, and after the solve lowers
// the caps of a sum found over its bound to the rows' shares of it (tighten), and the island is solved again from
// that answer, until no sum is over.
#pragma once

#include <limits>
#include <utility>
#include <vector>

class btManifoldPoint;
class btPersistentManifold;

namespace icedem {

class ContactBound {
 public:
  virtual ~ContactBound() = default;
  /// A new Bullet step begins (before any island is solved).
  virtual void begin_step() = 0;
  /// The manifolds of one island, about to be made rows for the step of `h` (s).
  virtual void prepare(btPersistentManifold* const* manifolds, int count, double h) = 0;
  /// The largest normal impulse (N s) `point` may carry this step, infinity where this bound does not hold it.
  virtual double cap(const btManifoldPoint& point) const = 0;
  /// The island's bounded points and the normal impulses (N s) its solve gave them: lower caps where a sum of them is
  /// over its bound; whether any cap changed (the island is then solved again).
  virtual bool tighten(const std::vector<std::pair<const btManifoldPoint*, double>>& impulses) = 0;
};

/// No bound: a row's cap where a ContactBound does not hold it.
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

}  // namespace icedem
