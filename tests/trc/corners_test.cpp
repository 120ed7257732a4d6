// Corners of radius compensation alone (src/trc/corners.cpp, W1 2.4.3/2.4.5, details Q3/Q4):
// motion blocks go into a trc::RadiusCompensation with a collecting Stage behind it, and the
// written elements are checked against the hand derivations of the golden cases named.
#include <gtest/gtest.h>

#include <cmath>

#include "stage_test_support.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {
namespace {

using test::Collect;
using test::expectRow;
using test::expectVec;
using test::Program;

// G41, R = 5: the selection block from (-10,-10) to (0,0), then the contour.
struct Fixture {
  Collect out;
  RadiusCompensation trc{out};
  Program prog;
  explicit Fixture(core::TrcSettings t) {
    prog.trc = t;
    prog.at = {-10, -10, 0};
  }
  void feed(const core::MotionBlock& b) { trc.motion(b); }
  void retract(int no, double x, double y) {
    prog.trc.mode = core::TrcMode::Off;
    feed(prog.line(no, x, y));
    trc.flush();
  }
};

TEST(Corners, OutsideCornerG450IsACircleOfRadiusRAboutTheCorner) {
  // g450_line_line_g17_g41: (0,0) -> (50,0) -> (50,-40), a right turn = outside for G41.
  Fixture f(test::g41(5));
  f.feed(f.prog.line(18, 0, 0));
  f.feed(f.prog.line(19, 50, 0));
  f.feed(f.prog.line(20, 50, -40));
  f.retract(21, 60, -50);
  ASSERT_EQ(f.out.blocks.size(), 5u);
  expectRow(f.out.blocks[0], 18, Motion::G1, 0, 5);  // NORM approach to the normal point
  expectRow(f.out.blocks[1], 19, Motion::G1, 50, 5);
  // The transition circle belongs to the next block: G2 about the corner point (50,0) from
  // A = (50,5) to B = (55,0), radius R at both ends.
  const core::MotionBlock& circle = f.out.blocks[2];
  expectRow(circle, 20, Motion::G2, 55, 0);
  expectVec(circle.start, 50, 5, 0);
  expectVec(circle.centre, 50, 0, 0);
  EXPECT_NEAR(norm(circle.start - circle.centre), 5, 1e-12);
  EXPECT_NEAR(norm(circle.end - circle.centre), 5, 1e-12);
  expectRow(f.out.blocks[3], 20, Motion::G1, 55, -40);
  expectVec(f.out.blocks[3].start, 55, 0, 0);
  expectRow(f.out.blocks[4], 21, Motion::G1, 60, -50);
  expectVec(f.out.blocks[4].start, 55, -40, 0);
}

TEST(Corners, OutsideCornerG451IsTheIntersection) {
  // g451_line_line_g17_g41: the same corner with G451 (90 deg < MD20210 = 100): S = (55,5).
  Fixture f(test::g41(5, CornerMode::Intersection));
  f.feed(f.prog.line(19, 0, 0));
  f.feed(f.prog.line(20, 50, 0));
  f.feed(f.prog.line(21, 50, -40));
  f.retract(22, 60, -50);
  ASSERT_EQ(f.out.blocks.size(), 4u);  // nothing inserted
  expectRow(f.out.blocks[0], 19, Motion::G1, 0, 5);
  expectRow(f.out.blocks[1], 20, Motion::G1, 55, 5);
  expectRow(f.out.blocks[2], 21, Motion::G1, 55, -40);
  expectVec(f.out.blocks[2].start, 55, 5, 0);
  expectRow(f.out.blocks[3], 22, Motion::G1, 60, -50);
}

TEST(Corners, G451BeyondTheCornerLimitTakesTheCircle) {
  // g451_beyond_corner_limit: deflection 135 deg >= MD20210 = 100: the G450 circle about (50,0)
  // from A = (50,5) to B = (50 + 5/sqrt2, -5/sqrt2).
  Fixture f(test::g41(5, CornerMode::Intersection));
  f.feed(f.prog.line(19, 0, 0));
  f.feed(f.prog.line(20, 50, 0));
  f.feed(f.prog.line(21, 20, -30));
  f.retract(22, 30, -40);
  ASSERT_EQ(f.out.blocks.size(), 5u);
  const double h = 5 / std::sqrt(2.0);
  expectRow(f.out.blocks[1], 20, Motion::G1, 50, 5);
  expectRow(f.out.blocks[2], 21, Motion::G2, 50 + h, -h);
  expectVec(f.out.blocks[2].centre, 50, 0, 0);
  expectRow(f.out.blocks[3], 21, Motion::G1, 20 + h, -30 - h);
}

TEST(Corners, InsideCornerIsTheIntersection) {
  // inside_line_line_g17_g41: (0,0) -> (50,0) -> (50,40), a left turn = inside for G41: the
  // equidistants o = 5 and a = 45 meet at S = (45,5); both blocks end there.
  for (CornerMode corner : {CornerMode::TransitionCircle, CornerMode::Intersection}) {
    Fixture f(test::g41(5, corner));
    f.feed(f.prog.line(15, 0, 0));
    f.feed(f.prog.line(16, 50, 0));
    f.feed(f.prog.line(17, 50, 40));
    f.retract(18, 40, 50);
    ASSERT_EQ(f.out.blocks.size(), 4u);
    expectRow(f.out.blocks[0], 15, Motion::G1, 0, 5);
    expectRow(f.out.blocks[1], 16, Motion::G1, 45, 5);
    expectRow(f.out.blocks[2], 17, Motion::G1, 45, 40);
    expectVec(f.out.blocks[2].start, 45, 5, 0);
    expectRow(f.out.blocks[3], 18, Motion::G1, 40, 50);
  }
}

TEST(Corners, TangentJoinsInsertNothing) {
  // tangent_line_arc_line_g17_g41: line -> G3 (centre (50,20), r = 20) -> line, all tangent;
  // the equidistants meet end to start: (50,5), the arc at radius 15 to (65,20), x = 65.
  Fixture f(test::g41(5));
  f.feed(f.prog.line(14, 0, 0));
  f.feed(f.prog.line(15, 50, 0));
  f.feed(f.prog.arc(16, Motion::G3, 70, 20, 50, 20));
  f.feed(f.prog.line(17, 70, 50));
  f.retract(18, 60, 60);
  ASSERT_EQ(f.out.blocks.size(), 5u);
  expectRow(f.out.blocks[1], 15, Motion::G1, 50, 5);
  expectRow(f.out.blocks[2], 16, Motion::G3, 65, 20);
  expectVec(f.out.blocks[2].start, 50, 5, 0);
  expectVec(f.out.blocks[2].centre, 50, 20, 0);
  expectRow(f.out.blocks[3], 17, Motion::G1, 65, 50);
  expectVec(f.out.blocks[3].start, 65, 20, 0);
  expectRow(f.out.blocks[4], 18, Motion::G1, 60, 60);
  EXPECT_TRUE(f.out.warnings.empty());
}

TEST(Corners, ElementsWaitForTheLookAhead) {
  // An element is written only once no later block can change it: with MD20240 = 3 (the
  // default) block k may still reach back to element k - 3. The corner circle is written with
  // the element it belongs to.
  Fixture f(test::g41(5));
  f.feed(f.prog.line(18, 0, 0));   // selection: waits for the first element
  f.feed(f.prog.line(19, 50, 0));  // element 1 (the approach line is element 0)
  f.feed(f.prog.line(20, 50, -40));
  EXPECT_TRUE(f.out.blocks.empty());
  f.feed(f.prog.line(21, 0, -40));  // element 3: element 0 is out of reach
  ASSERT_EQ(f.out.blocks.size(), 1u);
  expectRow(f.out.blocks[0], 18, Motion::G1, 0, 5);
  f.feed(f.prog.line(22, 0, -80));  // element 4: element 1 too
  ASSERT_EQ(f.out.blocks.size(), 2u);
  expectRow(f.out.blocks[1], 19, Motion::G1, 50, 5);
  f.retract(23, -10, -90);
  ASSERT_EQ(f.out.blocks.size(), 8u);  // + the circle and lines 20, 21 (with its circle), 22, 23
  expectRow(f.out.blocks[2], 20, Motion::G2, 55, 0);
  expectRow(f.out.blocks[7], 23, Motion::G1, -10, -90);
}

}  // namespace
}  // namespace ncoffset::trc
