#include "dem/fracture/ice_lattice.hpp"

#include "dem/core/errors.hpp"
#include "dem/world/joint_springs.hpp"

#include <cmath>
#include <functional>
#include <map>

namespace icedem {

ElementLattice floe_lattice(const Polygon& shape, double element_size, double& yaw0) {
  yaw0 = principal_yaw(shape);
  Polygon outline;
  for (const Eigen::Vector2d& v : shape) outline.push_back(rotate(v, -yaw0));
  return make_element_lattice(outline, element_size);
}

bool paper_lattice(const Polygon& outline, const FractureSettings& fracture) {
  if (fracture.element_shape != ElementShape::kSquare || fracture.lattice_angle != 0) return false;
  try {
    double yaw = 0;
    floe_lattice(outline, fracture.element_size, yaw);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

OutlineLattice floe_outline_lattice(const Polygon& shape, const FractureSettings& fracture, double& yaw0) {
  // the grid along the floe's principal axes, turned by fracture.lattice_angle: the outline is
  // filled in the grid's frame, and the elements are placed back through yaw0
  yaw0 = principal_yaw(shape) + fracture.lattice_angle;
  Polygon outline;
  for (const Eigen::Vector2d& v : shape) outline.push_back(rotate(v, -yaw0));
  return fill_outline(outline, fracture.element_size, fracture.element_shape, fracture.tiling);
}

namespace {

// The stand-in of a floe whose lattice waits outside the world (fracture.lattice_radius),
// and the lattice's record; the elements and joints are added after it
DormantLattice& add_stand_in(World& world, const Floe& floe, int floe_id, double y, double friction, int elements,
                             int joints, btTransform& stand_in_pose) {
  const FloeShape& whole = world.shape(floe.shape);
  stand_in_pose.setIdentity();
  stand_in_pose.setOrigin(btVector3(floe.centre.x(), y, floe.centre.y()));
  stand_in_pose.setRotation(btQuaternion(btVector3(0, 1, 0), floe.yaw + whole.principal_yaw));
  DormantLattice d;
  d.stand_in = world.add_resting_floe(whole, stand_in_pose, floe_id, friction);
  world.floes()[d.stand_in].stand_in = true;
  world.floes()[d.stand_in].lattice = static_cast<int>(world.lattices().size());
  d.first_element = static_cast<int>(world.floes().size());
  d.elements = elements;
  d.first_joint = static_cast<int>(world.joints().size());
  d.joints = joints;
  d.radius = whole.radius;
  world.lattices().push_back(std::move(d));
  return world.lattices().back();
}

// Bullet's fixed joint between two elements with the fracture settings' softness: springs
// of the ice (elastic joints) or Bullet's ERP and CFM
void add_element_joint(World& world, IceJoint joint, const btTransform& frame_a, const btTransform& frame_b,
                       const JointSprings& springs, const FractureSettings& fracture, bool in_world) {
  btRigidBody& body_a = *world.floes()[joint.body_a].body;
  btRigidBody& body_b = *world.floes()[joint.body_b].body;
  if (fracture.elastic_joints)
    joint.constraint = std::make_unique<SpringJoint>(body_a, body_b, frame_a, frame_b, springs, kSpringJointErp);
  else
    joint.constraint = std::make_unique<btFixedConstraint>(body_a, body_b, frame_a, frame_b);
  // softness set on all six axes (axis -1, Bullet's default for setParam, is silently ignored)
  for (int axis = 0; axis < 6; ++axis) {
    joint.constraint->setParam(BT_CONSTRAINT_STOP_CFM, fracture.cfm, axis);
    joint.constraint->setParam(BT_CONSTRAINT_STOP_ERP, fracture.elastic_joints ? kSpringJointErp : fracture.erp, axis);
  }
  // more iterations for the joints than for contacts where asked: Bullet solves a
  // constraint's rows for max(its override, solver.iterations) sweeps, contacts
  // only for solver.iterations (btSequentialImpulseConstraintSolver)
  if (fracture.joint_iterations > 0) joint.constraint->setOverrideNumSolverIterations(fracture.joint_iterations);
  joint.feedback = std::make_unique<btJointFeedback>();
  joint.constraint->setJointFeedback(joint.feedback.get());
  world.add_joint(std::move(joint), in_world);
}

// A floe of any outline, or of hexagons: its outline lattice's elements, each a body of its
// own shape (the convex hull of its part: exact for a convex outline) turned to its own
// principal axes, and a joint at the middle of each shared face whose frame has x along the
// face's normal (the springs and the loads are in that frame) and whose capacities follow
// the face's length (dem/fracture/fracture.cpp)
void add_outline_lattice_floe(World& world, const Floe& floe, int floe_id, double y, const FractureSettings& fracture,
                              const IceSettings& ice, double friction, bool held) {
  double yaw0 = 0;
  const OutlineLattice lattice = floe_outline_lattice(floe.shape, fracture, yaw0);
  const double yaw = floe.yaw + yaw0;
  const double floe_area = area(floe.shape);
  const AddedMass plate = plate_added_mass(floe_area, world.settings().water.water_density);
  const bool dormant = !held && fracture.lattice_radius > 0;
  btTransform stand_in_pose;
  if (dormant) {
    DormantLattice& d = add_stand_in(world, floe, floe_id, y, friction, static_cast<int>(lattice.elements.size()),
                                     static_cast<int>(lattice.joints.size()), stand_in_pose);
    d.equal_elements = false;  // make_dormant weighs its elements' motion by their masses
  }
  const int first = static_cast<int>(world.floes().size());
  std::vector<double> element_yaw;  // each element's body axes against the floe's principal frame
  for (const OutlineElement& e : lattice.elements) {
    Polygon local;
    for (const Eigen::Vector2d& v : e.hull) local.push_back(v - e.moments.centroid);
    const FloeShape& shape = world.shape(local);
    element_yaw.push_back(shape.principal_yaw);
    const Eigen::Vector2d at = floe.centre + rotate(e.moments.centroid, yaw);
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(btVector3(at.x(), y, at.y()));
    pose.setRotation(btQuaternion(btVector3(0, 1, 0), yaw + shape.principal_yaw));
    const int index = world.add_body(shape, pose, floe_id, friction, 0, !dormant,
                                     element_added_mass(plate, floe_area, e.moments.area));
    if (held) world.freeze(world.floes()[index]);
    if (dormant) {
      world.floes()[index].lattice = static_cast<int>(world.lattices().size()) - 1;
      world.lattices().back().offsets.push_back(stand_in_pose.inverse() * pose);
    }
  }
  int index = 0;
  for (const OutlineJoint& j : lattice.joints) {
    const Eigen::Vector2d ca = lattice.elements[j.a].moments.centroid, cb = lattice.elements[j.b].moments.centroid;
    const double pa = element_yaw[j.a], pb = element_yaw[j.b];
    IceJoint joint;
    joint.floe = floe_id;
    joint.index = index++;
    joint.body_a = first + j.a;
    joint.body_b = first + j.b;
    joint.face_length = j.face_length;
    const Eigen::Vector2d mid_a = rotate(j.midpoint - ca, -pa), mid_b = rotate(j.midpoint - cb, -pb);
    const Eigen::Vector2d axis_a = rotate(j.axis, -pa);
    joint.midpoint_a = Eigen::Vector3d(mid_a.x(), 0, mid_a.y());
    joint.axis_a = Eigen::Vector3d(axis_a.x(), 0, axis_a.y());
    // the frames' x along the face's normal, the same direction seen from both bodies
    const double turn_a = std::atan2(-axis_a.y(), axis_a.x());
    btTransform frame_a, frame_b;
    frame_a.setIdentity();
    frame_b.setIdentity();
    frame_a.setOrigin(btVector3(mid_a.x(), 0, mid_a.y()));
    frame_b.setOrigin(btVector3(mid_b.x(), 0, mid_b.y()));
    frame_a.setRotation(btQuaternion(btVector3(0, 1, 0), turn_a));
    frame_b.setRotation(btQuaternion(btVector3(0, 1, 0), turn_a + pa - pb));
    add_element_joint(world, std::move(joint), frame_a, frame_b,
                      elastic_joint_springs_along(fracture, ice, j.face_length, (cb - ca).norm()), fracture,
                      !dormant && !held);
  }
}

}  // namespace

void add_lattice_floe(World& world, const Floe& floe, int floe_id, double y, const FractureSettings& fracture,
                      const IceSettings& ice, double friction, bool held) {
  if (!paper_lattice(floe.shape, fracture)) {
    add_outline_lattice_floe(world, floe, floe_id, y, fracture, ice, friction, held);
    return;
  }
  // the lattice in the floe's principal frame (elements are squares in that frame)
  double yaw0 = 0;
  const double Le = fracture.element_size;
  const ElementLattice lattice = floe_lattice(floe.shape, Le, yaw0);
  const FloeShape& element = world.shape(square(Le));
  const double floe_area = area(floe.shape);
  const AddedMass element_added = element_added_mass(
      plate_added_mass(floe_area, world.settings().water.water_density), floe_area, Le * Le);

  const double yaw = floe.yaw + yaw0;
  const btQuaternion rotation(btVector3(0, 1, 0), yaw);

  // far from the structure the floe is one rigid body: its elements wait outside the world
  const bool dormant = !held && fracture.lattice_radius > 0;
  btTransform stand_in_pose;
  if (dormant)
    add_stand_in(world, floe, floe_id, y, friction, static_cast<int>(lattice.centres.size()),
                 static_cast<int>(lattice.joints.size()), stand_in_pose);

  const int first = static_cast<int>(world.floes().size());
  for (const Eigen::Vector2d& c : lattice.centres) {
    const Eigen::Vector2d at = floe.centre + rotate(c, yaw);
    btTransform pose;
    pose.setIdentity();
    pose.setOrigin(btVector3(at.x(), y, at.y()));
    pose.setRotation(rotation);
    // one piece: its elements do not collide with each other (fragment 0); the floe's added mass
    // shared among its elements (dem/water/added_mass.hpp)
    const int index = world.add_body(element, pose, floe_id, friction, 0, !dormant, element_added);
    if (held) world.freeze(world.floes()[index]);
    if (dormant) {
      DormantLattice& d = world.lattices().back();
      world.floes()[index].lattice = static_cast<int>(world.lattices().size()) - 1;
      d.offsets.push_back(stand_in_pose.inverse() * pose);
    }
  }

  // fixed joints at the middle of each shared face
  int index = 0;
  for (const LatticeJoint& j : lattice.joints) {
    IceJoint joint;
    joint.floe = floe_id;
    joint.index = index++;
    joint.body_a = first + j.a;
    joint.body_b = first + j.b;
    const Eigen::Vector2d mid_a = j.midpoint - lattice.centres[j.a];
    const Eigen::Vector2d mid_b = j.midpoint - lattice.centres[j.b];
    joint.midpoint_a = Eigen::Vector3d(mid_a.x(), 0, mid_a.y());
    joint.axis_a = Eigen::Vector3d(j.axis.x(), 0, j.axis.y());
    btTransform frame_a, frame_b;
    frame_a.setIdentity();
    frame_b.setIdentity();
    frame_a.setOrigin(btVector3(mid_a.x(), 0, mid_a.y()));
    frame_b.setOrigin(btVector3(mid_b.x(), 0, mid_b.y()));
    // elastic: springs of the ice, the same at any step (dem/world/joint_springs.hpp); else
    // Bullet's ERP and CFM set the stiffness. A dormant lattice's joints wait for wake_lattice
    const JointSprings springs = elastic_joint_springs(fracture, ice, joint.axis_a);
    add_element_joint(world, std::move(joint), frame_a, frame_b, springs, fracture, !dormant && !held);
  }
}

void wake_lattice(World& world, DormantLattice& lattice) {
  if (lattice.replaced) return;
  std::vector<FloeBody>& floes = world.floes();
  world.enter_reached(lattice.stand_in);  // if nothing had reached it: as if it had been in the world
  FloeBody& whole = floes[lattice.stand_in];
  if (whole.frozen) world.unfreeze(whole);
  btRigidBody& w = *whole.body;
  const btTransform T = w.getCenterOfMassTransform();
  const btVector3 v = w.getLinearVelocity(), omega = w.getAngularVelocity();
  world.dynamics().removeRigidBody(&w);
  w.forceActivationState(DISABLE_SIMULATION);
  const bool sleeping = world.settings().activation.sleeping;
  for (int i = 0; i < lattice.elements; ++i) {
    btRigidBody& e = *floes[lattice.first_element + i].body;
    const btTransform pose = T * lattice.offsets[i];
    e.setCenterOfMassTransform(pose);  // also the interpolation pose
    e.getMotionState()->setWorldTransform(pose);
    // rigid-body motion of the stand-in at the element's place
    e.setLinearVelocity(v + omega.cross(pose.getOrigin() - T.getOrigin()));
    e.setAngularVelocity(omega);
    world.enter_world(e);
    // awake: the structure is near (the sleep clock starts again)
    e.forceActivationState(sleeping ? ACTIVE_TAG : DISABLE_DEACTIVATION);
    e.setDeactivationTime(0);
  }
  for (int j = 0; j < lattice.joints; ++j) {
    btTypedConstraint* c = world.joints()[lattice.first_joint + j].constraint.get();
    if (c) world.dynamics().addConstraint(c, false);
  }
  lattice.replaced = true;
}

bool make_dormant(World& world, DormantLattice& lattice) {
  if (!lattice.replaced || lattice.broken) return false;
  std::vector<FloeBody>& floes = world.floes();
  for (int i = 0; i < lattice.elements; ++i)
    if (floes[lattice.first_element + i].frozen) return false;
  // the floe's motion, orientation from the first element through its offset. Equal squares:
  // centre of mass and mean velocities of the elements. Elements of unequal masses (an
  // outline's or hexagons', cut at the outline): the stand-in's centre where the elements'
  // poses put it, and the rigid motion of the same momentum, each element's velocity taken
  // back to that centre (v_i + omega x (X - x_i)) and weighed by its mass; exact for a lattice
  // moving as one body, whatever its elements' shapes. For equal elements the two are the same
  // motion; the squares keep the plain means only so that their runs (and the golden runs) stay
  // bit for bit what they were: the weighted sums round differently
  btVector3 v(0, 0, 0), omega(0, 0, 0);
  bool awake = false;
  for (int i = 0; i < lattice.elements; ++i)
    awake = awake || liveness(*floes[lattice.first_element + i].body) == Liveness::kAwake;
  btTransform T = floes[lattice.first_element].body->getCenterOfMassTransform() * lattice.offsets[0].inverse();
  T.setOrigin(lattice_centre(world, lattice));
  if (lattice.equal_elements) {
    for (int i = 0; i < lattice.elements; ++i) {
      const btRigidBody& e = *floes[lattice.first_element + i].body;
      v += e.getLinearVelocity();
      omega += e.getAngularVelocity();
    }
    v /= lattice.elements;
    omega /= lattice.elements;
  } else {
    double mass = 0;
    for (int i = 0; i < lattice.elements; ++i) {
      const btRigidBody& e = *floes[lattice.first_element + i].body;
      const double m = 1.0 / e.getInvMass();
      omega += m * e.getAngularVelocity();
      mass += m;
    }
    omega /= mass;
    for (int i = 0; i < lattice.elements; ++i) {
      const btRigidBody& e = *floes[lattice.first_element + i].body;
      v += (e.getLinearVelocity() + omega.cross(T.getOrigin() - e.getCenterOfMassPosition())) / e.getInvMass();
    }
    v /= mass;
  }

  for (int j = 0; j < lattice.joints; ++j)
    world.dynamics().removeConstraint(world.joints()[lattice.first_joint + j].constraint.get());
  for (int i = 0; i < lattice.elements; ++i) {
    btRigidBody& e = *floes[lattice.first_element + i].body;
    world.dynamics().removeRigidBody(&e);
    e.forceActivationState(DISABLE_SIMULATION);
  }
  btRigidBody& w = *floes[lattice.stand_in].body;
  w.setCenterOfMassTransform(T);
  w.getMotionState()->setWorldTransform(T);
  w.setLinearVelocity(v);
  w.setAngularVelocity(omega);
  world.enter_world(w);
  w.forceActivationState(!world.settings().activation.sleeping ? DISABLE_DEACTIVATION
                         : awake                                ? ACTIVE_TAG
                                                                : ISLAND_SLEEPING);
  w.setDeactivationTime(0);
  lattice.replaced = false;
  return true;
}

btVector3 lattice_centre(const World& world, const DormantLattice& lattice) {
  const std::vector<FloeBody>& floes = world.floes();
  if (!lattice.replaced) return floes[lattice.stand_in].body->getCenterOfMassPosition();
  btVector3 centre(0, 0, 0);
  for (int i = 0; i < lattice.elements; ++i) {
    const btRigidBody& e = *floes[lattice.first_element + i].body;
    // unequal elements: the stand-in's centre as each element's pose puts it (pose_i offset_i^-1),
    // the mean of those; a mean of the elements' centres would not be the floe's centre of mass
    // (equal squares keep that mean, the same point, for their bit-for-bit runs: make_dormant)
    centre += lattice.equal_elements ? e.getCenterOfMassPosition()
                                     : (e.getCenterOfMassTransform() * lattice.offsets[i].inverse()).getOrigin();
  }
  return centre / lattice.elements;
}

Eigen::Isometry3d output_pose(const World& world, const FloeBody& floe) {
  if (floe.lattice >= 0 && !floe.stand_in) {
    const DormantLattice& d = world.lattices()[floe.lattice];
    if (!d.replaced) {
      const int i = floe.body->getUserIndex2() - d.first_element;
      return to_eigen(world.floes()[d.stand_in].body->getCenterOfMassTransform() * d.offsets[i]);
    }
  }
  return body_pose(*floe.body);
}

bool output_awake(const World& world, const FloeBody& floe) {
  if (floe.lattice >= 0 && !floe.stand_in && !world.lattices()[floe.lattice].replaced)
    return liveness(*world.floes()[world.lattices()[floe.lattice].stand_in].body) == Liveness::kAwake;
  return liveness(*floe.body) == Liveness::kAwake;
}

namespace {

void update_fragments(World& world, int floe_id) {
  std::vector<FloeBody>& floes = world.floes();
  // level ice: thousands of elements, most held; only those whose fragment changed need new
  // broadphase pairs, and a held element stays asleep (dem/fracture/level_ice.hpp)
  const bool sheet = world.level_sheet() && world.level_sheet()->floe_id == floe_id;
  // fragments: connected components of the floe's elements over intact joints
  std::vector<int> bodies;
  for (int b = 0; b < static_cast<int>(floes.size()); ++b)
    if (floes[b].floe_id == floe_id && floes[b].fragment >= 0) bodies.push_back(b);
  std::map<int, int> parent;
  for (int b : bodies) parent[b] = b;
  std::function<int(int)> root = [&](int x) { return parent[x] == x ? x : parent[x] = root(parent[x]); };
  for (const IceJoint& j : world.joints())
    if (j.floe == floe_id && j.constraint) parent[root(j.body_a)] = root(j.body_b);
  // the sheet's fragments named by their first element, which a break elsewhere leaves as it was
  // (a root of the union depends on the order of all the unions before it)
  std::map<int, int> first;
  if (sheet)
    for (int b : bodies) first.emplace(root(b), b);  // bodies ascend: the first is the least
  std::vector<char> changed(bodies.size(), 1);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const int fragment = sheet ? first.at(root(bodies[k])) : root(bodies[k]);
    changed[k] = !sheet || floes[bodies[k]].fragment != fragment;
    floes[bodies[k]].fragment = fragment;
  }
  // new broadphase pairs between pieces that came apart: re-create their proxies
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (!changed[k]) continue;
    FloeBody& f = floes[bodies[k]];
    if (!(sheet && f.frozen)) f.body->activate(true);
    // the sheet's pairs keep their sides through a checkpoint (World::refresh_proxy); the floes'
    // are left as they were made, the paper profile's runs bit for bit
    if (sheet)
      world.refresh_proxy(*f.body);
    else
      world.dynamics().refreshBroadphaseProxy(f.body);
  }
}

}  // namespace

void break_joint(World& world, IceJoint& joint) {
  if (!joint.constraint) return;
  const int lattice = world.floes()[joint.body_a].lattice;
  if (lattice >= 0) world.lattices()[lattice].broken = true;
  world.dynamics().removeConstraint(joint.constraint.get());
  joint.constraint.reset();
  if (std::optional<LevelSheet>& sheet = world.level_sheet(); sheet && joint.floe == sheet->floe_id)
    sheet->joint_in_world[joint.index] = 0;  // out of the solver (dem/fracture/level_ice.hpp)
  update_fragments(world, joint.floe);
}

}  // namespace icedem
