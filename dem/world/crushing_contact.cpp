#include "dem/world/crushing_contact.hpp"

#include <algorithm>
#include <vector>

#include <BulletCollision/CollisionShapes/btPolyhedralConvexShape.h>

#include "dem/contact/contact_area.hpp"
#include "dem/world/bullet_eigen.hpp"
#include "dem/world/world.hpp"

namespace icedem {
namespace {

bool is_ice(const btCollisionObject& body) { return body.getUserIndex() == kIce; }

// the corners of a body's shape in the tank frame, into `out` (ice bodies are boxes or convex
// hulls: dem/world/floe_shape.cpp)
void corners(const btCollisionObject& body, std::vector<Eigen::Vector3d>& out) {
  out.clear();
  const auto* shape = dynamic_cast<const btPolyhedralConvexShape*>(body.getCollisionShape());
  if (!shape) return;
  const btTransform& pose = body.getWorldTransform();
  for (int i = 0; i < shape->getNumVertices(); ++i) {
    btVector3 v;
    shape->getVertex(i, v);
    out.push_back(to_eigen(pose * v));
  }
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
  // one body is ice: its section by the other's surface
  const bool a_ice = is_ice(a);
  const Eigen::Vector3d surface = to_eigen(a_ice ? p.getPositionWorldOnB() : p.getPositionWorldOnA());
  corners(a_ice ? a : b, corners_a);
  return section_area(corners_a, Plane{surface, a_ice ? n : Eigen::Vector3d(-n)});
}

}  // namespace

std::optional<double> crushing_cap(const btPersistentManifold& manifold, const CrushingLaw& law, double h) {
  const btCollisionObject& a = *manifold.getBody0();
  const btCollisionObject& b = *manifold.getBody1();
  const int n = manifold.getNumContacts();
  if (n == 0 || (!is_ice(a) && !is_ice(b))) return std::nullopt;
  // the deepest point stands for the manifold (Bullet's points of one face lie on one plane)
  int deepest = 0;
  for (int i = 1; i < n; ++i)
    if (manifold.getContactPoint(i).getDistance() < manifold.getContactPoint(deepest).getDistance()) deepest = i;
  const btManifoldPoint& p = manifold.getContactPoint(deepest);
  // a point not yet touching (within the margins) has no overlap and carries nothing
  const double area = p.getDistance() < 0 ? nominal_area(a, b, p) : 0.0;
  return h * crushing_force(law, area) / n;
}

}  // namespace icedem
