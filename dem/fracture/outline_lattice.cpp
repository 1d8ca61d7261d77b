#include "dem/fracture/outline_lattice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

namespace icedem {
namespace {

// the smallest part that is an element of its own when it cannot join a neighbour, as a
// share of a cell: a hexagonal lattice of a photo's floe cut parts down to 0.1 % of a cell
// (a fraction of a gram beside hexagons of 9 g), and a run of such floes blew up on one of
// them spinning at 1300 rad/s; below this a part is dropped (at most about 1 % of a floe's
// area on the photo's floes, reported as dropped_area)
constexpr double kLeast = 0.05;

// the grid of anchors Tiling::kFitted tries besides the aligned ones, along each axis of the
// tiling's period (anchor_shifts)
constexpr int kShifts = 8;

// a cell of the tiling: its convex outline (ccw) and centre
struct Cell {
  Polygon outline;
  Eigen::Vector2d centre;
};

// the hexagon of the tiling centred at c: neighbouring centres w apart, flat faces towards
// +-z (vertices at 0, 60, ..., 300 degrees from +x, circumradius w / sqrt(3))
Polygon hexagon(const Eigen::Vector2d& c, double w) {
  const double R = w / std::sqrt(3.0);
  Polygon h;
  for (int k = 0; k < 6; ++k) {
    const double a = k * M_PI / 3.0;
    h.emplace_back(c.x() + R * std::cos(a), c.y() + R * std::sin(a));
  }
  return make_ccw(h);
}

// the cells covering the box [lo, hi], anchored at lo
std::vector<Cell> cells_over(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double w, ElementShape shape) {
  std::vector<Cell> cells;
  if (shape == ElementShape::kSquare) {
    const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / w - 1e-9));
    const int nz = static_cast<int>(std::ceil((hi.y() - lo.y()) / w - 1e-9));
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < nz; ++j) {
        const Eigen::Vector2d c = lo + Eigen::Vector2d((i + 0.5) * w, (j + 0.5) * w);
        Polygon s = square(w);
        for (Eigen::Vector2d& v : s) v += c;
        cells.push_back({s, c});
      }
    return cells;
  }
  // hexagons in columns 1.5 R apart along x, w apart along z, every other column shifted
  // by w / 2; the first column's centres on the box's lower corner
  const double R = w / std::sqrt(3.0), dx = 1.5 * R;
  const int nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / dx)) + 1;
  const int nz = static_cast<int>(std::ceil((hi.y() - lo.y()) / w)) + 2;
  for (int i = 0; i < nx; ++i)
    for (int j = -1; j < nz; ++j) {
      const Eigen::Vector2d c = lo + Eigen::Vector2d(i * dx, j * w + (i % 2 ? 0.5 * w : 0.0));
      cells.push_back({hexagon(c, w), c});
    }
  return cells;
}

// the part of `subject` inside the convex, ccw `cell` (Sutherland-Hodgman: the subject may be
// concave; a cell holding two parts of it gets one polygon with a bridge of no area between)
Polygon clip(Polygon subject, const Polygon& cell) {
  for (std::size_t i = 0; i < cell.size() && subject.size() >= 3; ++i) {
    const Eigen::Vector2d& a = cell[i];
    const Eigen::Vector2d& b = cell[(i + 1) % cell.size()];
    // outward normal of a ccw edge (seen from above, +y: ccw turns +x towards -z)
    const Eigen::Vector2d edge = b - a;
    const Eigen::Vector2d outward(-edge.y(), edge.x());
    subject = cut(subject, a, outward).behind;
  }
  return subject;
}

// the polygon without consecutive vertices closer than eps (the clipping repeats a vertex that
// lies on a cell's edge, and a body's outline must not)
Polygon without_repeats(const Polygon& p, double eps) {
  Polygon out;
  for (const Eigen::Vector2d& v : p)
    if (out.empty() || (v - out.back()).norm() > eps) out.push_back(v);
  while (out.size() > 1 && (out.front() - out.back()).norm() <= eps) out.pop_back();
  return out;
}

