// The motion builder alone (src/interp/motion_builder.hpp): block words become one motion block
// for the first stage, with the tool length taken up axis by axis (W1 2.1, spec §2.6), frames,
// circles and the SAR request; the channel's position follows.
#include "interp/motion_builder.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "interp/collect_stage.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {
namespace {

struct Fixture : BuilderRig {
  ModalState modal;

  Fixture() {
    modal.motion = Motion::G1;
    modal.feed = 100;
  }
  BlockWords move(double x, double y, double z) {
    BlockWords w;
    const double v[3] = {x, y, z};
    for (int i = 0; i < 3; ++i) {
      w.axis[i] = true;
      w.axis_value[i] = v[i];
    }
    return w;
  }
};

TEST(MotionBuilder, LineToTheProgrammedPoint) {
  Fixture f;
  EXPECT_TRUE(f.builder.build(f.move(10, 20, 5), f.modal, {7, 0, 0, Motion::G0}));
  ASSERT_EQ(f.stage.blocks.size(), 1u);
  const core::MotionBlock& m = f.stage.blocks[0];
  EXPECT_EQ(m.line, 7);
  EXPECT_EQ(m.motion, Motion::G1);
  EXPECT_EQ(m.end.x, 10);
  EXPECT_EQ(m.end.y, 20);
  EXPECT_EQ(m.feed, 100);
  EXPECT_TRUE(m.frame.isIdentity());
  EXPECT_EQ(f.builder.wcs().z, 5);
}

TEST(MotionBuilder, ZeroLengthBlockGivesNoMotion) {
  Fixture f;
  f.builder.build(f.move(10, 20, 5), f.modal, {});
  EXPECT_FALSE(f.builder.build(f.move(10, 20, 5), f.modal, {}));
  EXPECT_EQ(f.stage.blocks.size(), 1u);
}

TEST(MotionBuilder, ToolLengthIsTakenUpByTheAxesTheBlockMoves) {
  Fixture f;
  std::vector<lang::Value> idx{lang::Value::integer(1), lang::Value::integer(1)};
  f.tools.write("$TC_DP1", idx, true, lang::Value::real(120));
  f.tools.write("$TC_DP3", idx, true, lang::Value::real(100));  // L1 = 100: Z in G17
  f.tools.execute({1, 1, false}, true, {});
  BlockWords xy;  // X10 Y10: Z does not move, so it does not take up the length yet
  xy.axis[0] = xy.axis[1] = true;
  xy.axis_value[0] = xy.axis_value[1] = 10;
  f.builder.build(xy, f.modal, {});
  EXPECT_EQ(f.stage.blocks.back().tool_offset.z, 0);
  BlockWords z;
  z.axis[2] = true;
  z.axis_value[2] = 5;
  f.builder.build(z, f.modal, {});
  EXPECT_EQ(f.stage.blocks.back().tool_offset.z, 100);
  EXPECT_EQ(f.builder.bcs().z, 5);  // the tool tip; the carrier is 100 mm above it
}

TEST(MotionBuilder, FeedMissingIsAlarm10860) {
  Fixture f;
  f.modal.feed = 0;
  try {
    f.builder.build(f.move(1, 0, 0), f.modal, {});
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), toInt(AlarmNumber::FeedNotProgrammed));
  }
}

TEST(MotionBuilder, FullCircleAboutTheCentre) {
  Fixture f;
  f.modal.motion = Motion::G2;
  BlockWords w;  // G2 I10: a full circle about (10, 0) from the start (0, 0)
  w.centre[0] = true;
  w.centre_value[0] = 10;
  f.builder.build(w, f.modal, {});
  const core::MotionBlock& m = f.stage.blocks.back();
  EXPECT_EQ(m.motion, Motion::G2);
  EXPECT_NEAR(m.centre.x, 10, 1e-12);
  EXPECT_NEAR(m.end.x, 0, 1e-12);
  EXPECT_EQ(m.applicate, 2);
}

TEST(MotionBuilder, ImplicitEndPointFedBackBecomesThePosition) {
  Fixture f;
  f.stage.next.end_point = Vec3{1, 2, 3};
  f.builder.build(f.move(10, 20, 5), f.modal, {});
  EXPECT_EQ(f.builder.wcs().x, 1);
  EXPECT_EQ(f.builder.wcs().z, 3);
}

TEST(MotionBuilder, FrameMapsTheStartPointBackToTheWcs) {
  Fixture f;
  f.frames.programmable().coarse = {100, 0, 0};  // TRANS X100
  f.frames.update();
  f.builder.build(f.move(10, 0, 0), f.modal, {});
  EXPECT_EQ(f.builder.bcs().x, 110);
  EXPECT_EQ(f.stage.blocks.back().frame.apply({10, 0, 0}).x, 110);
}

}  // namespace
}  // namespace ncoffset::interp
