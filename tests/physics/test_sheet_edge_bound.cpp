// The analytic level sheet's edge bears at most its breaking load inside the contact solve
// (dem/fracture/sheet_edge_bound.hpp): a floe pressing down on the edge is held by each of its points on the edge up to
// the breaking load of its patch, and no further, where the held sheet would otherwise carry whatever it is given;
// a floe pressing on the edge's face sideways bends nothing and is not bounded, unless its friction there bends it.
//
// The sheet: a fixed prism of the paper's ice (0.033 m) over x in [0, 1] m, its edge along z at x = 0; the solve the
// accelerated projected gradient to a merit of 1e-9 (the bound is a projection: a bounded point's impulse is at most
// its cap to round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "dem/core/errors.hpp"
#include "dem/fracture/analytic_sheet.hpp"
#include "dem/fracture/sheet_breaking.hpp"
#include "dem/fracture/sheet_edge_bound.hpp"
#include "dem/fracture/sheet_floe_load.hpp"
#include "dem/world/bullet_eigen.hpp"
#include "dem/world/contact_solver.hpp"
#include "dem/world/world.hpp"
#include "tests/support/box_world.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;
using namespace icedem::testing;

namespace {

const SheetIce& paper_ice() {
  static const SheetIce ice = sheet_ice(scene_from(""));
  return ice;
}

const Polygon& sheet_outline() {
  static const Polygon outline = make_ccw({{0.0, -0.5}, {1.0, -0.5}, {1.0, 0.5}, {0.0, 0.5}});
  return outline;
}

// A bench whose solver is icedem's (rigid contacts, the gradient method to 1e-9), the sheet's prism in it, and the
// edge's bound installed when `bounded`
struct SheetBench {
  explicit SheetBench(bool bounded) : bound(paper_ice()) {
    SolverSettings s = test_solver_settings();
    s.method = "apgd";
    s.merit_tolerance = s.joint_merit_tolerance = s.structure_merit_tolerance = 1e-9;
    s.method_iterations = 20000;
    auto owned = std::make_unique<ContactSolver>(s);
    solver = owned.get();
    bench = std::make_unique<Bench>(std::move(owned));
    const double h = paper_ice().thickness;
    prism = bench->box({0.5, h / 2, 0.5}, at(0.5, -h / 2, 0.0), 0.0, 0.5, kBoundary);
    bound.set_sheet(sheet_outline(), {prism});
    if (bounded) solver->set_contact_bound(&bound);
  }
  // the block's contact points with the prism
  std::vector<const btManifoldPoint*> points_of(const btRigidBody* block) {
    std::vector<const btManifoldPoint*> out;
    btDispatcher& d = *bench->world().getDispatcher();
    for (int i = 0; i < d.getNumManifolds(); ++i) {
      const btPersistentManifold* m = d.getManifoldByIndexInternal(i);
      if ((m->getBody0() == block && m->getBody1() == prism) || (m->getBody1() == block && m->getBody0() == prism))
        for (int k = 0; k < m->getNumContacts(); ++k) out.push_back(&m->getContactPoint(k));
    }
    return out;
  }

  SheetEdgeBound bound;
  ContactSolver* solver = nullptr;
  std::unique_ptr<Bench> bench;
  const btRigidBody* prism = nullptr;
};

// a 0.2 m x 0.2 m block of the ice's thickness, `mass` kg, resting with its near side on the edge: its bottom face
// over x in [-0.05, 0.15] m, in contact with the sheet over [0, 0.15]
btRigidBody* block_on_edge(SheetBench& b, double mass) {
  const double h = paper_ice().thickness;
  btRigidBody* block = b.bench->box({0.1, h / 2, 0.1}, at(0.05, h / 2 - 1e-4, 0.0), mass, 0.5, kIce);
  block->setUserIndex2(0);  // floe 0
  return block;
}

// the breaking load of the block's patch on the edge (its two points there, 0.2 m apart along it), N
double edge_breaking_load() {
  SheetContact patch;
  patch.centre = Eigen::Vector2d(0.0, 0.0);
  patch.direction = Eigen::Vector2d(1.0, 0.0);
  patch.half_width = 0.1;
  return plan_sheet_break(sheet_outline(), patch, paper_ice()).breaking_load;
}

}  // namespace