// the interval (along the unit `dir` from `a`) that `part`'s boundary covers on the line
// through a: the extent of its vertices within eps of the line (empty: lo > hi)
std::pair<double, double> on_line(const Polygon& part, const Eigen::Vector2d& a, const Eigen::Vector2d& dir,
                                  double eps) {
  const Eigen::Vector2d normal(-dir.y(), dir.x());
  double lo = 1e300, hi = -1e300;
  for (const Eigen::Vector2d& v : part)
    if (std::abs((v - a).dot(normal)) <= eps) {
      const double s = (v - a).dot(dir);
      lo = std::min(lo, s), hi = std::max(hi, s);
    }
  return {lo, hi};
}

// the moments of two parts together (areas add; second moments moved to the common centroid)
CentroidalMoments combined(const CentroidalMoments& p, const CentroidalMoments& q) {
  CentroidalMoments m;
  m.area = p.area + q.area;
  m.centroid = (p.area * p.centroid + q.area * q.centroid) / m.area;
  for (const CentroidalMoments* s : {&p, &q}) {
    const Eigen::Vector2d d = s->centroid - m.centroid;
    m.ixx += s->ixx + s->area * d.x() * d.x();
    m.izz += s->izz + s->area * d.y() * d.y();
    m.ixz += s->ixz + s->area * d.x() * d.y();
  }
  return m;
}

}  // namespace

const char* element_shape_name(ElementShape shape) { return shape == ElementShape::kSquare ? "square" : "hexagon"; }

double cell_area(double element_size, ElementShape shape) {
  return (shape == ElementShape::kSquare ? 1.0 : std::sqrt(3.0) / 2.0) * element_size * element_size;
}

namespace {

// The cells over the outline's box from an anchor `shift` below its lower corner, and each
// cell's part of the outline (parts[k] in cells[part_cell[k]]).
struct Cut {
  std::vector<Cell> cells;
  std::vector<Polygon> parts;
  std::vector<int> part_cell;
};
Cut cut_outline(const Polygon& outline, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi,
                const Eigen::Vector2d& shift, double w, ElementShape shape, double eps) {
  Cut c;
  c.cells = cells_over(lo - shift, hi, w, shape);
  for (std::size_t k = 0; k < c.cells.size(); ++k) {
    Polygon part = without_repeats(clip(outline, c.cells[k].outline), eps);
    if (part.size() >= 3 && area(part) > eps * eps) c.parts.push_back(std::move(part)), c.part_cell.push_back(int(k));
  }
  return c;
}

// The anchors Tiling::kFitted tries, as shifts of the tiling below the box's lower corner `lo`,
// within one period of the tiling (squares: w by w; hexagons: 1.5 R by w, since a shift of
// (1.5 R, w / 2) gives the same tiling): those that put the box's sides on a cell's centre line
// or on a line through its vertices (a side there cuts cells into halves or leaves them whole),
// and a grid of kShifts x kShifts. The aligned ones found the best of a 24 x 12 grid on the
// paper's 0.6 m floes, which a grid of 8 x 8 alone missed (the best cut is a sharp optimum).
// Each anchor once, the corner (no shift) left out, since each is a cut of the whole outline: the
// sides of a box a whole number of cells across give the same anchors, and the grid holds the
// corner and some aligned ones.
std::vector<Eigen::Vector2d> anchor_shifts(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, double w,
                                           ElementShape shape) {
  const double R = w / std::sqrt(3.0);
  const Eigen::Vector2d period(shape == ElementShape::kSquare ? w : 1.5 * R, w);
  auto wrap = [](double s, double p) { return s - p * std::floor(s / p); };
  // a cell's lines across x and across z, from its centre
  const std::vector<double> across_x =
      shape == ElementShape::kSquare ? std::vector<double>{0.0, 0.5 * w} : std::vector<double>{0.0, 0.5 * R, -0.5 * R, R, -R};
  const std::vector<double> across_z = {0.0, 0.5 * w};
  std::vector<double> xs, zs;
  for (double side : {lo.x(), hi.x()})
    for (double k : across_x) xs.push_back(wrap(lo.x() - side + k, period.x()));
  for (double side : {lo.y(), hi.y()})
    for (double k : across_z) zs.push_back(wrap(lo.y() - side + k, period.y()));
  std::vector<Eigen::Vector2d> shifts;
  auto add = [&](const Eigen::Vector2d& shift) {
    // exactly the same only: a shift off by round-off cuts the same parts to round-off, and
    // where two mirror cuts tie, that round-off picks one of them
    if (shift == Eigen::Vector2d::Zero() || std::find(shifts.begin(), shifts.end(), shift) != shifts.end()) return;
    shifts.push_back(shift);
  };
  for (double x : xs)
    for (double z : zs) add({x, z});
  for (int i = 0; i < kShifts; ++i)
    for (int j = 0; j < kShifts; ++j) add({period.x() * i / kShifts, period.y() * j / kShifts});
  return shifts;
}

// How badly a cut cuts, to be made least in the order given: the parts below min_fraction of a
// cell (those a hexagon cannot take in), the parts below half a cell, and the smallest part's
// share, negated. A small part has the capacities of its short faces while the contacts on it
// are any element's, and its joints broke 1.8-3.5 times as often as whole hexagons' in the
// paper's floes (docs/model/breakage.md, "The cut elements break more often").
std::array<double, 3> badness(const Cut& c, double cell, double min_fraction) {
  std::array<double, 3> b = {0.0, 0.0, 0.0};
  double smallest = 1.0;
  for (const Polygon& p : c.parts) {
    const double share = area(p) / cell;
    b[0] += share < min_fraction;
    b[1] += share < 0.5;
    smallest = std::min(smallest, share);
  }
  b[2] = -smallest;
  return b;
}

}  // namespace

