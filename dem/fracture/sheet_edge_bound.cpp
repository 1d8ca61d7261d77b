#include "dem/fracture/sheet_edge_bound.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include <btBulletDynamicsCommon.h>

#include "dem/fracture/sheet_floe_load.hpp"
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
  std::vector<std::pair<const btManifoldPoint*, double>> normals;  // each point's |n_y|, in the order of points
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
      normals.emplace_back(&p, std::abs(double(p.m_normalWorldOnB.y())));
    }
  }
  if (points.empty()) return;
  const FloePatches patches = floe_patches(outline_, points, ice_.thickness);
  std::unordered_map<int, double> load;  // N, each floe's patch's breaking load
  for (std::size_t k = 0; k < patches.patches.size(); ++k)
    load[patches.floes[k]] = plan_sheet_break(outline_, patches.patches[k], ice_).breaking_load;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& [point, vertical] = normals[i];
    if (vertical <= 0) continue;  // a push on the edge's face bends nothing
    const double p = load.at(points[i].floe);
    caps_[point] = Bound{h * p / vertical, points[i].floe, vertical, h * p};
  }
}

bool SheetEdgeBound::tighten(const std::vector<std::pair<const btManifoldPoint*, double>>& impulses) {
  std::map<int, double> sum;  // N s, each floe's sum of r_N |n_y| over its bounded points
  for (const auto& [point, impulse] : impulses) {
    const auto it = caps_.find(point);
    if (it != caps_.end()) sum[it->second.floe] += impulse * it->second.vertical;
  }
  bool lowered = false;
  for (const auto& [point, impulse] : impulses) {
    const auto it = caps_.find(point);
    if (it == caps_.end()) continue;
    Bound& b = it->second;
    const double total = sum[b.floe];
    if (total <= (1.0 + ContactSolver::kAtBound) * b.patch_bound) continue;
    // its share of the patch's bound: the sum of the shares is the bound
    b.cap = std::min(b.cap, impulse * b.patch_bound / total);
    lowered = true;
  }
  return lowered;
}

double SheetEdgeBound::cap(const btManifoldPoint& point) const {
  const auto it = caps_.find(&point);
  return it == caps_.end() ? kUnbounded : it->second.cap;
}

std::vector<int> SheetEdgeBound::floes_at_bound() const {
  std::vector<int> out;
  for (const auto& [point, bound] : caps_)
    if (point->m_appliedImpulse >= (1.0 - ContactSolver::kAtBound) * bound.cap) out.push_back(bound.floe);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace icedem
