#include "dem/world/joint_springs.hpp"

#include <cmath>

#include "dem/input/scene.hpp"

namespace icedem {

JointSprings elastic_joint_springs(const FractureSettings& f, const IceSettings& ice, const Eigen::Vector3d& axis_a) {
  const double E = ice.elastic_modulus, G = E / (2.0 * (1.0 + ice.poisson_ratio));
  const double H = ice.thickness, L = f.element_size;
  // in the joint frame: axial, shear up, shear across; torsion, in-plane bending, out-of-plane bending
  const double axial = E * H, shear = G * H;
  const double torsion = G * H * H * H / 3.0, in_plane = E * H * L * L / 12.0, out_of_plane = E * H * H * H / 12.0;
  JointSprings k;
  const bool along_x = std::abs(axis_a.x()) > std::abs(axis_a.z());
  // body x, y, z: the joint axis is x or z; y is up
  k << (along_x ? axial : shear), shear, (along_x ? shear : axial),
      (along_x ? torsion : out_of_plane), in_plane, (along_x ? out_of_plane : torsion);
  return f.stiffness_scale * k;
}

JointSprings elastic_joint_springs_along(const FractureSettings& f, const IceSettings& ice, double face_length,
                                         double distance) {
  const double E = ice.elastic_modulus, G = E / (2.0 * (1.0 + ice.poisson_ratio));
  const double H = ice.thickness, L = face_length, d = distance;
  JointSprings k;
  k << E * L * H / d, G * L * H / d, G * L * H / d,  // axial, shear up, shear across
      G * L * H * H * H / 3.0 / d, E * H * L * L * L / 12.0 / d, E * L * H * H * H / 12.0 / d;  // torsion, bending
  return f.stiffness_scale * k;
}

}  // namespace icedem