// A 100 kg block resting on the edge, its centre of mass 5 cm in: its two points on the edge would carry two thirds of
// its weight (moments about the block's centre: 654 N), some 20 times the edge's breaking load. With the bound the
// two points together carry the breaking load over the step, no more (to 1e-3 of it: a bound counts as reached within
// the merit's relative tolerance; each bounded alone by the whole would let them carry twice it), and the floe is
// reported as at its bound; without it the edge carries the two thirds (to 1 %: the solve's merit and Bullet's
// points' spread over its margin), so the bound is what holds it
TEST(SheetEdgeBound, AFloePressingDownOnTheEdgeIsHeldAtMostAtTheBreakingLoad) {
  const double mass = 100.0, load = edge_breaking_load();
  ASSERT_GT(2.0 / 3.0 * mass * kGravity, 10 * load) << "the weight on the edge is well above its breaking load";
  const double h = paper_ice().thickness;
  const auto edge_force = [&](bool bounded, std::vector<int>* at_bound) {
    SheetBench b(bounded);
    btRigidBody* block = block_on_edge(b, mass);
    b.bench->world().stepSimulation(kDt, 1, kDt);
    double on_edge = 0;  // N, the vertical force of the block's points on the edge
    int edge_points = 0;
    for (const btManifoldPoint* p : b.points_of(block)) {
      const btVector3 at = p->getPositionWorldOnA();
      if (!at_edge(sheet_outline(), Eigen::Vector2d(at.x(), at.z()), h)) continue;
      ++edge_points;
      const double vertical = std::abs(p->m_appliedImpulse * p->m_normalWorldOnB.y()) / kDt;
      on_edge += vertical;
      if (bounded) {
        EXPECT_LE(vertical, load * (1 + 1e-9)) << "a point on the edge";
      }
    }
    EXPECT_EQ(edge_points, 2) << "the block's near corners";
    if (at_bound) *at_bound = b.bound.floes_at_bound();
    return on_edge;
  };
  std::vector<int> at_bound;
  const double bounded = edge_force(true, &at_bound);
  EXPECT_NEAR(bounded, load, 1e-3 * load) << "the patch at its breaking load, shared by its points";
  EXPECT_EQ(at_bound, std::vector<int>{0});
  EXPECT_NEAR(edge_force(false, nullptr), 2.0 / 3.0 * mass * kGravity, 0.01 * mass * kGravity);
}

// A block pushed sideways into the edge's face (no gravity, 500 N along +x): its contact's normal is horizontal,
// it bends nothing, and the face carries the whole push over the step (to 1e-6: the solve's merit), far above the
// breaking load: the held sheet takes an in-plane push rigidly, bound or not. No floe at its bound
TEST(SheetEdgeBound, APushOnTheEdgesFaceIsNotBounded) {
  SheetBench b(true);
  const double h = paper_ice().thickness;
  btRigidBody* block = b.bench->box({0.1, h / 2, 0.1}, at(-0.1 + 1e-4, -h / 2, 0.0), 2.0, 0.0, kIce);
  block->setUserIndex2(0);
  block->setGravity(btVector3(0, 0, 0));
  const double push = 500.0;  // N
  ASSERT_GT(push, 10 * edge_breaking_load());
  block->applyCentralForce(btVector3(push, 0, 0));
  b.bench->world().stepSimulation(kDt, 1, kDt);
  double carried = 0;  // N, along x on the block
  for (const btManifoldPoint* p : b.points_of(block)) {
    ASSERT_TRUE(b.bound.cap(*p).has_value()) << "a point on the face: held by its patch's sum";
    EXPECT_GE(*b.bound.cap(*p), 1e6 * push * kDt) << "a point on the face: no cap of its own";
    carried += std::abs(p->m_appliedImpulse * p->m_normalWorldOnB.x()) / kDt;
  }
  EXPECT_NEAR(carried, push, 1e-6 * push);
  EXPECT_TRUE(b.bound.floes_at_bound().empty());
}

