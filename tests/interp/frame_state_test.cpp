// The frame state alone (src/interp/frame_state.hpp): selecting a settable frame, the chain
// $P_IFRAME : $P_PFRAME and the block frame handed to the stages.
#include "interp/frame_state.hpp"

#include <gtest/gtest.h>

namespace ncoffset::interp {
namespace {

void expectVec(Vec3 v, double x, double y, double z) {
  EXPECT_NEAR(v.x, x, 1e-12);
  EXPECT_NEAR(v.y, y, 1e-12);
  EXPECT_NEAR(v.z, z, 1e-12);
}

TEST(FrameState, StartsWithoutFrame) {
  FrameState f;
  EXPECT_TRUE(f.isIdentity());
  EXPECT_TRUE(f.blockFrame().isIdentity());
  expectVec(f.toBcs({1, 2, 3}), 1, 2, 3);
}

TEST(FrameState, SettableThenProgrammableFrame) {
  FrameState f;
  f.settable(1).coarse = {100, 50, 0};  // G54: X100 Y50
  f.select(1);
  f.programmable().rotation = {0, 0, 90};  // ROT Z90 inside it
  f.update();
  EXPECT_FALSE(f.isIdentity());
  // WCS (10, 0, 5): rotated to (0, 10, 5), then translated.
  expectVec(f.toBcs({10, 0, 5}), 100, 60, 5);
  expectVec(f.toWcs({100, 60, 5}), 10, 0, 5);
  expectVec(f.blockFrame().apply({10, 0, 5}), 100, 60, 5);
}

TEST(FrameState, EveryUpdateIsANewStateButEqualFramesCompareSame) {
  FrameState f;
  const core::BlockFrame before = f.blockFrame();
  f.programmable().coarse = {1, 0, 0};
  f.update();
  EXPECT_FALSE(f.blockFrame().sameAs(before));
  f.programmable() = Frame();  // back to no frame: a new state, the same map
  f.update();
  EXPECT_NE(f.blockFrame().state(), before.state());
  EXPECT_TRUE(f.blockFrame().sameAs(before));
}

}  // namespace
}  // namespace ncoffset::interp
