// How icedem fills Bullet's dynamic bounding-box trees (btDbvt). Bullet inserts boxes one at a
// time, each next to the nearest, and in the order the bodies were made (row by row) that builds
// a chain, not a tree: boxes go in in a shuffled order, and trees are rebuilt top-down.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace icedem {

/// A top-down rebuild of a btDbvt splits its boxes down to groups of this many, which it joins
/// bottom-up at a cost of the cube of the group (Bullet's default, 128, made one rebuild of
/// 96,000 boxes cost about a second).
inline constexpr int kBottomUpLeaves = 8;

/// `items` shuffled (Fisher-Yates on Knuth's 64-bit linear congruential generator, fixed seed).
template <class T>
void shuffle_fixed(std::vector<T>& items) {
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (std::size_t i = items.size(); i > 1; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(items[i - 1], items[(state >> 33) % i]);
  }
}

}  // namespace icedem