// A 10 kg block pushed sideways into the edge's face (1000 N along +x) and held up there by its friction alone (its
// weight, 98 N, 2.35 times the edge's breaking load, within what the friction can carry): the friction on the face
// bends the edge. With the bound the block's points push the edge vertically by the breaking load over the step (to
// 2 %: the passes lower the points' normal impulses, and with them the friction, but the face's points partly stick
// and take up what the others shed, so each pass cuts the excess by about half: 0.9 % above after the solver's eight
// solves), and the floe is reported as at its bound; without it the face carries the whole weight (to 1e-6: the
// solve's merit), so the bound is what holds it
TEST(SheetEdgeBound, FrictionOnTheEdgesFaceIsHeldAtMostAtTheBreakingLoad) {
  const double h = paper_ice().thickness, mass = 10.0, push = 1000.0, load = edge_breaking_load();
  ASSERT_GT(mass * kGravity, 2 * load) << "the weight is well above the edge's breaking load";
  const auto face_force = [&](bool bounded, std::vector<int>* at_bound) {
    SheetBench b(bounded);
    btRigidBody* block = b.bench->box({0.1, h / 2, 0.1}, at(-0.1 + 1e-4, -h / 2, 0.0), mass, 1.0, kIce);
    block->setUserIndex2(0);
    block->applyCentralForce(btVector3(push, 0, 0));
    b.bench->world().stepSimulation(kDt, 1, kDt);
    double vertical = 0;  // N, the block's points' vertical force on the sheet (normal and friction)
    for (const btManifoldPoint* p : b.points_of(block)) vertical += std::abs(contact_impulse(*p).y()) / kDt;
    if (at_bound) *at_bound = b.bound.floes_at_bound();
    return vertical;
  };
  EXPECT_NEAR(face_force(false, nullptr), mass * kGravity, 1e-6 * mass * kGravity) << "friction holds the block";
  std::vector<int> at_bound;
  EXPECT_NEAR(face_force(true, &at_bound), load, 2e-2 * load) << "the face's friction at the edge's breaking load";
  EXPECT_EQ(at_bound, std::vector<int>{0});
}

