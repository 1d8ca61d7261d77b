// The nominal contact areas of dem/contact/contact_area.hpp computed by Boost.Geometry: the
// reference the unit tests compare icedem's own to, and the baseline of its benchmark
// (bench/micro/contact_area.cpp).
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

// Boost.Geometry's rescaling policy reads a factor GCC 12 cannot prove set (a false alarm), and
// Boost 1.74's geometry includes a header of its own it calls deprecated (a note in every build)
#ifndef BOOST_ALLOW_DEPRECATED_HEADERS
#define BOOST_ALLOW_DEPRECATED_HEADERS
#endif
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_point.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#pragma GCC diagnostic pop

#include "dem/contact/contact_area.hpp"

namespace icedem::testing {

namespace bg = boost::geometry;
using BoostPoint = bg::model::d2::point_xy<double>;
using BoostPolygon = bg::model::polygon<BoostPoint>;

inline BoostPolygon boost_section(const std::vector<Eigen::Vector3d>& vertices, const Plane& plane) {
  const Eigen::Vector3d seed = std::abs(plane.normal.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = plane.normal.cross(seed).normalized(), e2 = plane.normal.cross(e1);
  std::vector<double> side(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) side[i] = plane.normal.dot(vertices[i] - plane.point);
  bg::model::multi_point<BoostPoint> crossings;
  auto add = [&](const Eigen::Vector3d& x) { bg::append(crossings, BoostPoint(e1.dot(x - plane.point), e2.dot(x - plane.point))); };
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (side[i] == 0.0) add(vertices[i]);
    for (std::size_t j = i + 1; j < vertices.size(); ++j)
      if ((side[i] < 0.0 && side[j] > 0.0) || (side[i] > 0.0 && side[j] < 0.0))
        add(vertices[i] + (vertices[j] - vertices[i]) * (side[i] / (side[i] - side[j])));
  }
  BoostPolygon hull;
  if (crossings.size() >= 3) bg::convex_hull(crossings, hull);
  return hull;
}

inline double boost_section_area(const std::vector<Eigen::Vector3d>& vertices, const Plane& plane) {
  return std::abs(bg::area(boost_section(vertices, plane)));
}

inline double boost_common_section_area(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                                        const Plane& plane) {
  const BoostPolygon sa = boost_section(a, plane), sb = boost_section(b, plane);
  if (sa.outer().size() < 3 || sb.outer().size() < 3) return 0.0;
  std::vector<BoostPolygon> common;
  bg::intersection(sa, sb, common);
  double area = 0.0;
  for (const BoostPolygon& p : common) area += std::abs(bg::area(p));
  return area;
}

}  // namespace icedem::testing
