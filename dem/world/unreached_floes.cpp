#include "dem/world/unreached_floes.hpp"

#include <cstdint>

#include "dem/world/dbvt_fill.hpp"

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

}  // namespace

UnreachedFloes::~UnreachedFloes() { tree_.clear(); }

void UnreachedFloes::add(int index, const btVector3& lo, const btVector3& hi) {
  if (index >= static_cast<int>(kept_.size())) {
    kept_.resize(static_cast<std::size_t>(index) + 1, 0);
    leaves_.resize(kept_.size(), nullptr);
  }
  if (kept_[index]) return;
  kept_[index] = 1;
  added_.push_back(Added{index, lo, hi});
  ++count_;
}

void UnreachedFloes::insert_added() {
  if (added_.empty()) return;
  shuffle_fixed(added_);
  for (const Added& a : added_)
    if (kept_[a.index])
      leaves_[a.index] =
          tree_.insert(btDbvtVolume::FromMM(a.lo, a.hi), reinterpret_cast<void*>(static_cast<std::intptr_t>(a.index)));
  added_.clear();
  tree_.optimizeTopDown(kBottomUpLeaves);
}

void UnreachedFloes::remove(int index) {
  if (!contains(index)) return;
  insert_added();
  tree_.remove(leaves_[index]);
  leaves_[index] = nullptr;
  kept_[index] = 0;
  --count_;
}

void UnreachedFloes::overlapping(const btVector3& lo, const btVector3& hi, std::vector<int>& out) {
  insert_added();
  Collector collector(out);
  tree_.collideTV(tree_.m_root, btDbvtVolume::FromMM(lo, hi), collector);
}

}  // namespace icedem
