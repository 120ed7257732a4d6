// The DISC transition curve (details Q3 model [D]): circle at DISC = 0, overshoot
// o = R + DISC/100 (|PS| - R) at its middle, tangent to both equidistants, chords within the
// tolerance, and the corner A - S - B at DISC = 100.
#include "geom/disc_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ncoffset::geom {
namespace {

// A 90 degree outside corner at P = (0, 50) for G41 with R = 5: the first line runs up x = 0,
// the second to the right along y = 50; equidistants x = -5 and y = 55.
const Vec2 kP{0, 50}, kA{-5, 50}, kB{0, 55}, kTa{0, 1}, kTb{1, 0};

TEST(DiscCurve, ZeroIsTheCircle) {
  auto c = discCurve(kA, kTa, kB, kTb, kP, 0);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->w, std::cos(M_PI / 4), 1e-12);  // the rational circle weight cos(delta/2)
  for (double t = 0; t <= 1; t += 0.05) EXPECT_NEAR(length(c->at(t) - kP), 5, 1e-12) << t;
}

TEST(DiscCurve, OvershootAtTheMiddle) {
  for (double disc : {20.0, 50.0, 75.0}) {
    auto c = discCurve(kA, kTa, kB, kTb, kP, disc);
    ASSERT_TRUE(c);
    // |PS| = R / cos(45 deg) = 7.0710678; o = 5 + disc/100 * 2.0710678.
    const double o = 5 + disc / 100 * (5 * std::sqrt(2.0) - 5);
    EXPECT_NEAR(length(c->at(0.5) - kP), o, 1e-12) << disc;
    EXPECT_NEAR(c->s.a, -5, 1e-12);
    EXPECT_NEAR(c->s.o, 55, 1e-12);
    // Ends on the equidistants, tangent to them: the first step leaves along ta, the last
    // arrives along tb.
    EXPECT_NEAR(length(c->at(0) - kA), 0, 1e-12);
    EXPECT_NEAR(length(c->at(1) - kB), 0, 1e-12);
    const Vec2 d0 = c->at(1e-7) - kA, d1 = kB - c->at(1 - 1e-7);
    EXPECT_NEAR(cross(d0, kTa) / length(d0), 0, 1e-6);
    EXPECT_NEAR(cross(d1, kTb) / length(d1), 0, 1e-6);
  }
}

TEST(DiscCurve, ChordsWithinTolerance) {
  auto c = discCurve(kA, kTa, kB, kTb, kP, 50);
  ASSERT_TRUE(c);
  auto pts = chords(*c, 1e-3);
  ASSERT_FALSE(pts.empty());
  EXPECT_NEAR(length(pts.back() - kB), 0, 1e-12);
  Vec2 prev = kA;
  for (const Vec2& q : pts) {
    EXPECT_GT(length(q - prev), 0);
    prev = q;
  }
  // A dense check: every curve point is within 1e-3 of some chord.
  for (double t = 0; t <= 1; t += 1e-4) {
    Vec2 x = c->at(t);
    double best = 1e300;
    Vec2 from = kA;
    for (const Vec2& q : pts) {
      Vec2 d = q - from;
      double u = std::fmax(0, std::fmin(1, dot(x - from, d) / dot(d, d)));
      best = std::fmin(best, length(x - (from + u * d)));
      from = q;
    }
    EXPECT_LE(best, 1e-3 + 1e-12) << t;
  }
}

TEST(DiscCurve, HundredIsTheCorner) {
  auto c = discCurve(kA, kTa, kB, kTb, kP, 100);
  ASSERT_TRUE(c);
  auto pts = chords(*c, 1e-3);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_NEAR(pts[0].a, -5, 1e-12);
  EXPECT_NEAR(pts[0].o, 55, 1e-12);
}

TEST(DiscCurve, ReversalHasNoCurve) {
  EXPECT_FALSE(discCurve({5, 0}, {0, 1}, {-5, 0}, {0, -1}, {0, 0}, 50));
}

}  // namespace
}  // namespace ncoffset::geom
