// Hydrostatics of convex bodies: exact volumes and centroids against closed forms, symmetry
// and an independent column integration; equilibrium draft and righting moment of a floe
// against docs/model/validation_targets.md §1.
#include "dem/core/constants.hpp"
#include "dem/water/hydrostatics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dem/core/errors.hpp"

namespace icedem {
namespace {

// the NMRI small floe (docs/model/validation_targets.md §1)
constexpr double kL = 0.3;        // m, side
constexpr double kH = 0.033;      // m, thickness
constexpr double kRhoIce = 930.0; // kg/m^3
constexpr double kRhoW = 1000.0;  // kg/m^3

std::vector<Eigen::Vector2d> rectangle(double lx, double lz) {
  return {{-lx / 2, -lz / 2}, {lx / 2, -lz / 2}, {lx / 2, lz / 2}, {-lx / 2, lz / 2}};
}

std::vector<Eigen::Vector2d> regular_polygon(int n, double radius) {
  std::vector<Eigen::Vector2d> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    p.emplace_back(radius * std::cos(t), radius * std::sin(t));
  }
  return p;
}

Eigen::Isometry3d pose_of(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = translation;
  return pose;
}

Eigen::Matrix3d random_rotation(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
}

TEST(Hydrostatics, PrismFacesPointOutwardForBothOutlineOrientations) {
  for (bool reversed : {false, true}) {
    std::vector<Eigen::Vector2d> outline = regular_polygon(6, 0.2);
    if (reversed) std::reverse(outline.begin(), outline.end());
    const ConvexPolyhedron body = make_prism(outline, kH);
    ASSERT_EQ(body.faces.size(), 8u);
    for (std::size_t f = 0; f < body.faces.size(); ++f) {
      // newell normal of the listed order, and the face centre seen from the body centre
      Eigen::Vector3d n = Eigen::Vector3d::Zero(), c = Eigen::Vector3d::Zero();
      const auto& face = body.faces[f];
      for (std::size_t i = 0; i < face.size(); ++i) {
        n += body.vertices[face[i]].cross(body.vertices[face[(i + 1) % face.size()]]);
        c += body.vertices[face[i]];
      }
      EXPECT_GT(n.dot(c / face.size()), 0.0) << "face " << f << (reversed ? " (reversed)" : "");
    }
    // faces 0 and 1 are bottom and top (documented order)
    EXPECT_LT(body.vertices[body.faces[0][0]].y(), 0.0);
    EXPECT_GT(body.vertices[body.faces[1][0]].y(), 0.0);
  }
}

TEST(Hydrostatics, PrismVolumeIsOutlineAreaTimesThickness) {
  // regular hexagon of circumradius R: area 3 sqrt(3)/2 R^2
  const double radius = 0.2;
  const ConvexPolyhedron body = make_prism(regular_polygon(6, radius), kH);
  const double exact = 1.5 * std::sqrt(3.0) * radius * radius * kH;
  // floating-point round-off only
  EXPECT_NEAR(body_volume(body), exact, 1e-13 * exact);
}

TEST(Hydrostatics, MakePrismRejectsBadOutlines) {
  EXPECT_THROW(make_prism({{0, 0}, {1, 0}}, kH), InputError);
  EXPECT_THROW(make_prism(rectangle(1, 1), 0.0), InputError);
  // a dart (non-convex quadrilateral)
  EXPECT_THROW(make_prism({{0, 0}, {1, -1}, {0.2, 0}, {1, 1}}, kH), InputError);
  EXPECT_THROW(make_prism({{0, 0}, {1, 0}, {2, 0}}, kH), InputError);  // no area
  try {
    make_prism({{0, 0}, {1, -1}, {0.2, 0}, {1, 1}}, kH);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("convex"), std::string::npos) << e.what();
  }
}

TEST(Hydrostatics, FullySubmergedBodyDisplacesItsWholeVolume) {
  const ConvexPolyhedron body = make_prism(rectangle(kL, kL), kH);
  std::mt19937 rng(7);
  const Eigen::Vector3d com(12.3, -1.0, -0.7);
  const Submersion s = submerge(body, pose_of(random_rotation(rng), com), 0.0);
  const double exact = kL * kL * kH;
  // floating-point round-off only
  EXPECT_NEAR(s.volume, exact, 1e-12 * exact);
  EXPECT_NEAR((s.centroid - com).norm(), 0.0, 1e-12);
  EXPECT_EQ(s.faces.size(), 6u);
  double area = 0.0;
  for (const WettedFace& f : s.faces) area += f.area;
  EXPECT_NEAR(area, 2 * kL * kL + 4 * kL * kH, 1e-12);
}

