#include "dem/unreached_floes.hpp"

#include <cstdint>

namespace icedem {
namespace {

// gathers the floe indices of the leaves a query meets
struct Collector : btDbvt::ICollide {
  explicit Collector(std::vector<int>& out) : out(out) {}
  void Process(const btDbvtNode* leaf) override {
    out.push_back(static_cast<int>(reinterpret_cast<std::intptr_t>(leaf->data)));
  }
  std::vector<int>& out;
};

// Top-down rebuilds join groups of this many leaves bottom-up, at a cost of the cube of the
// group (Bullet's default, 128, costs about a second per 96,000 leaves)
constexpr int kBottomUpLeaves = 8;

}  // namespace

UnreachedFloes::~UnreachedFloes() { tree_.clear(); }

void UnreachedFloes::add(int index, const btVector3& lo, const btVector3& hi) {
  if (index >= static_cast<int>(leaves_.size())) leaves_.resize(static_cast<std::size_t>(index) + 1, nullptr);
  if (leaves_[index]) return;
  leaves_[index] = tree_.insert(btDbvtVolume::FromMM(lo, hi), reinterpret_cast<void*>(static_cast<std::intptr_t>(index)));
  ++count_;
}

void UnreachedFloes::balance() { tree_.optimizeTopDown(kBottomUpLeaves); }

void UnreachedFloes::remove(int index) {
  if (!contains(index)) return;
  tree_.remove(leaves_[index]);
  leaves_[index] = nullptr;
  --count_;
}

void UnreachedFloes::overlapping(const btVector3& lo, const btVector3& hi, std::vector<int>& out) const {
  Collector collector(out);
  tree_.collideTV(tree_.m_root, btDbvtVolume::FromMM(lo, hi), collector);
}

}  // namespace icedem
