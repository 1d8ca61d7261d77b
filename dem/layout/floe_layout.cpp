// Floe layouts: seeded generation of square floes at a target concentration
// (layout files: layout_file.cpp). Format and conventions: floe_layout.hpp.
#include "dem/layout/floe_layout.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

#include <fmt/format.h>

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "dem/layout/channel_cells.hpp"

namespace icedem {
namespace {

// ---------------------------------------------------------------- random numbers

// std::mt19937_64 is fully specified by the standard; the distributions are
// not (libstdc++ and libc++ differ), so the mappings are written out here
class Rng {
 public:
  explicit Rng(uint64_t seed) : engine_(seed) {}

  // uniform in [0, 1): the top 53 bits of one draw
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  // uniform in [-1, 1)
  double symmetric() { return 2.0 * uniform() - 1.0; }

  // uniform integer in [0, n), unbiased by rejection
  uint64_t below(uint64_t n) {
    assert(n > 0);
    const uint64_t max = std::numeric_limits<uint64_t>::max();
    const uint64_t limit = max - max % n;
    uint64_t r;
    do {
      r = engine_();
    } while (r >= limit);
    return r % n;
  }

 private:
  std::mt19937_64 engine_;
};

// ---------------------------------------------------------------- generation

// a regular grid of nx (along x) by nz (along z) cells of dx by dz metres
struct Grid {
  int nx = 0, nz = 0;
  double dx = 0.0, dz = 0.0;  // m
};

// the grid with at least n cells, each fitting a floe plus the gap, whose cell
// aspect is closest to 1 (ties: fewer cells); nx = 0 if none fits. For a given
// nz the smallest nx = ceil(n / nz) has the largest cells, so these candidates
// (and the same with x and z swapped) contain a fitting grid whenever one exists.
Grid choose_grid(long n, double lx, double lz, double need) {
  Grid best;
  double best_score = std::numeric_limits<double>::infinity();
  auto consider = [&](long nx, long nz) {
    const double dx = lx / static_cast<double>(nx), dz = lz / static_cast<double>(nz);
    if (std::min(dx, dz) < need) return;
    const double score = std::abs(std::log(dx / dz));
    const long cells = nx * nz;
    if (score < best_score - 1e-12 ||
        (score < best_score + 1e-12 && cells < static_cast<long>(best.nx) * best.nz)) {
      best_score = score;
      best = {static_cast<int>(nx), static_cast<int>(nz), dx, dz};
    }
  };
  for (long k = 1; k <= n; ++k) {
    const long other = (n + k - 1) / k;
    consider(other, k);
    consider(k, other);
  }
  return best;
}

// largest yaw (rad, <= pi/4) at which a square of side L spans at most `span`
// along x and along z: L (cos t + sin t) = sqrt(2) L sin(t + pi/4) <= span
double fitting_yaw(double side, double span) {
  const double ratio = span / (std::sqrt(2.0) * side);
  if (ratio >= 1.0) return kPi / 4.0;
  return std::max(0.0, std::asin(ratio) - kPi / 4.0);
}

void check_params(const LayoutParams& p) {
  const std::string ctx = "floe layout";
  check_channel(p.channel, ctx);
  if (!std::isfinite(p.floe_size) || !(p.floe_size > 0.0)) {
    throw InputError(fmt::format("{}: ice.floe_size = {} m: expected a finite size > 0", ctx,
                                 p.floe_size));
  }
  if (!std::isfinite(p.concentration) || p.concentration < 0.0 || p.concentration > 1.0) {
    throw InputError(fmt::format("{}: ice.concentration = {}: expected a fraction in [0, 1]", ctx,
                                 p.concentration));
  }
  if (!std::isfinite(p.max_yaw) || p.max_yaw < 0.0) {
    throw InputError(
        fmt::format("{}: max_yaw = {} rad: expected a finite angle >= 0", ctx, p.max_yaw));
  }
  if (p.sweeps < 0) {
    throw InputError(fmt::format("{}: sweeps = {}: expected a count >= 0", ctx, p.sweeps));
  }
  if (!std::isfinite(p.size_spread) || p.size_spread < 0.0 || p.size_spread >= 1.0) {
    throw InputError(fmt::format("{}: size_spread = {}: expected a fraction in [0, 1)", ctx, p.size_spread));
  }
  if (!std::isfinite(p.min_gap) || p.min_gap < 0.0) {
    throw InputError(
        fmt::format("{}: min_gap = {} m: expected a finite gap >= 0", ctx, p.min_gap));
  }
}

// The sides of a field with a size spread: drawn uniformly from L (1 +- spread) from a stream of
// their own (they do not depend on the arrangement's draws), one by one while the floes' area
// comes nearer `target` by another floe
std::vector<double> spread_sides(const LayoutParams& p, double target) {
  Rng rng(p.seed ^ 0x9e3779b97f4a7c15ULL);
  std::vector<double> sides;
  double area = 0.0;
  for (;;) {
    const double s = p.floe_size * (1.0 + p.size_spread * rng.symmetric());
    if (std::abs(area + s * s - target) >= std::abs(area - target)) return sides;
    sides.push_back(s);
    area += s * s;
  }
}

}  // namespace

Layout generate_square_layout(const LayoutParams& params) {
  check_params(params);
  const Channel& ch = params.channel;
  const double lx = ch.x_max - ch.x_min, lz = ch.z_max - ch.z_min;
  // the largest side: every floe must fit across the channel (and in a cell of the grid below)
  const double side = params.floe_size * (1.0 + params.size_spread), gap = params.min_gap;
  const std::string ctx = "floe layout";

  Layout layout;
  layout.channel_area = channel_area(ch);
  // the floes' size in messages; with a spread, the largest side is what has to fit
  const std::string size =
      params.size_spread > 0.0
          ? fmt::format("ice.floe_size = {} m with layout.size_spread = {} (largest side {} m)", params.floe_size,
                        params.size_spread, side)
          : fmt::format("ice.floe_size = {} m", side);

  // the floe itself must fit across the channel
  if (side + gap > std::min(lx, lz)) {
    throw InputError(fmt::format(
        "{}: {} (with min gap {} m) is larger than the {} m x {} m channel; "
        "expected floes smaller than the channel width",
        ctx, size, gap, lx, lz));
  }

  // number of floes for the target concentration, and their sides
  const double target = params.concentration * layout.channel_area;
  const double exact_n = target / (params.floe_size * params.floe_size);
  const std::vector<double> sides = params.size_spread > 0.0 ? spread_sides(params, target) : std::vector<double>{};
  const long n = params.size_spread > 0.0 ? static_cast<long>(sides.size()) : std::lround(exact_n);
  if (params.concentration == 0.0) return layout;  // open water
  if (n == 0) {
    throw InputError(fmt::format(
        "{}: ice.concentration = {} with {} gives round({}) = 0 floes in the "
        "{} m x {} m channel; expected a concentration giving at least one floe (or 0 for open "
        "water)",
        ctx, params.concentration, size, exact_n, lx, lz));
  }
  // the relaxation costs a trial move per floe per sweep, about 0.5 us each (measured: 100000
  // sweeps of 990 floes, 51 s): refuse what would take minutes rather than hang in set-up
  const double moves = static_cast<double>(params.sweeps) * static_cast<double>(n);
  if (moves > kMaxLayoutMoves)
    throw InputError(fmt::format(
        "{}: layout.sweeps = {} over {} floes is {:.3g} Monte-Carlo moves, about {:.0f} s of set-up; expected at "
        "most {:.0e} moves (layout.sweeps <= {}): the relaxation has randomised a layout after some 30 "
        "sweeps (the default)",
        ctx, params.sweeps, n, moves, moves * 0.5e-6, kMaxLayoutMoves,
        static_cast<long>(kMaxLayoutMoves / static_cast<double>(n))));

  Rng rng(params.seed);
  const double radius = bounding_radius(square(side));  // the largest floe's
  // the relaxation's first step: half the room a floe has in its cell (columns: a hundredth of a side)
  double step = 0.01 * side;
  layout.floes.reserve(n);
  if (params.size_spread == 0.0) {
    // start: the most regular grid that holds n floes; cells need a small margin
    // so floes in neighbouring cells keep the gap despite rounding
    const double need = (side + gap) * (1.0 + 1e-9);
    const Grid grid = choose_grid(n, lx, lz, need);
    if (grid.nx == 0) {
      const long max_n = static_cast<long>(std::floor(lx / need)) *
                         static_cast<long>(std::floor(lz / need));
      throw InputError(fmt::format(
          "{}: ice.concentration = {} with {} needs {} floes, but at most {} fit "
          "on a grid in the {} m x {} m channel with min gap {} m; expected ice.concentration <= "
          "{:.4f} for this ice.floe_size (or smaller floes)",
          ctx, params.concentration, size, n, max_n, lx, lz, gap,
          static_cast<double>(max_n) * side * side / layout.channel_area));
    }

    // leave the surplus cells empty, chosen at random (partial Fisher-Yates)
    const long cells = static_cast<long>(grid.nx) * grid.nz;
    std::vector<long> order(cells);
    for (long c = 0; c < cells; ++c) order[c] = c;
    for (long c = 0; c < cells - n; ++c) {
      const long pick = c + static_cast<long>(rng.below(static_cast<uint64_t>(cells - c)));
      std::swap(order[c], order[pick]);
    }
    std::vector<long> occupied(order.begin() + (cells - n), order.end());
    std::sort(occupied.begin(), occupied.end());  // floes numbered along x, then z

    // floes at the cell centres, with a random yaw small enough to stay in the cell
    const Polygon shape = square(side);
    const double yaw0 =
        std::min(params.max_yaw, 0.999 * fitting_yaw(side, std::min(grid.dx, grid.dz) - gap));
    for (long c : occupied) {
      const long i = c / grid.nz, k = c % grid.nz;
      const Eigen::Vector2d centre(ch.x_min + (static_cast<double>(i) + 0.5) * grid.dx,
                                   ch.z_min + (static_cast<double>(k) + 0.5) * grid.dz);
      layout.floes.push_back({centre, yaw0 * rng.symmetric(), shape});
    }
    step = std::max(0.5 * (std::min(grid.dx, grid.dz) - side - gap), 0.01 * side);
  } else {
    // floes of many sizes do not fill a grid of cells for the largest: start from columns
    // across the channel instead, the floes taken largest first (each column as wide as its
    // first floe, filled down the channel's width while they fit), the columns then shuffled
    // along the channel and the room left spread evenly. Within a column the sizes are alike;
    // the relaxation then moves and turns every floe
    std::vector<double> sorted = sides;
    std::sort(sorted.begin(), sorted.end(), std::greater<>());
    std::vector<std::vector<double>> columns;
    double used_z = lz;  // of the last column
    for (double a : sorted) {
      if (columns.empty() || used_z + a + gap > lz) {
        columns.push_back({});
        used_z = 0.0;
      }
      columns.back().push_back(a);
      used_z += a + gap;
    }
    double used_x = 0.0;
    for (const auto& c : columns) used_x += c.front() + gap;
    if (used_x > lx)
      throw InputError(fmt::format(
          "{}: ice.concentration = {} with {} needs {} floes, which fill {:.3g} m of columns across the "
          "{} m x {} m channel with min gap {} m; expected a lower ice.concentration or a smaller spread",
          ctx, params.concentration, size, n, used_x, lx, lz, gap));
    for (std::size_t c = columns.size(); c > 1; --c) std::swap(columns[c - 1], columns[rng.below(c)]);
    const double room_x = (lx - used_x) / static_cast<double>(columns.size());
    double x = ch.x_min;
    for (const auto& c : columns) {
      const double width = c.front();
      double z_used = 0.0;
      for (double a : c) z_used += a + gap;
      const double room_z = (lz - z_used) / static_cast<double>(c.size());
      double z = ch.z_min;
      for (double a : c) {
        layout.floes.push_back({Eigen::Vector2d(x + 0.5 * (room_x + gap + width), z + 0.5 * (room_z + gap + a)), 0.0,
                                square(a)});
        z += a + gap + room_z;
      }
      x += width + gap + room_x;
    }
    // floes numbered along x, then z, as on the grid
    std::sort(layout.floes.begin(), layout.floes.end(), [](const Floe& a, const Floe& b) {
      return a.centre.x() < b.centre.x() || (a.centre.x() == b.centre.x() && a.centre.y() < b.centre.y());
    });
  }

  // world outlines and the cell list for the relaxation
  std::vector<Polygon> world(n);
  CellList cell_list(ch, 2.0 * radius + gap, static_cast<size_t>(n));
  std::vector<int> cell_of(n);
  for (long i = 0; i < n; ++i) {
    const Floe& f = layout.floes[i];
    world[i] = transformed(f.shape, f.centre, f.yaw);
    cell_of[i] = cell_list.cell_of(f.centre);
    cell_list.insert(static_cast<int>(i), cell_of[i]);
  }

  // Monte-Carlo relaxation of hard polygons: a move is accepted only if the
  // floe stays inside, within the yaw limit and clear of all neighbours
  const double min_step = 1e-6 * side, max_step = side;
  long accepted_total = 0, tried_total = 0;
  for (int sweep = 0; sweep < params.sweeps; ++sweep) {
    if (params.on_sweep) params.on_sweep(static_cast<double>(sweep) / params.sweeps);
    // a rotation by dyaw moves the corners by up to radius * dyaw
    const double yaw_step = std::min(step / radius, params.max_yaw);
    long accepted = 0;
    for (long i = 0; i < n; ++i) {
      Floe& f = layout.floes[i];
      // always draw three numbers so the stream does not depend on outcomes
      const double ux = rng.symmetric(), uz = rng.symmetric(), uyaw = rng.symmetric();
      const Eigen::Vector2d centre = f.centre + step * Eigen::Vector2d(ux, uz);
      const double yaw = f.yaw + yaw_step * uyaw;
      if (std::abs(yaw) > params.max_yaw) continue;
      Polygon trial = transformed(f.shape, centre, yaw);
      if (!inside(trial, ch, 0.0)) continue;
      const double reach = 2.0 * radius + gap;
      const bool blocked = cell_list.any_near(centre, [&](int j) {
        if (j == i) return false;
        if ((layout.floes[j].centre - centre).squaredNorm() >= reach * reach) return false;
        return overlap(trial, world[j], gap);
      });
      if (blocked) continue;
      // accept
      f.centre = centre;
      f.yaw = yaw;
      world[i] = std::move(trial);
      const int cell = cell_list.cell_of(centre);
      if (cell != cell_of[i]) {
        cell_list.remove(static_cast<int>(i), cell_of[i]);
        cell_list.insert(static_cast<int>(i), cell);
        cell_of[i] = cell;
      }
      ++accepted;
    }
    accepted_total += accepted;
    tried_total += n;
    // steer the acceptance towards 40 % (the middle of the 30-50 % band)
    const double rate = static_cast<double>(accepted) / static_cast<double>(n);
    step = std::clamp(step * std::clamp(rate / 0.4, 0.5, 2.0), min_step, max_step);
  }

  layout.acceptance_rate =
      tried_total > 0 ? static_cast<double>(accepted_total) / static_cast<double>(tried_total)
                      : 0.0;
  layout.achieved_concentration = concentration(layout.floes, ch);
  return layout;
}

double concentration(const std::vector<Floe>& floes, const Channel& channel) {
  double total = 0.0;
  for (const auto& f : floes) total += area(f.shape);
  return total / channel_area(channel);
}

}  // namespace icedem
