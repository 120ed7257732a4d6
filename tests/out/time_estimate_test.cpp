// The time estimate of the HTML report (src/out/time_estimate.hpp): each block a trapezoid from
// standstill to standstill. The expected values by hand:
//  * t(L, v, a) = L/v + v/a when L >= v^2/a (accelerate v/a s over v^2/2a mm, the same braking),
//    else 2 sqrt(L/a) (a triangle);
//  * rapid traverse: the path velocity the axes allow, min over moving axes of vmax_i / |dir_i|;
//    the acceleration the same way with amax_i.
#include "out/time_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::lineSeg;

TEST(TimeEstimate, Trapezoid) {
  // 100 mm at 100 mm/s with 1000 mm/s2: v^2/a = 10 mm <= 100: 1 s + 0.1 s.
  EXPECT_NEAR(trapezoidSeconds(100, 100, 1000), 1.1, 1e-12);
  // 4 mm: v is never reached: 2 sqrt(4 / 1000) = 0.126491 s.
  EXPECT_NEAR(trapezoidSeconds(4, 100, 1000), 2 * std::sqrt(0.004), 1e-12);
  EXPECT_EQ(trapezoidSeconds(0, 100, 1000), 0);
}

TEST(TimeEstimate, FeedAndRapidWithTheDefaults) {
  TimeEstimate t;  // MD32000 10000 mm/min = 166.667 mm/s, MD32300 1 m/s2 = 1000 mm/s2
  // G1 X100 F6000: 100 mm/s: 1.1 s (above); without acceleration 1 s.
  t.segment(lineSeg(1, Motion::G1, {0, 0, 0}, {100, 0, 0}, 6000));
  EXPECT_NEAR(t.seconds(), 1.1, 1e-9);
  EXPECT_NEAR(t.secondsNoAccel(), 1.0, 1e-9);
  // G0 X100 Y100 from X0 Y0: dir (0.7071, 0.7071): v = 166.667 / 0.7071 = 235.70 mm/s,
  // a = 1000 / 0.7071 = 1414.2 mm/s2, L = 141.42 mm: 0.6 s + 0.16667 s = 0.76667 s.
  t.segment(lineSeg(2, Motion::G0, {0, 0, 0}, {100, 100, 0}));
  EXPECT_NEAR(t.rapidSeconds(), 0.6 + 1.0 / 6, 1e-9);
  EXPECT_NEAR(t.seconds(), 1.1 + 0.6 + 1.0 / 6, 1e-9);
}

TEST(TimeEstimate, AxisDataOfTheMachine) {
  TimeEstimate t;
  AxisDynamics d;
  d.max_velocity = {30000, 30000, 12000};  // mm/min: Z 200 mm/s
  d.max_acceleration = {2, 2, 0.5};        // m/s2: Z 500 mm/s2
  t.setDynamics(d);
  // G0 Z-50: 200 mm/s, 500 mm/s2: v^2/a = 80 mm > 50: a triangle, 2 sqrt(50/500) = 0.63246 s.
  t.segment(lineSeg(1, Motion::G0, {0, 0, 0}, {0, 0, -50}));
  EXPECT_NEAR(t.seconds(), 2 * std::sqrt(0.1), 1e-9);
  // A feed above what the axes allow is limited: F60000 along X: 500 mm/s, a 2000 mm/s2,
  // 500 mm: 500/500 + 500/2000 = 1.25 s.
  t.segment(lineSeg(2, Motion::G1, {0, 0, 0}, {500, 0, 0}, 60000));
  EXPECT_NEAR(t.seconds(), 2 * std::sqrt(0.1) + 1.25, 1e-9);
}

TEST(TimeEstimate, FeedPerRevolutionInverseTimeAndDwell) {
  TimeEstimate t;
  Segment s = lineSeg(1, Motion::G1, {0, 0, 0}, {0, 0, -30}, 0.2);
  s.feed_unit = FeedUnit::MmPerRev;
  t.segment(s);  // no spindle speed yet: not estimated
  EXPECT_EQ(t.blocksWithoutSpeed(), 1);
  EXPECT_EQ(t.seconds(), 0);
  t.spindle({1, 0, 1500, 0});  // S1500: 0.2 mm/rev = 300 mm/min = 5 mm/s
  t.segment(s);                // 30 mm: 6 s + 5/1000 s
  EXPECT_NEAR(t.seconds(), 6.005, 1e-9);
  // G93 F2: the block takes 1/2 min = 30 s (10 mm at 0.3333 mm/s, a = 1000: + 0.000333 s).
  Segment g93 = lineSeg(2, Motion::G1, {0, 0, 0}, {10, 0, 0}, 2);
  g93.feed_unit = FeedUnit::InverseTime;
  t.segment(g93);
  EXPECT_NEAR(t.seconds(), 6.005 + 30 + (10.0 / 30) / 1000, 1e-9);
  // G4 F2.5 and G4 S10 (10 revolutions at 1500/min = 0.4 s).
  t.dwell({3, 0, 2.5, 0});
  t.dwell({4, 0, 0, 10});
  EXPECT_NEAR(t.dwellSeconds(), 2.9, 1e-12);
}

}  // namespace
}  // namespace ncoffset::out
