// Element joints as springs of the ice (fracture.joint_stiffness = "elastic").
//
// Bullet softens a joint row by ERP and CFM, and the stiffness they give grows as
// 1/h^2 with the step h (its CFM is scaled by the row's effective mass; measured
// 60, 195 and 635 MPa at 1, 2 and 4 substeps: docs/model/bullet.md). Here every row
// of an element joint is a spring K of the ice between the two element centres,
// integrated implicitly: with the row's position error e (m or rad) and impulse
// l = f h over the step,
//   J v = e / h - l / (h^2 K),
// i.e. ERP = 1 and a compliance C = 1 / (h^2 K) (ODE's convention with no damping:
// implicit Euler damps on its own). The force a row settles to for an error e is K e
// at any h, so the lattice has the same modulus at any step and number of substeps.
//
// The springs of a joint between two square elements of side L and thickness H, the
// ice between their centres a beam of length L and cross-section L x H (E the
// modulus, G = E / (2 (1 + nu)) the shear modulus), in the joint frame (x along the
// joint axis from A to B, y up, z across):
//   axial           E L H / L              = E H
//   shear (y, z)    G L H / L              = G H
//   torsion (x)     G (L H^3 / 3) / L      = G H^3 / 3        (thin section, beta = 1/3)
//   bending (z)     E (L H^3 / 12) / L     = E H^3 / 12       (out of plane: the plate's bending)
//   bending (y)     E (H L^3 / 12) / L     = E H L^2 / 12     (in plane)
// times fracture.stiffness_scale, the one factor calibrated on the plate-deflection
// test for what a lattice of rigid squares misses of a continuous plate.
#pragma once

#include <Eigen/Core>
#include <BulletDynamics/ConstraintSolver/btFixedConstraint.h>

namespace icedem {

struct FractureSettings;
struct IceSettings;

/// The stiffness of a joint's six rows, in the frame of body A's axes (the joint's
/// constraint frames are A's and B's body axes): N/m along x, y, z, then N m/rad about them.
using JointSprings = Eigen::Matrix<double, 6, 1>;

/// The springs of a joint whose axis, from A's centre towards B's, is `axis_a` in A's
/// body frame (horizontal: +x or +z), for `fracture`'s element size and stiffness scale
/// and `ice`'s modulus, Poisson ratio and thickness.
JointSprings elastic_joint_springs(const FractureSettings& fracture, const IceSettings& ice,
                                   const Eigen::Vector3d& axis_a);

/// The springs of a joint in its own frame (x along the joint axis, y up, z across) between
/// two elements whose centres are `distance` apart and which share a face `face_length` long
/// (elements cut at a floe's outline, hexagons: dem/fracture/outline_lattice.hpp): the ice
/// between the centres a beam of that length and of cross-section face_length x H, so axial
/// E f H / d, shear G f H / d, torsion G (f H^3 / 3) / d, in-plane bending E (H f^3 / 12) / d,
/// out-of-plane bending E (f H^3 / 12) / d, times fracture.stiffness_scale. For two squares
/// of side L (f = d = L) these are elastic_joint_springs' with the axis along x.
JointSprings elastic_joint_springs_along(const FractureSettings& fracture, const IceSettings& ice, double face_length,
                                         double distance);

/// The stop ERP a spring joint's rows are written with: Bullet writes the position
/// error e as erp e / h, the solver reads it back (any erp > 0 would do; fracture.erp is
/// for Bullet's own joints).
inline constexpr double kSpringJointErp = 1.0;

/// A fixed joint whose rows are springs: the contact solver (dem/world/contact_solver.cpp)
/// rewrites its rows' bias and compliance from them every step.
class SpringJoint : public btFixedConstraint {
 public:
  SpringJoint(btRigidBody& a, btRigidBody& b, const btTransform& frame_a, const btTransform& frame_b,
              const JointSprings& springs, double erp)
      : btFixedConstraint(a, b, frame_a, frame_b), springs_(springs), erp_(erp) {}
  const JointSprings& springs() const { return springs_; }
  /// The stop ERP the rows were written with by Bullet (their error is read back through it).
  double erp() const { return erp_; }

 private:
  JointSprings springs_;
  double erp_;
};

}  // namespace icedem
