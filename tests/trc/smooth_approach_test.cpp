// Smooth approach and retraction alone (src/trc/smooth_approach.cpp, W1 2.4.4, spec §6): a SAR
// block goes into a trc::SmoothApproach with a collecting Stage behind it; what comes out are
// the sub-blocks of the programmed (uncompensated) contour, and the Feedback carries $P_APR /
// $P_AEP and the implicit end point of a retraction. The numbers are those of the cases in
// tests/programs/sar/ (README.md there: construction and readings).
#include "trc/smooth_approach.hpp"

#include <gtest/gtest.h>

#include "ncoffset/alarm.hpp"
#include "stage_test_support.hpp"

namespace ncoffset::trc {
namespace {

using test::Collect;
using test::expectRow;
using test::expectVec;
using test::Program;

TEST(SmoothApproach, G147ExpandsIntoItsSubBlocks) {
  // app_g147_g340_g17_g42: P0 = (80,30,25) after G0 F300; G42 G147 G340 DISR=8 DISCL=2
  // FAD=100 X40 Y0 Z-5 F400; the next block G1 X0 Y0 gives t = (-1,0). Line length
  // R + DISR = 13: P3 = (53,0), P1 = (53,0,25), P3 = (53,0,-3), P4 = (40,0,-5).
  Collect out;
  SmoothApproach sar(out);
  Program p;
  p.at = {80, 30, 25};
  p.trc.mode = core::TrcMode::Right;
  p.trc.radius = 5;
  p.feed = 400;
  core::MotionBlock s = p.line(26, 40, 0, -5);
  s.sar.kind = core::SarKind::Line147;
  s.sar.infeed = core::SarInfeed::G340;
  s.sar.has_disr = s.sar.has_discl = s.sar.has_fad = true;
  s.sar.disr = 8;
  s.sar.discl = 2;
  s.sar.fad = 100;
  s.sar.plane_axis = s.sar.any_axis = s.sar.f_programmed = true;
  s.sar.rapid_before = true;
  s.sar.feed_value = 400;
  s.sar.feed_before = 300;
  // The SAR block itself writes nothing yet: the approach points are no longer valid.
  const core::Feedback began = sar.motion(s);
  EXPECT_TRUE(out.blocks.empty());
  ASSERT_TRUE(began.approach);
  EXPECT_FALSE(began.approach->valid);
  EXPECT_FALSE(began.end_point);
  // The tangent block evaluates the approach: A, B and D of the SAR block, then itself.
  const core::Feedback done = sar.motion(p.line(27, 0, 0));
  ASSERT_EQ(out.blocks.size(), 4u);
  expectRow(out.blocks[0], 26, Motion::G0, 53, 0, 25);  // A: P0 -> P1, as the block before
  expectVec(out.blocks[0].start, 80, 30, 25);
  expectRow(out.blocks[1], 26, Motion::G0, 53, 0, -3);  // B: P1 -> P3 (G340)
  expectRow(out.blocks[2], 26, Motion::G1, 40, 0, -5);  // D: P3 -> P4 with FAD
  EXPECT_EQ(out.blocks[2].feed, 100);
  expectRow(out.blocks[3], 27, Motion::G1, 0, 0, -5);
  for (const core::MotionBlock& b : out.blocks) {
    EXPECT_EQ(b.sar.kind, core::SarKind::None);  // the radius compensation sees plain blocks
    EXPECT_EQ(b.trc.mode, core::TrcMode::Right);
  }
  // $P_APR = P3 (uncompensated), $P_AEP = P4, $P_APDV = 1.
  ASSERT_TRUE(done.approach);
  EXPECT_TRUE(done.approach->valid);
  expectVec(done.approach->apr, 53, 0, -3);
  expectVec(done.approach->aep, 40, 0, -5);
}

TEST(SmoothApproach, G247HelixAndTheApproachPoints) {
  // app_sysvars_papr_paep: P0 = (0,20,20), G41 G247 G340 G140 DISR=8 DISCL=3 FAD=100
  // X40 Y-10 Z0 F350, then G1 X70 Y-10 (t = (1,0)). Tool inside the arc: r = DISR + R = 13,
  // M = (40,3), P3 = M - r t = (27,3), applicate 3: a helix G3 from (27,3,3) to (40,-10,0) with
  // the centre at its start's applicate. $P_APR = (27,3,3), $P_AEP = (40,-10,0).
  Collect out;
  SmoothApproach sar(out);
  Program p;
  p.at = {0, 20, 20};
  p.trc = test::g41(5);
  p.feed = 350;
  core::MotionBlock s = p.line(38, 40, -10, 0);
  s.sar.kind = core::SarKind::Quadrant247;
  s.sar.side = core::SarSide::G140;
  s.sar.has_disr = s.sar.has_discl = s.sar.has_fad = true;
  s.sar.disr = 8;
  s.sar.discl = 3;
  s.sar.fad = 100;
  s.sar.plane_axis = s.sar.any_axis = s.sar.f_programmed = true;
  s.sar.rapid_before = true;
  s.sar.feed_value = 350;
  s.sar.feed_before = 300;
  sar.motion(s);
  const core::Feedback done = sar.motion(p.line(39, 70, -10));
  ASSERT_EQ(out.blocks.size(), 4u);
  expectRow(out.blocks[0], 38, Motion::G0, 27, 3, 20);
  expectRow(out.blocks[1], 38, Motion::G0, 27, 3, 3);
  const core::MotionBlock& helix = out.blocks[2];
  expectRow(helix, 38, Motion::G3, 40, -10, 0);
  expectVec(helix.start, 27, 3, 3);
  expectVec(helix.centre, 40, 3, 3);
  EXPECT_EQ(helix.feed, 100);
  expectRow(out.blocks[3], 39, Motion::G1, 70, -10, 0);
  ASSERT_TRUE(done.approach);
  EXPECT_TRUE(done.approach->valid);
  expectVec(done.approach->apr, 27, 3, 3);
  expectVec(done.approach->aep, 40, -10, 0);
}

// G148 G141 G340 DISR=5 DISCL=3 where the tool stands, feed 400.
core::MotionBlock g148Line(Program& p, int no) {
  core::MotionBlock s = p.line(no, p.at.x, p.at.y, p.at.z);
  s.sar.kind = core::SarKind::Line148;
  s.sar.side = core::SarSide::G141;
  s.sar.has_disr = s.sar.has_discl = true;
  s.sar.disr = 5;
  s.sar.discl = 3;
  s.sar.feed_value = s.sar.feed_before = 400;
  return s;
}

TEST(SmoothApproach, RetractionWithoutEndPointFeedsBackWhereItEnds) {
  // G148 G141 G340 DISR=5 DISCL=3 without any geometry axis after G1 X40 Y0 (t = (1,0), no
  // compensation): P3 = P4 + DISR t = (45,0), P2.app = 0 + 3; without an axis the retraction
  // ends in P2 (README "Construction"; details §4.3, PM-F 10.2004 8-50): (45,0,3). P3 -> P2 and
  // P2 -> P0 have no length and give no rows.
  Collect out;
  SmoothApproach sar(out);
  Program p;
  p.at = {0, 0, 0};
  p.feed = 400;
  EXPECT_FALSE(sar.motion(p.line(10, 40, 0)).end_point);
  const core::Feedback back = sar.motion(g148Line(p, 11));
  ASSERT_TRUE(back.end_point);
  expectVec(*back.end_point, 45, 0, 3);
  EXPECT_FALSE(back.approach);
  ASSERT_EQ(out.blocks.size(), 2u);
  expectRow(out.blocks[1], 11, Motion::G1, 45, 0, 3);  // D': P4 -> P3, a sloped line
  expectVec(out.blocks[1].start, 40, 0, 0);
}

// The retraction's tangent comes from what the stage keeps of the last block with plane motion
// (its motion and end - centre / end - start, docs/performance.md §38), not from the blocks
// after it that move only the applicate or less than the point tolerance in the plane.
TEST(SmoothApproach, RetractionTakesTheTangentOfTheLastBlockWithPlaneMotion) {
  // From (40,0): G3 to (50,10) about (40,10) ends in direction +Y, G2 to (50,-10) about
  // (40,-10) in -Y, G1 to (50,0) in +X. Then Z-1 and a step of 1e-7 in X (no plane motion):
  // P3 = P4 + DISR t, P2 = P3 + DISCL along Z.
  struct Case {
    Motion motion;
    double x, y, cx, cy;  // the last contour block (cx, cy unused for the line)
    double p3x, p3y;
  };
  for (const Case& c :
       {Case{Motion::G3, 50, 10, 40, 10, 50, 15}, Case{Motion::G2, 50, -10, 40, -10, 50, -15},
        Case{Motion::G1, 50, 0, 0, 0, 55, 0}}) {
    Collect out;
    SmoothApproach sar(out);
    Program p;
    p.at = {40, 0, 0};
    p.feed = 400;
    sar.motion(c.motion == Motion::G1 ? p.line(10, c.x, c.y)
                                      : p.arc(10, c.motion, c.x, c.y, c.cx, c.cy));
    sar.motion(p.line(11, c.x, c.y, -1));
    sar.motion(p.line(12, c.x + 1e-7, c.y, -1));
    const core::Feedback back = sar.motion(g148Line(p, 13));
    ASSERT_TRUE(back.end_point);
    expectVec(*back.end_point, c.p3x + 1e-7, c.p3y, 2);
    ASSERT_EQ(out.blocks.size(), 4u);
    expectRow(out.blocks[3], 13, Motion::G1, c.p3x + 1e-7, c.p3y, 2);
  }
}

TEST(SmoothApproach, NoBlockAfterTheApproachIsAlarm10744) {
  // A SAR block at the end of the program: no block defines the approach direction, alarm
  // 10744 "no valid approach direction" on the SAR block; nothing is flushed behind it.
  Collect out;
  SmoothApproach sar(out);
  Program p;
  core::MotionBlock s = p.line(5, 10, 0);
  s.sar.kind = core::SarKind::Line147;
  s.sar.has_disr = true;
  s.sar.disr = 5;
  s.sar.plane_axis = true;
  sar.motion(s);
  try {
    sar.flush();
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), 10744);
    EXPECT_EQ(e.line(), 5);
  }
  EXPECT_EQ(out.flushed, 0);
}

}  // namespace
}  // namespace ncoffset::trc