// A floe is at its bound where its patch's push is, not where one of its points is (its manifold made by hand, the
// solve's answer set on it; the sum is the impulses' vertical part with their signs, as the load read after the step
// sums it). A piece at the edge pressing it down at one point and lifting it at another has its first point at that
// point's own cap (h P, the whole on its normal), but the edge bears the difference: lifted by 0.7 of it, the patch
// bears 0.3 h P and did not give way; lifted by nothing, it bears h P and did. A piece pressing down at two points,
// whose caps the passes lowered to their shares, gave way at them though friction leaves the sum 0.5 % below h P
// (the passes leave a held patch's sum within kPatchAtBound of its bound); but where the next solve leaves the other
// point nothing, or a point's cap was lowered to nothing, a point at its lowered cap is not the patch at its bound
TEST(SheetEdgeBound, AFloeIsAtItsBoundWhereItsPatchsPushIs) {
  const double h = kDt;
  btCollisionObject prism, floe;
  floe.setUserIndex2(0);  // floe 0
  SheetEdgeBound bound(paper_ice());
  bound.set_sheet(sheet_outline(), {&prism});
  // body 0 is the sheet; a point's normal on body 1 points toward body 0, the impulse on the sheet along it; the two
  // points on the edge (x = 0), 0.1 m apart; returns h P, the patch's bound
  btPersistentManifold m(&prism, &floe, 0, 0.02, 0.02);
  const auto prepare = [&](double second_normal_y) {
    m.clearManifold();
    for (const auto& [z, normal_y] : {std::pair{-0.05, -1.0}, std::pair{0.05, second_normal_y}}) {
      btManifoldPoint p(btVector3(0, 0, 0), btVector3(0, 0, 0), btVector3(0, normal_y, 0), -1e-4);
      p.m_positionWorldOnA = p.m_positionWorldOnB = btVector3(0.0, 0.0, z);
      m.addManifoldPoint(p);
    }
    btPersistentManifold* manifolds[] = {&m};
    bound.begin_step();
    bound.prepare(manifolds, 1, h);
    const std::optional<double> cap = bound.cap(m.getContactPoint(0));
    EXPECT_TRUE(cap.has_value() && *cap > 0 && *cap < kUnbounded) << "the pressing point has a cap of its own";
    return cap.value_or(0.0);
  };
  const auto lifted_by = [&](double lift) {
    const double bound_impulse = prepare(1.0);  // pressing down at the first point, lifting at the second
    m.getContactPoint(0).m_appliedImpulse = btScalar(bound_impulse);  // at its first cap
    m.getContactPoint(1).m_appliedImpulse = btScalar(lift * bound_impulse);
    return bound.floes_at_bound();
  };
  EXPECT_TRUE(lifted_by(0.7).empty()) << "the patch at 0.3 of its bound";
  EXPECT_EQ(lifted_by(0.0), std::vector<int>{0}) << "the patch at its bound";

  const double bound_impulse = prepare(-1.0);  // pressing down at both
  std::vector<BoundedImpulse> answer;
  for (int k = 0; k < 2; ++k)
    answer.push_back({&m.getContactPoint(k), bound_impulse, btVector3(0, btScalar(-bound_impulse), 0)});
  ASSERT_TRUE(bound.tighten(answer)) << "the patch at twice its bound: each point's cap lowered to its share";
  for (int k = 0; k < 2; ++k) {
    btManifoldPoint& p = m.getContactPoint(k);
    p.m_appliedImpulse = btScalar(*bound.cap(p));
    EXPECT_NEAR(p.m_appliedImpulse, bound_impulse / 2, 1e-9 * bound_impulse) << "its share";
  }
  m.getContactPoint(1).m_lateralFrictionDir1 = btVector3(0, 1, 0);  // friction lifting it by 0.5 % of h P
  m.getContactPoint(1).m_appliedImpulseLateral1 = btScalar(0.005 * bound_impulse);
  EXPECT_EQ(bound.floes_at_bound(), std::vector<int>{0}) << "held at its bound by the passes";
  // the next solve left the second point nothing: the first at its lowered cap, the patch at half its bound
  m.getContactPoint(1).m_appliedImpulseLateral1 = 0;
  m.getContactPoint(1).m_appliedImpulse = 0;
  EXPECT_TRUE(bound.floes_at_bound().empty()) << "one point at its lowered cap, the patch at half its bound";

  // a point whose normal impulse was none at the pass has its cap lowered to nothing, and no impulse meets it: the
  // patch bears what its other point does (a floe on the edge's face broke the sheet at 0.003 of its load so)
  prepare(-1.0);
  answer = {{&m.getContactPoint(0), 2 * bound_impulse, btVector3(0, btScalar(-2 * bound_impulse), 0)},
            {&m.getContactPoint(1), 0.0, btVector3(0, 0, 0)}};
  ASSERT_TRUE(bound.tighten(answer)) << "the patch at twice its bound";
  ASSERT_EQ(*bound.cap(m.getContactPoint(1)), 0.0) << "the second point's share: nothing";
  m.getContactPoint(0).m_appliedImpulse = btScalar(0.003 * bound_impulse);
  m.getContactPoint(1).m_appliedImpulse = 0;
  EXPECT_TRUE(bound.floes_at_bound().empty()) << "a point at a cap of nothing, the patch at 0.003 of its bound";
}

// A contact method that cannot take the bound is refused at the key, naming those that can
TEST(SheetEdgeBound, AMethodThatCannotBoundTheEdgeIsRefused) {
  for (const char* method : {"pgs", "ipm"}) {
    try {
      scene_from("", {"ice.cover=\"level\"", "fracture.mode=\"analytic\"", "channel.start_x=1.0", "channel.length=3.0",
                      "channel.width=1.2", "structure.start_x=0.3", std::string("solver.method=\"") + method + "\""});
      ADD_FAILURE() << method << ": accepted";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("solver.method"), std::string::npos) << msg;
      EXPECT_NE(msg.find("apgd"), std::string::npos) << msg;
    }
  }
}
