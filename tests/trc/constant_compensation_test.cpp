// Keep tool radius compensation constant (src/trc/constant_compensation.cpp; FM W1 "Keep tool
// radius compensation constant", docs/radius-compensation.md "CUTCONON"): motion blocks go into
// a trc::RadiusCompensation with a collecting Stage behind it. G17, G41, R = 5, n_L = (-t_y, t_x).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "stage_test_support.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {
namespace {

// G41, R = 5, starting at (-10,-10): the first block is the selection block.
test::Program g41Program() {
  test::Program p;
  p.trc = test::g41(5);
  p.at = {-10, -10, 0};
  return p;
}

// The blocks through a RadiusCompensation; what it wrote.
std::vector<core::MotionBlock> compensated(const std::vector<core::MotionBlock>& blocks) {
  test::Collect out;
  RadiusCompensation trc{out};
  for (const core::MotionBlock& b : blocks) trc.motion(b);
  trc.flush();
  return out.blocks;
}

TEST(KeepConstant, NoCornerBeforeTheSuppressionAndTheBlocksAreShifted) {
  // (0,0) -> (50,0), then with CUTCONON (50,0) -> (50,-40), a right turn (outside for G41): no
  // G450 circle; X50 ends on its offset point (50,5); v = (0,5); the suppressed line runs
  // (50,5) -> (50,-35). CUTCONOF (50,-40) -> (100,-40): offset start (50,-35) = where the tool
  // stands, so nothing is inserted; offset end (100,-35).
  test::Program p = g41Program();
  std::vector<core::MotionBlock> in{p.line(10, 0, 0), p.line(11, 50, 0)};
  p.trc.constant = true;
  in.push_back(p.line(12, 50, -40));
  p.trc.constant = false;
  in.push_back(p.line(13, 100, -40));
  const auto out = compensated(in);
  ASSERT_EQ(out.size(), 4u);
  test::expectRow(out[0], 10, Motion::G1, 0, 5);
  test::expectRow(out[1], 11, Motion::G1, 50, 5);
  test::expectRow(out[2], 12, Motion::G1, 50, -35);
  test::expectVec(out[2].start, 50, 5, 0);
  test::expectRow(out[3], 13, Motion::G1, 100, -35);
  test::expectVec(out[3].start, 50, -35, 0);
}

TEST(KeepConstant, ACircleIsShiftedWithItsCentre) {
  // (0,0) -> (40,0): v = (0,5). G3 (40,0) -> (60,20) about (40,20): (40,5) -> (60,25) about
  // (40,25), radius 20 at both ends.
  test::Program p = g41Program();
  std::vector<core::MotionBlock> in{p.line(10, 0, 0), p.line(11, 40, 0)};
  p.trc.constant = true;
  in.push_back(p.arc(12, Motion::G3, 60, 20, 40, 20));
  const auto out = compensated(in);
  ASSERT_EQ(out.size(), 3u);
  const core::MotionBlock& c = out[2];
  test::expectRow(c, 12, Motion::G3, 60, 25);
  test::expectVec(c.start, 40, 5, 0);
  test::expectVec(c.centre, 40, 25, 0);
  EXPECT_NEAR(norm(c.start - c.centre), 20, 1e-12);
  EXPECT_NEAR(norm(c.end - c.centre), 20, 1e-12);
}

TEST(KeepConstant, BlocksWithoutPlaneMotionStandAtTheShiftedEndAndDoNotCount) {
  // MD20250 = 1 (TrcSettings' default): three Z blocks in a row while suppressed are no alarm;
  // they stand at (50,25), the end of the shifted Y20 block. CUTCONOF X0: offset start (50,15),
  // a line from (50,25) is inserted at Z-3.
  test::Program p = g41Program();
  std::vector<core::MotionBlock> in{p.line(10, 0, 0), p.line(11, 50, 0)};
  p.trc.constant = true;
  in.push_back(p.line(12, 50, 20));
  for (int i = 1; i <= 3; ++i) in.push_back(p.line(12 + i, 50, 20, -i));
  p.trc.constant = false;
  in.push_back(p.line(16, 0, 20));
  const auto out = compensated(in);
  ASSERT_EQ(out.size(), 8u);
  test::expectRow(out[2], 12, Motion::G1, 50, 25);
  test::expectRow(out[5], 15, Motion::G1, 50, 25, -3);
  test::expectRow(out[6], 16, Motion::G1, 50, 15, -3);
  test::expectRow(out[7], 16, Motion::G1, 0, 15, -3);
}

TEST(KeepConstant, SelectionUnderCutconIsNotModelled) {
  test::Program p = g41Program();
  p.trc.constant = true;
  try {
    compensated({p.line(10, 0, 0), p.line(11, 50, 0)});
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), 99010);
    EXPECT_EQ(e.line(), 10);
  }
}

}  // namespace
}  // namespace ncoffset::trc
