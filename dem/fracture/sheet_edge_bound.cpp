#include "dem/fracture/sheet_edge_bound.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include <btBulletDynamicsCommon.h>

#include "dem/fracture/sheet_floe_load.hpp"
#include "dem/world/bullet_eigen.hpp"
#include "dem/world/contact_solver.hpp"

namespace icedem {

void SheetEdgeBound::set_sheet(const Polygon& outline, std::vector<const btCollisionObject*> prisms) {
  outline_ = outline;
  prisms_ = std::move(prisms);
  std::sort(prisms_.begin(), prisms_.end());
}

void SheetEdgeBound::prepare(btPersistentManifold* const* manifolds, int count, double h) {
  // the island's points on the sheet's edge, each of unit weight: floe_patches then makes each floe's patch from where
  // its points are (their mean, their spread), as it will from where the forces act after the step. A floe's points
  // farther in are an interior load, in no patch after the step: left out here, and not bounded
  std::vector<SheetLoadPoint> points;
  // each point's |n_y| and the sign that makes its impulse on body 0 the sheet's, in the order of points
  struct Normal {
    const btManifoldPoint* point;
    double vertical, sign;
  };
  std::vector<Normal> normals;
  for (int i = 0; i < count; ++i) {
    const btPersistentManifold& m = *manifolds[i];
    const PrismContact c = prism_contact(m, prisms_);
    if (c.floe < 0) continue;
    for (int k = 0; k < m.getNumContacts(); ++k) {
      const btManifoldPoint& p = m.getContactPoint(k);
      const btVector3 at = c.prism_first ? p.getPositionWorldOnA() : p.getPositionWorldOnB();
      const Eigen::Vector2d plan(at.x(), at.z());
      if (!at_edge(outline_, plan, ice_.thickness)) continue;
      points.push_back(SheetLoadPoint{plan, Eigen::Vector3d::UnitY(), c.floe});
      normals.push_back({&p, std::abs(double(p.m_normalWorldOnB.y())), c.prism_first ? 1.0 : -1.0});
    }
  }
  if (points.empty()) return;
  const FloePatches patches = floe_patches(outline_, points, ice_.thickness);
  std::unordered_map<int, double> load;  // N, each floe's patch's breaking load
  for (std::size_t k = 0; k < patches.patches.size(); ++k)
    load[patches.floes[k]] = plan_sheet_break(outline_, patches.patches[k], ice_).breaking_load;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Normal& n = normals[i];
    const double p = load.at(points[i].floe);
    // a point pushing on the edge's face (n_y = 0) has no cap of its own: only its friction bends the edge, and the
    // patch's sum (tighten) holds that
    caps_[n.point] = Bound{n.vertical > 0 ? h * p / n.vertical : kUnbounded, points[i].floe, h * p, n.sign};
  }
}

bool SheetEdgeBound::tighten(const std::vector<BoundedImpulse>& impulses) {
  // N s, each floe's push normal to the sheet over its held points: the vertical part of their impulses on the sheet,
  // the normals' and the friction's, summed with their signs, as the sheet's load read after the step sums them
  // (floe_patches): friction lifting a piece at one point and its normal pressing it down at another bend the edge
  // by what is left
  std::map<int, double> sum;
  for (const BoundedImpulse& i : impulses) {
    const auto it = caps_.find(i.point);
    if (it != caps_.end()) sum[it->second.floe] += it->second.sign * double(i.impulse.y());
  }
  bool lowered = false;
  for (const BoundedImpulse& i : impulses) {
    const auto it = caps_.find(i.point);
    if (it == caps_.end()) continue;
    Bound& b = it->second;
    const double total = std::abs(sum[b.floe]);
    if (total <= (1.0 + ContactSolver::kAtBound) * b.patch_bound) continue;
    // its share of the patch's bound, on its normal impulse, which also bounds its friction: the shares sum to the
    // bound where the push is all normal; friction above its share lowers it again at the next pass
    b.cap = std::min(b.cap, i.normal * b.patch_bound / total);
    b.lowered = lowered = true;
  }
  return lowered;
}

std::optional<double> SheetEdgeBound::cap(const btManifoldPoint& point) const {
  const auto it = caps_.find(&point);
  if (it == caps_.end()) return std::nullopt;
  return it->second.cap;
}

std::vector<int> SheetEdgeBound::floes_at_bound() const {
  // a floe gave way where its patch's push in the answer kept is at its bound: to ContactSolver::kAtBound, or where
  // tighten held the patch (lowered its points' caps to their shares) to kPatchAtBound, the passes' slack. Not where
  // one of its points sits at a cap while the sum is below. At its first cap (the whole h P on its normal), a piece
  // pressing the edge down at one point and lifting it at another bends it by the difference (in the crushing tows,
  // such a floe broke the sheet at 0.28 of its patch's load); at a cap tighten lowered to its share, the next solve may
  // move the push to the patch's other points or turn its friction against it (a floe pressing the edge's face
  // sideways broke the sheet at 0.003 of its load, its one point with an impulse at its lowered cap; a cap lowered to
  // nothing, its point's normal impulse none at the pass, is met by no impulse at all)
  struct Push {
    double sum = 0;     // N s, of sign J_y over the patch's points
    double bound = 0;   // N s, h P
    bool held = false;  // a point's cap lowered by tighten
  };
  std::map<int, Push> push;  // by floe
  for (const auto& [point, bound] : caps_) {
    Push& p = push[bound.floe];
    p.sum += bound.sign * double(contact_impulse(*point).y());
    p.bound = bound.patch_bound;
    p.held = p.held || bound.lowered;
  }
  std::vector<int> out;
  for (const auto& [floe, p] : push)
    if (std::abs(p.sum) >= (1.0 - (p.held ? kPatchAtBound : ContactSolver::kAtBound)) * p.bound) out.push_back(floe);
  return out;  // in increasing order: a std::map's keys
}

}  // namespace icedem
