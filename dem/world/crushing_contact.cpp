#include "dem/world/crushing_contact.hpp"

#include <algorithm>
#include <vector>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/CollisionShapes/btPolyhedralConvexShape.h>

#include "dem/contact/contact_area.hpp"
#include "dem/world/bullet_eigen.hpp"
#include "dem/world/world.hpp"

namespace icedem {
namespace {

bool is_ice(const btCollisionObject& body) { return body.getUserIndex() == kIce; }

// the corners of a convex shape at `pose` in the tank frame, into `out` (ice bodies are boxes
// or convex hulls: dem/world/floe_shape.cpp; the structure's pieces convex hulls, the
// boundaries boxes); none if the shape is not polyhedral
void corners(const btCollisionShape* any, const btTransform& pose, std::vector<Eigen::Vector3d>& out) {
  out.clear();
  const auto* shape = dynamic_cast<const btPolyhedralConvexShape*>(any);
  if (!shape) return;
  for (int i = 0; i < shape->getNumVertices(); ++i) {
    btVector3 v;
    shape->getVertex(i, v);
    out.push_back(to_eigen(pose * v));
  }
}

void corners(const btCollisionObject& body, std::vector<Eigen::Vector3d>& out) {
  corners(body.getCollisionShape(), body.getWorldTransform(), out);
}

// how far Bullet's surface of a convex piece lies beyond its corners' hull: a convex hull's
// margin (it is grown by it), none for a box (its corners include it)
double margin_beyond_corners(const btCollisionShape& shape) {
  return dynamic_cast<const btBoxShape*>(&shape) ? 0.0 : shape.getMargin();
}

// the two bodies' corners, kept from one manifold to the next rather than allocated for each
// (one or two per crushing manifold and substep)
thread_local std::vector<Eigen::Vector3d> corners_a, corners_b;

// the nominal contact area of the overlap at point p (m^2)
double nominal_area(const btCollisionObject& a, const btCollisionObject& b, const btManifoldPoint& p) {
  const Eigen::Vector3d n = to_eigen(p.m_normalWorldOnB);  // from B to A
  if (is_ice(a) && is_ice(b)) {
    // both may crush, and the one of smaller section does: a corner pressed into a straight
    // edge crushes at the edge's face, over its section there. The larger of the common
    // sections on the two bodies' surfaces (through Bullet's point on each) is that, and is
    // the same for two like faces
    corners(a, corners_a);
    corners(b, corners_b);
    return std::max(common_section_area(corners_a, corners_b, Plane{to_eigen(p.getPositionWorldOnA()), n}),
                    common_section_area(corners_a, corners_b, Plane{to_eigen(p.getPositionWorldOnB()), n}));
  }
  // one body is ice: its section by the other's surface plane, where it lies over the other's
  // section by the parallel plane through the ice's deepest point. On a flat face (a wall, a
  // fixed box) that is the whole section; on the cone's facets, whose surface turns away
  // around the hull, a straight edge laid on a facet crushes over the band of the hull within
  // the penetration, not along its whole length
  const bool a_ice = is_ice(a);
  const btCollisionObject& other = a_ice ? b : a;
  const Eigen::Vector3d surface = to_eigen(a_ice ? p.getPositionWorldOnB() : p.getPositionWorldOnA());
  const Eigen::Vector3d deepest = to_eigen(a_ice ? p.getPositionWorldOnA() : p.getPositionWorldOnB());
  const Eigen::Vector3d outward = a_ice ? n : Eigen::Vector3d(-n);  // out of the other body
  corners(a_ice ? a : b, corners_a);
  const Plane at_surface{surface, n};
  // over one convex piece of the other body: its section as deep below its corners' hull as
  // the ice is below its surface
  const auto over_piece = [&](const btCollisionShape& shape, const btTransform& pose) {
    corners(&shape, pose, corners_b);
    if (corners_b.empty()) return section_area(corners_a, at_surface);  // no corners: its face taken as flat
    return common_section_area(corners_a, at_surface, corners_b,
                               Plane{deepest - margin_beyond_corners(shape) * outward, n});
  };
  // the structure's hull is a compound of convex pieces, one per segment of its profile
  // (dem/world/cone_geometry.hpp), that share only their seams: the ice at the waterline seam
  // lies over two of them, and their sections do not overlap
  if (const auto* compound = dynamic_cast<const btCompoundShape*>(other.getCollisionShape())) {
    double area = 0.0;
    for (int i = 0; i < compound->getNumChildShapes(); ++i)
      area += over_piece(*compound->getChildShape(i), other.getWorldTransform() * compound->getChildTransform(i));
    return area;
  }
  return over_piece(*other.getCollisionShape(), other.getWorldTransform());
}

// the manifold's deepest point, which stands for it (Bullet's points of one face lie on one plane);
// the manifold has at least one
const btManifoldPoint& deepest_point(const btPersistentManifold& manifold) {
  int deepest = 0;
  for (int i = 1; i < manifold.getNumContacts(); ++i)
    if (manifold.getContactPoint(i).getDistance() < manifold.getContactPoint(deepest).getDistance()) deepest = i;
  return manifold.getContactPoint(deepest);
}

}  // namespace

double manifold_overlap(const btPersistentManifold& manifold) {
  if (manifold.getNumContacts() == 0) return 0.0;
  return std::max(0.0, -double(deepest_point(manifold).getDistance()));
}

void CrushedIce::next_step() {
  std::swap(previous_, current_);
  current_.clear();
}

double CrushedIce::depth(const btPersistentManifold& manifold) {
  const double overlap = manifold_overlap(manifold);
  const auto it = previous_.find(&manifold);
  const bool known =
      it != previous_.end() && it->second.a == manifold.getBody0() && it->second.b == manifold.getBody1();
  double d = overlap;
  if (known) d = it->second.crushing ? std::max(it->second.depth, overlap) : std::min(it->second.depth, overlap);
  current_[&manifold] = Memory{manifold.getBody0(), manifold.getBody1(), d, false};
  return d;
}

void CrushedIce::set_crushing(const btPersistentManifold& manifold, bool crushing) {
  const auto it = current_.find(&manifold);
  if (it != current_.end()) it->second.crushing = crushing;
}

const CrushedIce::Memory* CrushedIce::remembered(const btPersistentManifold* manifold) const {
  const auto it = current_.find(manifold);
  if (it == current_.end() || it->second.a != manifold->getBody0() || it->second.b != manifold->getBody1())
    return nullptr;
  return &it->second;
}

void CrushedIce::remember(const btPersistentManifold* manifold, const Memory& memory) { current_[manifold] = memory; }

std::optional<double> crushing_cap(const btPersistentManifold& manifold, const CrushingLaw& law, double h,
                                   CrushingScope scope) {
  const btCollisionObject& a = *manifold.getBody0();
  const btCollisionObject& b = *manifold.getBody1();
  const int n = manifold.getNumContacts();
  if (n == 0 || (!is_ice(a) && !is_ice(b))) return std::nullopt;
  const auto either = [&](Material m) { return a.getUserIndex() == m || b.getUserIndex() == m; };
  if (scope == CrushingScope::kStructure && !either(kStructure)) return std::nullopt;
  if (scope == CrushingScope::kStructureAndHeldIce && !either(kStructure) && !either(kHeldIce)) return std::nullopt;
  const btManifoldPoint& p = deepest_point(manifold);
  // a point not yet touching (within the margins) has no overlap and carries nothing
  const double area = p.getDistance() < 0 ? nominal_area(a, b, p) : 0.0;
  return h * crushing_force(law, area) / n;
}

}  // namespace icedem
