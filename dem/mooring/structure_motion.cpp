#include "dem/mooring/structure_motion.hpp"

#include <Eigen/Geometry>

namespace icedem {

Eigen::Matrix3d rotation_matrix(const StructureMotionState& m) {
  const double angle = m.rotation.norm();
  if (angle == 0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, m.rotation / angle).toRotationMatrix();
}

MooringLoad mooring_load_at(const Scene& scene, const FloatingStructure& body, const Eigen::Vector3d& reference,
                            const StructureMotionState& m, double time) {
  return body.mooring->load(reference, rotation_matrix(m), scene.structure.speed * time);
}

void advance_structure(const Scene& scene, const FloatingStructure& body, double h, double carriage,
                       Eigen::Vector3d& reference, StructureMotionState& m, const Eigen::Vector3d& extra) {
  const Eigen::Matrix3d r = rotation_matrix(m);
  const Eigen::Vector3d arm = r * Eigen::Vector3d(0, body.gravity_centre_y, 0);  // reference point to G
  Eigen::Vector3d centre = reference + arm;

  // forces at the step's start: the ice's impulse of the step before, the water's weight balance
  // (exact buoyancy upright), the mooring and the steady pull
  const MooringLoad mooring = body.mooring->load(reference, r, carriage);
  const Eigen::Vector3d buoyancy(0, hull_buoyancy(scene, reference.y()) - body.mass * scene.water.gravity, 0);
  const Eigen::Vector3d force = buoyancy + mooring.force + extra;
  const Eigen::Vector3d impulse = m.ice_impulse + h * force;
  // moments about G: the ice's and the mooring's were taken about the reference point
  const Eigen::Vector3d to_reference = -arm;
  const Eigen::Vector3d restoring(-body.tilt_stiffness * m.rotation.x(), 0, -body.tilt_stiffness * m.rotation.z());
  const Eigen::Vector3d angular_impulse = m.ice_angular_impulse + to_reference.cross(m.ice_impulse) +
                                          h * (mooring.moment + to_reference.cross(mooring.force) + restoring);

  // semi-implicit Euler, the damping implicit, on the motion relative to the carriage
  const Eigen::Vector3d carriage_velocity(scene.structure.speed, 0, 0);
  for (int i = 0; i < 3; ++i) {
    const double mass = body.mass + body.added_mass[i], inertia = body.inertia[i] + body.added_inertia[i];
    const double c = h * body.damping[i] / mass;
    m.velocity[i] = (m.velocity[i] + impulse[i] / mass + c * carriage_velocity[i]) / (1 + c);
    m.angular_velocity[i] = (m.angular_velocity[i] + angular_impulse[i] / inertia) / (1 + h * body.angular_damping[i] / inertia);
  }
  centre += h * m.velocity;
  const double turn = m.angular_velocity.norm() * h;
  Eigen::Matrix3d next = r;
  if (turn > 0) next = Eigen::AngleAxisd(turn, m.angular_velocity.normalized()).toRotationMatrix() * r;
  const Eigen::AngleAxisd aa(next);
  m.rotation = aa.angle() * aa.axis();
  reference = centre - next * Eigen::Vector3d(0, body.gravity_centre_y, 0);
  m.ice_impulse.setZero();
  m.ice_angular_impulse.setZero();
}

}  // namespace icedem
