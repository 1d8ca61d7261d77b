// Floes nothing has reached yet, kept out of Bullet's world.
//
// A field far larger than the ice the structure disturbs is mostly floes at rest where the
// layout put them, asleep from the start. In Bullet's world each of them still costs every
// step (its loops over bodies, its broadphase, the pairs of resting neighbours) and every
// checkpoint (the world is rebuilt from each). Such a floe is instead kept here, as a box in a
// tree of its own, and enters the world (asleep, where it lies, as it would have been there all
// along) once a moving body or the structure comes within kReachMargin of it (dem/activation/reach.hpp).
// A floe that entered stays in the world.
//
// Nothing changes for a run: a sleeping floe that no moving body has come near has no contact
// and no part in any island, solve or force; Bullet makes a pair for two boxes only when they
// overlap (its dbvt pads a moving box by 0.05 m), so a floe that enters while the nearest
// moving box is kReachMargin away meets that body exactly as a floe that was in the world.
#pragma once

#include <vector>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <LinearMath/btVector3.h>

namespace icedem {

/// How near (m) a moving body's box may come to an unreached floe's box before the floe enters
/// the world: Bullet's dbvt margin (0.05 m) twice over, for the lag of its padded boxes, and
/// room for a step of motion; a body's own travel in a step is added to it (dem/activation/reach.hpp).
inline constexpr double kReachMargin = 0.25;

/// The floes out of the world until reached, by index into World::floes(), with their boxes.
class UnreachedFloes {
 public:
  UnreachedFloes() = default;
  ~UnreachedFloes();
  UnreachedFloes(const UnreachedFloes&) = delete;
  UnreachedFloes& operator=(const UnreachedFloes&) = delete;

  /// Keep floe `index`, whose box is [lo, hi], out of the world until reached. Its box joins
  /// the tree with the others added since, at the next query.
  void add(int index, const btVector3& lo, const btVector3& hi);

  /// Whether floe `index` is kept here.
  bool contains(int index) const {
    return index >= 0 && index < static_cast<int>(kept_.size()) && kept_[index];
  }

  /// Stop keeping floe `index` (it enters the world).
  void remove(int index);

  /// The floes whose boxes overlap [lo, hi], appended to `out` (each once per call).
  void overlapping(const btVector3& lo, const btVector3& hi, std::vector<int>& out);

  /// How many floes are kept here.
  int size() const { return count_; }

 private:
  // the boxes added since the last query into the tree: in a shuffled order, then rebuilt
  // balanced (one at a time in the order of the layout, 96,000 boxes made a chain: 40 s)
  void insert_added();

  struct Added {
    int index;
    btVector3 lo, hi;
  };
  btDbvt tree_;
  std::vector<btDbvtNode*> leaves_;  // per floe index, null when not in the tree
  std::vector<char> kept_;           // per floe index
  std::vector<Added> added_;         // not yet in the tree
  int count_ = 0;
};

}  // namespace icedem
