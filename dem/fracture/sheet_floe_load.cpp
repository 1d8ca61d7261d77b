#include "dem/fracture/sheet_floe_load.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <btBulletDynamicsCommon.h>

#include "dem/world/bullet_eigen.hpp"
#include "dem/world/contact_solver.hpp"

namespace icedem {
namespace {

// the point of the outline nearest to p, and the sheet's inward normal there (ccw seen from above, +y: in (x, z)
// the inside is on the right of each side, dem/layout/polygon.hpp; at a corner the mean of its two sides' normals)
struct OnOutline {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  Eigen::Vector2d inward = Eigen::Vector2d::UnitX();
  double distance = std::numeric_limits<double>::infinity();
};

OnOutline nearest_on_outline(const Polygon& sheet, const Eigen::Vector2d& p) {
  const std::size_t n = sheet.size();
  const auto inward_of = [&](std::size_t i) {
    const Eigen::Vector2d t = (sheet[(i + 1) % n] - sheet[i]).normalized();
    return Eigen::Vector2d(t.y(), -t.x());
  };
  OnOutline best;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = sheet[i], b = sheet[(i + 1) % n];
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    if (length2 <= 0) continue;
    const double s = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
    const Eigen::Vector2d q = a + s * ab;
    const double d = (p - q).norm();
    if (d >= best.distance) continue;
    best.point = q;
    best.distance = d;
    Eigen::Vector2d normal = inward_of(i);
    if (s <= 0.0) normal += inward_of((i + n - 1) % n);
    if (s >= 1.0) normal += inward_of((i + 1) % n);
    best.inward = normal.normalized();
  }
  return best;
}

}  // namespace

bool at_edge(const Polygon& sheet, const Eigen::Vector2d& at, double thickness) {
  return nearest_on_outline(sheet, at).distance <= kEdgeReach * thickness;
}

PrismContact prism_contact(const btPersistentManifold& manifold, const std::vector<const btCollisionObject*>& prisms) {
  if (manifold.getNumContacts() == 0) return {};
  const auto is_prism = [&](const btCollisionObject* o) {
    return std::binary_search(prisms.begin(), prisms.end(), o);
  };
  const bool prism0 = is_prism(manifold.getBody0()), prism1 = is_prism(manifold.getBody1());
  const btCollisionObject* other = prism0 ? manifold.getBody1() : manifold.getBody0();
  if (prism0 == prism1 || other->getUserIndex2() < 0) return {};  // two prisms or none, or a prism and a fixed body
  return PrismContact{other->getUserIndex2(), prism0};
}

std::vector<SheetLoadPoint> floe_loads_on_prisms(const btDispatcher& dispatcher,
                                                 const std::vector<const btCollisionObject*>& prisms, double h) {
  auto& d = const_cast<btDispatcher&>(dispatcher);
  std::vector<std::pair<const btPersistentManifold*, PrismContact>> touching;
  for (int i = 0; i < d.getNumManifolds(); ++i) {
    const btPersistentManifold* m = d.getManifoldByIndexInternal(i);
    const PrismContact c = prism_contact(*m, prisms);
    if (c.floe >= 0) touching.emplace_back(m, c);
  }
  // the canonical order, so that the sums do not depend on the order of Bullet's arrays
  std::sort(touching.begin(), touching.end(), [](const auto& a, const auto& b) {
    return ContactSolver::canonical(a.first) < ContactSolver::canonical(b.first);
  });
  std::vector<SheetLoadPoint> out;
  for (const auto& [m, c] : touching) {
    for (int k = 0; k < m->getNumContacts(); ++k) {
      const btManifoldPoint& p = m->getContactPoint(k);
      // the impulse acts on body 0, its opposite on body 1
      const Eigen::Vector3d on0 = to_eigen(contact_impulse(p)) / h;
      const Eigen::Vector3d at = to_eigen(c.prism_first ? p.getPositionWorldOnA() : p.getPositionWorldOnB());
      out.push_back(SheetLoadPoint{Eigen::Vector2d(at.x(), at.z()), c.prism_first ? on0 : Eigen::Vector3d(-on0), c.floe});
    }
  }
  return out;
}

FloePatches floe_patches(const Polygon& sheet, const std::vector<SheetLoadPoint>& points, double thickness) {
  FloePatches out;
  std::map<int, std::vector<const SheetLoadPoint*>> by_floe;  // ordered by floe: the patches in a fixed order
  for (const SheetLoadPoint& p : points) {
    if (at_edge(sheet, p.at, thickness))
      by_floe[p.floe].push_back(&p);
    else
      out.interior_vertical += std::abs(p.force.y());
  }
  for (const auto& [floe, mine] : by_floe) {
    Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    double weight = 0;
    for (const SheetLoadPoint* p : mine) {
      weighted += p->force.norm() * p->at;
      weight += p->force.norm();
      force += p->force;
    }
    if (weight <= 0) continue;  // touching, carrying nothing
    const OnOutline on = nearest_on_outline(sheet, weighted / weight);
    SheetContact c;
    c.centre = on.point;
    c.direction = on.inward;
    const Eigen::Vector2d across(-c.direction.y(), c.direction.x());
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const SheetLoadPoint* p : mine) {
      low = std::min(low, p->at.dot(across));
      high = std::max(high, p->at.dot(across));
    }
    c.half_width = std::max((high - low) / 2, kLeastPatch * thickness / 2);
    c.normal_force = force.norm();
    c.horizontal_force = Eigen::Vector2d(force.x(), force.z()).dot(c.direction);
    c.bending_force = std::abs(force.y());
    out.patches.push_back(std::move(c));
    out.floes.push_back(floe);
  }
  return out;
}

}  // namespace icedem
