// Conversions between Bullet's and Eigen's vectors and transforms, in one place.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <btBulletDynamicsCommon.h>

namespace icedem {

inline Eigen::Vector3d to_eigen(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

inline btVector3 to_bt(const Eigen::Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }

inline Eigen::Isometry3d to_eigen(const btTransform& t) {
  const btQuaternion q = t.getRotation();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()).toRotationMatrix();
  pose.translation() = to_eigen(t.getOrigin());
  return pose;
}

/// A body's centre-of-mass pose as an Eigen transform (body frame -> tank frame).
inline Eigen::Isometry3d body_pose(const btRigidBody& body) { return to_eigen(body.getCenterOfMassTransform()); }

/// The impulse a contact point applied to body 0 of its manifold in the last solve, N s: the
/// normal impulse and both friction directions' (body 1 felt the opposite).
inline btVector3 contact_impulse(const btManifoldPoint& p) {
  return p.m_normalWorldOnB * p.m_appliedImpulse + p.m_lateralFrictionDir1 * p.m_appliedImpulseLateral1 +
         p.m_lateralFrictionDir2 * p.m_appliedImpulseLateral2;
}

}  // namespace icedem
