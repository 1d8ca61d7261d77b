// Floes in a channel: a cell list for neighbour queries (generation and the
// overlap check of layout files), and the checks both make against the channel.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dem/layout/floe_layout.hpp"

namespace icedem {

// uniform grid over the channel; a body is filed under the cell holding its
// centre. With cell size >= the largest interaction distance, every possible
// partner of a body is in its own or one of the 8 surrounding cells, so a
// neighbour query is O(1) and a sweep O(N).
class CellList {
 public:
  CellList(const Channel& ch, double interaction_distance, size_t bodies) : ch_(ch) {
    const double lx = ch.x_max - ch.x_min, lz = ch.z_max - ch.z_min;
    // never more than ~4 cells per body, whatever the sizes
    const double min_size = std::sqrt(lx * lz / (4.0 * static_cast<double>(bodies) + 16.0));
    // the small factor keeps "distance < size" => "adjacent cells" under rounding
    size_ = std::max(interaction_distance * (1.0 + 1e-9), min_size);
    nx_ = std::max(1, static_cast<int>(std::ceil(lx / size_)));
    nz_ = std::max(1, static_cast<int>(std::ceil(lz / size_)));
    cells_.resize(static_cast<size_t>(nx_) * nz_);
  }

  int cell_of(const Eigen::Vector2d& p) const {
    return index(ix(p.x()), iz(p.y()));
  }

  void insert(int body, int cell) { cells_[cell].push_back(body); }

  void remove(int body, int cell) {
    auto& c = cells_[cell];
    auto it = std::find(c.begin(), c.end(), body);
    assert(it != c.end());
    *it = c.back();
    c.pop_back();
  }

  // calls f(body) for every body filed near p; stops and returns true as soon
  // as f returns true
  template <class F>
  bool any_near(const Eigen::Vector2d& p, F&& f) const {
    const int cx = ix(p.x()), cz = iz(p.y());
    for (int i = std::max(cx - 1, 0); i <= std::min(cx + 1, nx_ - 1); ++i) {
      for (int k = std::max(cz - 1, 0); k <= std::min(cz + 1, nz_ - 1); ++k) {
        for (int body : cells_[index(i, k)]) {
          if (f(body)) return true;
        }
      }
    }
    return false;
  }

 private:
  int ix(double x) const { return clamp_cell((x - ch_.x_min) / size_, nx_); }
  int iz(double z) const { return clamp_cell((z - ch_.z_min) / size_, nz_); }
  int index(int i, int k) const { return i * nz_ + k; }
  static int clamp_cell(double u, int n) {
    if (!(u >= 0.0)) return 0;  // also NaN
    return u >= n - 1 ? n - 1 : static_cast<int>(u);
  }

  Channel ch_;
  double size_;
  int nx_, nz_;
  std::vector<std::vector<int>> cells_;
};

/// True if every vertex of `world` lies in the channel, within `tolerance` (m).
bool inside(const Polygon& world, const Channel& ch, double tolerance);

/// Area of the channel, m^2.
double channel_area(const Channel& ch);

/// "x in [a, b] m, z in [c, d] m", for messages.
std::string channel_text(const Channel& ch);

/// InputError, prefixed by `context`, unless the channel has a finite positive length and width.
void check_channel(const Channel& ch, const std::string& context);

}  // namespace icedem
