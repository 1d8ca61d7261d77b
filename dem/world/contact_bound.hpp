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
// that answer, until no sum is over. The sum may hold what a cap cannot: the friction a point's normal impulse
// allows (a push on the sheet's face holding a piece up by friction bends the edge), so tighten is given each held
// point's whole impulse, and a point may be held by the sum alone, with no cap of its own until one is over.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include <LinearMath/btVector3.h>

class btManifoldPoint;
class btPersistentManifold;

namespace icedem {

/// A point a ContactBound holds and what the island's last solve gave it.
struct BoundedImpulse {
  const btManifoldPoint* point = nullptr;
  double normal = 0;                  // N s, its normal impulse
  btVector3 impulse{0, 0, 0};         // N s, on body 0 of its manifold: the normal's and the friction's together
};

class ContactBound {
 public:
  virtual ~ContactBound() = default;
  /// A new Bullet step begins (before any island is solved).
  virtual void begin_step() = 0;
  /// The manifolds of one island, about to be made rows for the step of `h` (s).
  virtual void prepare(btPersistentManifold* const* manifolds, int count, double h) = 0;
  /// Whether this bound holds `point` this step (none: not), and the largest normal impulse (N s) it may carry:
  /// kUnbounded where only a sum holds it.
  virtual std::optional<double> cap(const btManifoldPoint& point) const = 0;
  /// The island's held points and what its solve gave them: lower caps where a sum of them is over its bound; whether
  /// any cap changed (the island is then solved again).
  virtual bool tighten(const std::vector<BoundedImpulse>& impulses) = 0;
};

/// No cap: a row's where neither the contact law nor a ContactBound caps it.
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

}  // namespace icedem