TEST(Hydrostatics, DryBodyDisplacesNothing) {
  const ConvexPolyhedron body = make_prism(rectangle(kL, kL), kH);
  const Submersion s = submerge(body, pose_of(Eigen::Matrix3d::Identity(), {0, 0.5, 0}), 0.0);
  EXPECT_EQ(s.volume, 0.0);
  EXPECT_TRUE(s.faces.empty());
}

TEST(Hydrostatics, CubeOnEdgeHalfSubmergedThroughItsCentreHasHalfVolume) {
  // cube of side a rotated 45 degrees about x: its (y, z) section is a diamond, the lower
  // half a triangle with apex at y = -a/sqrt(2), so the centroid is at y = -a/(3 sqrt(2))
  const double a = 0.4;
  const ConvexPolyhedron cube = make_prism(rectangle(a, a), a);
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(kPi / 4, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Submersion s = submerge(cube, pose_of(rot, {1.0, 0.0, 2.0}), 0.0);
  // round-off of the rotation (cos and sin of pi/4 differ by one ulp)
  EXPECT_NEAR(s.volume, 0.5 * a * a * a, 1e-14);
  EXPECT_NEAR(s.centroid.x(), 1.0, 1e-14);
  EXPECT_NEAR(s.centroid.y(), -a / (3 * std::sqrt(2.0)), 1e-14);
  EXPECT_NEAR(s.centroid.z(), 2.0, 1e-14);
  // wetted: two full faces, two faces cut in half (the ends are half-diamonds: area a^2/2)
  double area = 0.0;
  for (const WettedFace& f : s.faces) area += f.area;
  EXPECT_NEAR(area, 2 * a * a + 2 * 0.5 * a * a, 1e-14);
}

TEST(Hydrostatics, VerticesExactlyOnTheWaterPlaneAreHandled) {
  const double a = 0.4;
  const ConvexPolyhedron cube = make_prism(rectangle(a, a), a);
  // an exactly symmetric 45-degree rotation: the four middle vertices land on y = 0 exactly
  const double c = std::sqrt(0.5);
  Eigen::Matrix3d rot;
  rot << 1, 0, 0, 0, c, -c, 0, c, c;
  const Eigen::Isometry3d pose = pose_of(rot, Eigen::Vector3d::Zero());
  double y_min = 1, y_max = -1;
  for (const auto& v : cube.vertices) {
    y_min = std::min(y_min, (pose * v).y());
    y_max = std::max(y_max, (pose * v).y());
  }
  // through four vertices: half
  EXPECT_NEAR(submerge(cube, pose, 0.0).volume, 0.5 * a * a * a, 1e-15);  // round-off
  // touching the lowest edge only: nothing
  const Submersion touch = submerge(cube, pose, y_min);
  EXPECT_EQ(touch.volume, 0.0);
  EXPECT_TRUE(touch.faces.empty());
  // up to the highest edge: everything
  EXPECT_NEAR(submerge(cube, pose, y_max).volume, a * a * a, 1e-15);  // round-off

  // upright cube with a face lying in the plane: that face is not wetted
  const Eigen::Isometry3d upright = Eigen::Isometry3d::Identity();
  const Submersion on_bottom = submerge(cube, upright, -a / 2);
  EXPECT_EQ(on_bottom.volume, 0.0);
  EXPECT_TRUE(on_bottom.faces.empty());
  const Submersion to_top = submerge(cube, upright, a / 2);
  EXPECT_NEAR(to_top.volume, a * a * a, 1e-15);  // round-off
  EXPECT_EQ(to_top.faces.size(), 5u);
}

TEST(Hydrostatics, WettedFacesOfAFloatingFloeAreItsBottomAndSubmergedEdges) {
  const ConvexPolyhedron floe = make_prism(rectangle(kL, kL), kH);
  const double draft = 0.025;
  const Submersion s = submerge(floe, pose_of(Eigen::Matrix3d::Identity(), {3, kH / 2 - draft, 1}), 0.0);
  ASSERT_EQ(s.faces.size(), 5u);
  for (const WettedFace& f : s.faces) {
    if (f.normal.y() < -0.5) {
      EXPECT_NEAR(f.area, kL * kL, 1e-15);          // round-off
      EXPECT_NEAR(f.centroid.y(), -draft, 1e-15);
    } else {
      EXPECT_NEAR(f.area, kL * draft, 1e-15);       // round-off
      EXPECT_NEAR(f.centroid.y(), -draft / 2, 1e-15);
      // the edge centroid sits half a side from the floe centre, along the normal
      EXPECT_NEAR((f.centroid - Eigen::Vector3d(3, -draft / 2, 1) - kL / 2 * f.normal).norm(), 0.0, 1e-15);
    }
  }
}

TEST(Hydrostatics, PressureOnWettedFacesSumsToArchimedesForce) {
  // hydrostatic pressure is linear in depth, so the force on a plane face is exactly
  // p(centroid) A n; summed over the wetted faces it must equal rho g V up (Archimedes).
  // This checks the faces' areas and centroids independently of the volume computation.
  const ConvexPolyhedron body = make_prism(regular_polygon(7, 0.25), 0.1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> level(-0.1, 0.1);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Isometry3d pose = pose_of(random_rotation(rng), {0.3, level(rng), -0.2});
    const Submersion s = submerge(body, pose, 0.0);
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  // per unit rho g
    for (const WettedFace& f : s.faces) force += f.centroid.y() * f.area * f.normal;
    // round-off relative to the body's volume (6e-3 m^3)
    EXPECT_NEAR(force.x(), 0.0, 1e-15) << "trial " << trial;
    EXPECT_NEAR(force.y(), s.volume, 1e-15) << "trial " << trial;
    EXPECT_NEAR(force.z(), 0.0, 1e-15) << "trial " << trial;
  }
}

TEST(Hydrostatics, TiltedBoxVolumeAndCentroidMatchColumnIntegration) {
  // independent reference: integrate along body-y columns on a fine (x, z) grid; the
  // submerged length of each column is exact (linear in y), the grid sum is the midpoint rule
  const double lx = 0.5, h = 0.2, lz = 0.3;
  const ConvexPolyhedron box = make_prism(rectangle(lx, lz), h);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> level(-0.15, 0.15);
  const int n = 400;
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::Matrix3d rot = random_rotation(rng);
    const Eigen::Isometry3d pose = pose_of(rot, {0.0, level(rng), 0.0});
    const Submersion s = submerge(box, pose, 0.0);

    double volume = 0.0;
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    const double dx = lx / n, dz = lz / n;
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        const double x = -lx / 2 + (i + 0.5) * dx, z = -lz / 2 + (j + 0.5) * dz;
        // world height along the column: y0 + k s, s in [-h/2, h/2]
        const double y0 = (pose * Eigen::Vector3d(x, 0, z)).y();
        const double k = rot(1, 1);
        double lo = -h / 2, hi = h / 2;
        if (k > 0) hi = std::min(hi, -y0 / k);
        if (k < 0) lo = std::max(lo, -y0 / k);
        if (k == 0 && y0 >= 0) hi = lo;
        if (hi <= lo) continue;
        volume += (hi - lo) * dx * dz;
        moment += (hi - lo) * dx * dz * (pose * Eigen::Vector3d(x, 0.5 * (lo + hi), z));
      }
    }
    // midpoint rule on a continuous, piecewise-linear column length: O(1/n^2) error (it
    // drops 4x from n = 200 to 400), observed at n = 400 up to 2e-8 m^3 (7e-7 of the box
    // volume) and 4e-7 m; the bounds below are 5x those
    EXPECT_NEAR(s.volume, volume, 1e-7) << "trial " << trial;
    if (volume > 1e-4) {
      EXPECT_NEAR((s.centroid - moment / volume).norm(), 0.0, 2e-6) << "trial " << trial;
    }
  }
}

