// A shuffle that is the same on every machine and every run, for inserting boxes into Bullet's
// dbvt: it adds them one at a time next to the nearest, and in the order the bodies were made
// (row by row) that builds a chain, not a tree.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace icedem {

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
