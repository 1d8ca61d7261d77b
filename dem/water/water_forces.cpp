// Buoyancy, form drag, skin friction and damping of the water on one body (see
// water_forces.hpp for the model and its sources).
#include "dem/water/water_forces.hpp"

#include <algorithm>
#include <cmath>

namespace icedem {

WaterParams water_params(const WaterSettings& w) {
  return WaterParams{w.density, w.gravity, w.drag_coefficient, w.skin_friction_coefficient,
                     w.heave_damping_ratio, w.roll_pitch_damping_ratio, w.linear_buoyancy};
}

DampingCoefficients damping_coefficients(const ConvexPolyhedron& body, double mass,
                                         double horizontal_inertia, const WaterParams& p) {
  DampingCoefficients d;
  const double volume = body_volume(body);
  d.displaced_volume = std::min(mass / p.water_density, volume);

  // waterplane of the upright body floating freely (through the COM if it sinks)
  double level = equilibrium_water_level(body, d.displaced_volume);
  if (d.displaced_volume >= volume) level = 0.0;
  const WaterplaneSection wp = waterplane_section(body, Eigen::Isometry3d::Identity(), level);

  // c = 2 zeta sqrt(m k): k = rho g A_wp in heave, rho g I_wp in roll/pitch
  const double rho_g = p.water_density * p.gravity;
  d.heave = 2.0 * p.heave_damping_ratio * std::sqrt(mass * rho_g * wp.area);
  d.roll_pitch = 2.0 * p.roll_pitch_damping_ratio *
                 std::sqrt(horizontal_inertia * rho_g * std::max(0.0, wp.second_moment_min));
  return d;
}

Wrench water_wrench(const ConvexPolyhedron& body, const BodyMotion& motion, const FlowField& flow,
                    const WaterParams& p, const DampingCoefficients& d) {
  // per-thread submersion reused between calls: no allocation once its face list has grown
  thread_local Submersion sub;
  submerge(body, motion.pose, 0.0, sub);

  Wrench w;
  if (!(sub.volume > 0.0)) return w;
  const Eigen::Vector3d com = motion.pose.translation();

  // buoyancy at the centre of buoyancy (Archimedes)
  const Eigen::Vector3d buoyancy(0.0, p.water_density * p.gravity * sub.volume, 0.0);
  w.force += buoyancy;
  w.torque += (sub.centroid - com).cross(buoyancy);
  if (p.linear_buoyancy)  // the ablation: the column above each upward-facing wetted face pushes up too
    for (const WettedFace& face : sub.faces)
      if (face.normal.y() > 0.0 && face.centroid.y() < 0.0) {
        const Eigen::Vector3d up(0.0, p.water_density * p.gravity * (-face.centroid.y()) * face.area * face.normal.y(),
                                 0.0);
        w.force += up;
        w.torque += (face.centroid - com).cross(up);
      }

  // form drag and skin friction per wetted face, lumped at its centroid
  const double half_rho = 0.5 * p.water_density;
  for (const WettedFace& face : sub.faces) {
    const Eigen::Vector3d arm = face.centroid - com;
    const Eigen::Vector3d v_body = motion.linear_velocity + motion.angular_velocity.cross(arm);
    const Eigen::Vector3d v_rel = v_body - flow.velocity(face.centroid);
    const double v_n = v_rel.dot(face.normal);
    const Eigen::Vector3d v_t = v_rel - v_n * face.normal;

    Eigen::Vector3d f = -half_rho * p.skin_friction_coefficient * face.area * v_t.norm() * v_t;
    if (v_n > 0.0) {
      // the face advances into the water: stagnation pressure on it
      f -= half_rho * p.drag_coefficient * face.area * v_n * v_n * face.normal;
    }
    w.force += f;
    w.torque += arm.cross(f);
  }

  // linear heave and roll/pitch damping, fading out as the body leaves the water
  const double s = d.displaced_volume > 0.0 ? std::min(1.0, sub.volume / d.displaced_volume) : 1.0;
  w.force.y() -= s * d.heave * motion.linear_velocity.y();
  w.torque.x() -= s * d.roll_pitch * motion.angular_velocity.x();
  w.torque.z() -= s * d.roll_pitch * motion.angular_velocity.z();
  return w;
}

}  // namespace icedem
