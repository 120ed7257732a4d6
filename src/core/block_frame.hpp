// The frame valid for one block (K2: WCS -> BCS), as the interpreter hands it on with the block.
// One value: the affine map, whether it is exactly the identity (the usual case, where the stages
// skip the products), and which of the interpreter's frame states it is, so that comparing the
// frames of two blocks is one integer comparison where they are the same, as they usually are.
#pragma once

#include <cmath>
#include <cstdint>

#include "ncoffset/geometry.hpp"

namespace ncoffset::core {

class BlockFrame {
 public:
  // No frame: WCS = BCS (G500 without a programmable frame, and G53/G153/SUPA).
  BlockFrame() = default;
  // The frame state number `state` of the interpreter with its map (see FrameState).
  BlockFrame(const Affine& map, std::uint64_t state, bool identity)
      : map_(map), state_(state), identity_(identity) {}

  const Affine& map() const { return map_; }
  const Mat3& linear() const { return map_.linear; }
  bool isIdentity() const { return identity_; }
  Vec3 apply(Vec3 p) const { return identity_ ? p : map_.apply(p); }
  // Which frame state of the interpreter this is (0: none).
  std::uint64_t state() const { return state_; }
  // The same frame: the same state of the interpreter, or maps equal within 1e-12 (a frame
  // programmed again with the same values is no change).
  bool sameAs(const BlockFrame& o) const { return state_ == o.state_ || sameMap(map_, o.map_); }

 private:
  Affine map_;
  std::uint64_t state_ = 0;  // 0: frames suppressed (G53/G153/SUPA) or none
  bool identity_ = true;

  static bool sameMap(const Affine& a, const Affine& b) {
    for (int i = 0; i < 3; ++i) {
      if (std::fabs(a.offset[i] - b.offset[i]) > 1e-12) return false;
      for (int j = 0; j < 3; ++j)
        if (std::fabs(a.linear.m[static_cast<size_t>(i)][static_cast<size_t>(j)] -
                      b.linear.m[static_cast<size_t>(i)][static_cast<size_t>(j)]) > 1e-12)
          return false;
    }
    return true;
  }
};

}  // namespace ncoffset::core