OutlineLattice fill_outline(const Polygon& outline_in, double element_size, ElementShape shape, Tiling tiling,
                            double min_fraction) {
  if (!(element_size > 0)) throw std::invalid_argument("fill_outline: the element size must be positive");
  if (outline_in.size() < 3 || !(area(outline_in) > 0))
    throw std::invalid_argument("fill_outline: the outline has no area");
  const Polygon outline = make_ccw(outline_in);
  Eigen::Vector2d lo = outline[0], hi = outline[0];
  for (const Eigen::Vector2d& v : outline) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double w = element_size, eps = 1e-9 * std::max(w, (hi - lo).maxCoeff());

  // each cell's part of the outline: the tiling anchored at the box's lower corner, or, fitted,
  // shifted by the one of anchor_shifts' anchors that cuts least (badness); the corner is tried
  // first and ties keep the earlier, so a rectangle of whole elements keeps the corner
  Cut cut = cut_outline(outline, lo, hi, Eigen::Vector2d::Zero(), w, shape, eps);
  if (tiling == Tiling::kFitted) {
    const double cell = cell_area(w, shape);
    std::array<double, 3> best = badness(cut, cell, min_fraction);
    for (const Eigen::Vector2d& shift : anchor_shifts(lo, hi, w, shape)) {
      Cut other = cut_outline(outline, lo, hi, shift, w, shape, eps);
      const std::array<double, 3> b = badness(other, cell, min_fraction);
      if (b < best) best = b, cut = std::move(other);
    }
  }
  const std::vector<Cell>& cells = cut.cells;
  const std::vector<int>& part_cell = cut.part_cell;  // the cell of each part
  std::vector<Polygon>& parts = cut.parts;

  // the faces two parts share on their cells' common edge
  struct Face {
    int a, b;
    Eigen::Vector2d midpoint, axis;
    double length;
  };
  std::vector<Face> faces;
  const double reach = 1.01 * w;  // neighbouring centres are w apart (squares: the diagonal, sqrt(2) w, is not)
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (std::size_t q = p + 1; q < parts.size(); ++q) {
      const Cell& A = cells[part_cell[p]];
      const Cell& B = cells[part_cell[q]];
      if ((B.centre - A.centre).norm() > reach) continue;
      // the common edge: A's edge through the centres' midpoint
      const Eigen::Vector2d mid = 0.5 * (A.centre + B.centre);
      for (std::size_t e = 0; e < A.outline.size(); ++e) {
        const Eigen::Vector2d& a = A.outline[e];
        const Eigen::Vector2d& b = A.outline[(e + 1) % A.outline.size()];
        if (((a + b) / 2 - mid).norm() > 1e-6 * w) continue;
        const double len = (b - a).norm();
        const Eigen::Vector2d dir = (b - a) / len;
        const auto [lp, hp] = on_line(parts[p], a, dir, eps);
        const auto [lq, hq] = on_line(parts[q], a, dir, eps);
        const double from = std::max({lp, lq, 0.0}), to = std::min({hp, hq, len});
        if (to - from > eps)
          faces.push_back({int(p), int(q), a + dir * (0.5 * (from + to)), (B.centre - A.centre).normalized(), to - from});
      }
    }

  // parts below min_fraction of a cell go into a neighbour they share a face with
  const double small = min_fraction * cell_area(w, shape);
  std::vector<int> host(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p) host[p] = int(p);
  std::vector<CentroidalMoments> moments(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p) moments[p] = centroidal_moments(parts[p]);
  OutlineLattice lattice;
  std::vector<char> dropped(parts.size(), 0);
  // a small part joins a neighbour only where the two make a convex body (a body is a convex
  // prism, whose mass and buoyancy are its hull's): a square's sliver along a straight edge
  // continues its neighbour's rectangle, but a hexagon with a sliver of the next cell is not
  // convex, and its hull's mass was up to a fifth more than its ice (measured on a photo's floe
  // of 0.15 m hexagons: 3.6 % of the floe's mass in all). Such a part stays an element of its
  // own, joined by its short faces, whose capacities are as small as its faces. Convexity is
  // judged against all a host holds so far (two slivers on two sides of a corner square
  // would leave the corner out)
  std::vector<std::vector<Eigen::Vector2d>> held(parts.size());
  std::vector<double> held_area(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p)
    held[p].assign(parts[p].begin(), parts[p].end()), held_area[p] = moments[p].area;
  auto convex_union = [&](int p, int q) {
    std::vector<Eigen::Vector2d> both(held[q]);
    both.insert(both.end(), parts[p].begin(), parts[p].end());
    const double together = held_area[q] + moments[p].area;
    return area(convex_hull(both)) <= together * (1.0 + 1e-9) + eps * eps;
  };
  for (std::size_t p = 0; p < parts.size(); ++p) {
    if (moments[p].area >= small) continue;
    // of the neighbours it makes a convex body with, the one with the longest shared face
    int best = -1;
    double longest = 0;
    bool any_face = false;
    for (const Face& f : faces) {
      const int other = f.a == int(p) ? f.b : f.b == int(p) ? f.a : -1;
      if (other < 0) continue;
      any_face = true;
      if (moments[other].area >= small && f.length > longest && convex_union(int(p), other))
        best = other, longest = f.length;
    }
    if (best >= 0) {
      host[p] = best;
      held[best].insert(held[best].end(), parts[p].begin(), parts[p].end());
      held_area[best] += moments[p].area;
    } else if (!any_face || moments[p].area < kLeast * cell_area(w, shape)) {
      dropped[p] = 1;
      lattice.dropped_area += moments[p].area;
    }
  }

  // the elements: each kept part with the small parts it hosts (their vertices in `held`)
  std::vector<int> element_of(parts.size(), -1);
  for (std::size_t p = 0; p < parts.size(); ++p)
    if (host[p] == int(p) && !dropped[p]) {
      element_of[p] = int(lattice.elements.size());
      lattice.elements.push_back({without_repeats(make_ccw(convex_hull(held[p])), 1e-9 * w), moments[p]});
    }
  for (std::size_t p = 0; p < parts.size(); ++p)
    if (host[p] != int(p)) {
      const int e = element_of[host[p]];
      element_of[p] = e;
      lattice.elements[e].moments = combined(lattice.elements[e].moments, moments[p]);
    }

  // the joints: faces between two elements, those between the same two summed (a merged
  // part's face continues its host's)
  std::map<std::pair<int, int>, OutlineJoint> joints;
  for (const Face& f : faces) {
    int a = element_of[f.a], b = element_of[f.b];
    if (a < 0 || b < 0 || a == b) continue;
    Eigen::Vector2d axis = f.axis;
    if (a > b) std::swap(a, b), axis = -axis;
    auto [it, fresh] = joints.try_emplace({a, b}, OutlineJoint{a, b, f.midpoint, axis, f.length});
    if (!fresh) {
      OutlineJoint& j = it->second;
      const double total = j.face_length + f.length;
      j.midpoint = (j.face_length * j.midpoint + f.length * f.midpoint) / total;
      j.axis = (j.face_length * j.axis + f.length * axis).normalized();
      j.face_length = total;
    }
  }
  for (const auto& [key, j] : joints) lattice.joints.push_back(j);
  return lattice;
}

}  // namespace icedem