TEST(Hydrostatics, FloeFloatsAtDraftOfDensityRatioTimesThickness) {
  // docs/model/validation_targets.md §1: d = rho_i h / rho_w = 30.69 mm
  const ConvexPolyhedron floe = make_prism(rectangle(kL, kL), kH);
  const double level = equilibrium_water_level(floe, kRhoIce * kL * kL * kH / kRhoW);
  const double draft = level + kH / 2;
  // bisection to 1e-12 of the height
  EXPECT_NEAR(draft, kRhoIce / kRhoW * kH, 1e-12);
  EXPECT_NEAR(draft, 0.03069, 0.005e-3);  // the sheet's rounded value, to its last digit
}

TEST(Hydrostatics, WaterplaneOfAFloatingRectangleHasItsAreaAndSecondMoments) {
  const double lx = 0.3, lz = 0.15;
  const ConvexPolyhedron floe = make_prism(rectangle(lx, lz), kH);
  // rotate about y by 30 degrees: principal values do not change
  const Eigen::Matrix3d yaw = Eigen::AngleAxisd(kPi / 6, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const WaterplaneSection wp = waterplane_section(floe, pose_of(yaw, {2.0, 0.01, -1.0}), 0.0);
  // round-off
  EXPECT_NEAR(wp.area, lx * lz, 1e-15);
  EXPECT_NEAR(wp.centroid.x(), 2.0, 1e-14);
  EXPECT_NEAR(wp.centroid.y(), -1.0, 1e-14);
  EXPECT_NEAR(wp.second_moment_min, lx * lz * lz * lz / 12, 1e-16);
  EXPECT_NEAR(wp.second_moment_max, lz * lx * lx * lx / 12, 1e-16);
  // plane missing the body
  EXPECT_EQ(waterplane_section(floe, pose_of(yaw, {0, 1, 0}), 0.0).area, 0.0);
}

TEST(Hydrostatics, HeeledFloeRightingMomentIsRhoGVGMSinPhi) {
  // docs/model/validation_targets.md §1: GM = L^2/(12 d) + d/2 - h/2 = 0.243 m for the 0.3 m floe
  const ConvexPolyhedron floe = make_prism(rectangle(kL, kL), kH);
  const double d = kRhoIce / kRhoW * kH;
  const double gm = kL * kL / (12 * d) + d / 2 - kH / 2;
  ASSERT_NEAR(gm, 0.243, 0.0005);  // the sheet's rounded value
  const double volume = kL * kL * d;
  const double g = 9.81;
  for (double phi_deg : {0.5, -0.5}) {
    // heel about the x axis through the waterplane centre: a wall-sided floe keeps its
    // displacement while no edge emerges (tan(phi) L/2 < freeboard 2.31 mm for |phi| < 0.88 deg)
    const double phi = phi_deg * kPi / 180;
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitX()).toRotationMatrix();
    const Eigen::Vector3d com = rot * Eigen::Vector3d(0, kH / 2 - d, 0);
    const Submersion s = submerge(floe, pose_of(rot, com), 0.0);
    EXPECT_NEAR(s.volume, volume, 1e-12 * volume);  // round-off: displacement unchanged
    const Eigen::Vector3d buoyancy(0, kRhoW * g * s.volume, 0);
    const Eigen::Vector3d torque = (s.centroid - com).cross(buoyancy);
    const double expected = -kRhoW * g * volume * gm * std::sin(phi);  // restoring: opposes phi
    // the small-angle formula omits the wall-sided term BM tan^2(phi) / 2 (4e-5 relative at
    // 0.5 deg); 1e-3 allows for it
    EXPECT_NEAR(torque.x(), expected, 1e-3 * std::abs(expected)) << "phi " << phi_deg;
    // the wall-sided formula GZ = sin(phi) (GM + BM tan^2(phi) / 2) is exact for a box whose
    // edges stay wet and dry: round-off only
    const double bm = kL * kL / (12 * d);
    const double wall_sided = expected * (1 + bm * std::pow(std::tan(phi), 2) / (2 * gm));
    EXPECT_NEAR(torque.x(), wall_sided, 1e-9 * std::abs(expected)) << "phi " << phi_deg;
    EXPECT_NEAR(torque.y(), 0.0, 1e-12);
    EXPECT_NEAR(torque.z(), 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace icedem
