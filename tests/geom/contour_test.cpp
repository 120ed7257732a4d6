// Plane contour primitives of radius compensation (src/geom/contour.hpp): tangents, sweeps,
// equidistants of lines and arcs, intersections with their parameters, the nearest-crossing
// rule, boxes, and the KONT tangent point. Expected values by hand; where a golden case of
// tests/programs/trc/ derives the same numbers, its name is given.
#include "geom/contour.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "elements.hpp"

namespace ncoffset::geom {
namespace {

constexpr double kTol = 1e-12;

using test::arc;
using test::line;

void expectPoint(Vec2 p, double a, double o, double tol = kTol) {
  EXPECT_NEAR(p.a, a, tol);
  EXPECT_NEAR(p.o, o, tol);
}

// The G3 of tangent_line_arc_line_g17_g41: (50,0) -> (70,20) about (50,20), r = 20.
const Element kQuarter = arc({50, 0}, {70, 20}, {50, 20}, true);

TEST(Contour, TangentsAndSweep) {
  const Element l = line({0, 0}, {30, 40});
  expectPoint(l.startTangent(), 0.6, 0.8);
  expectPoint(l.endTangent(), 0.6, 0.8);
  EXPECT_EQ(l.sweep(), 0);
  // Start angle 270 deg: tangent (1,0), tangent to the line before it; end angle 0: (0,1).
  expectPoint(kQuarter.startTangent(), 1, 0);
  expectPoint(kQuarter.endTangent(), 0, 1);
  EXPECT_NEAR(kQuarter.sweep(), M_PI / 2, kTol);
  EXPECT_NEAR(kQuarter.radius(), 20, kTol);
  // The same arc the other way round is clockwise: negative sweep of the other three quarters.
  const Element cw = arc({50, 0}, {70, 20}, {50, 20}, false);
  EXPECT_NEAR(cw.sweep(), -3 * M_PI / 2, kTol);
  expectPoint(cw.startTangent(), -1, 0);
  // End on start: a full circle; TURN= adds whole revolutions.
  Element full = arc({10, 0}, {10, 0}, {0, 0}, true);
  EXPECT_NEAR(full.sweep(), 2 * M_PI, kTol);
  full.turns = 1;
  EXPECT_NEAR(full.sweep(), 4 * M_PI, kTol);
  expectPoint(tangentAt(kQuarter, {50 + 20 * std::cos(-M_PI / 4), 20 + 20 * std::sin(-M_PI / 4)}),
              std::sqrt(0.5), std::sqrt(0.5));
}

TEST(Contour, UnitAndAngle) {
  expectPoint(unit({3, -4}), 0.6, -0.8);
  expectPoint(unit({0, 0}), 1, 0);  // a degenerate element still has a direction
  EXPECT_NEAR(angleDeg({1, 0}, {0, -1}), 90, kTol);
  EXPECT_NEAR(angleDeg({1, 0}, {1, 0}), 0, kTol);
  EXPECT_NEAR(angleDeg({1, 0}, {-1, 0}), 180, kTol);
  // kont_g450_pm_example: the deflection N40/N50, t1 = (0,1), t2 = (0.8,-0.6): acos(-0.6).
  EXPECT_NEAR(angleDeg({0, 1}, {0.8, -0.6}), 126.869897645844, 1e-9);
}

TEST(Contour, EquidistantOfALine) {
  // g450_line_line_g17_g41: (0,0) -> (50,0) with G41, R = 5: o = 5; G42 (d < 0): o = -5.
  auto left = equidistant(line({0, 0}, {50, 0}), 5);
  ASSERT_TRUE(left);
  expectPoint(left->p0, 0, 5);
  expectPoint(left->p1, 50, 5);
  auto right = equidistant(line({0, 0}, {50, 0}), -5);
  ASSERT_TRUE(right);
  expectPoint(right->p0, 0, -5);
  expectPoint(right->p1, 50, -5);
  // (50,0) -> (50,-40), t = (0,-1), n_L = (1,0): a = 55.
  auto down = equidistant(line({50, 0}, {50, -40}), 5);
  ASSERT_TRUE(down);
  expectPoint(down->p0, 55, 0);
  expectPoint(down->p1, 55, -40);
}

TEST(Contour, EquidistantOfAnArc) {
  // tangent_line_arc_line_g17_g41: G41 is the inside of the G3, radius 20 - 5 = 15.
  auto inside = equidistant(kQuarter, 5);
  ASSERT_TRUE(inside);
  EXPECT_TRUE(inside->arc);
  expectPoint(inside->c, 50, 20);
  expectPoint(inside->p0, 50, 5);
  expectPoint(inside->p1, 65, 20);
  EXPECT_NEAR(inside->radius(), 15, kTol);
  // G42: the outside, radius 25.
  auto outside = equidistant(kQuarter, -5);
  ASSERT_TRUE(outside);
  expectPoint(outside->p0, 50, -5);
  expectPoint(outside->p1, 75, 20);
  // A G2 (cw) arc: its left is the outside, r + d.
  auto cw = equidistant(arc({0, 10}, {10, 0}, {0, 0}, false), 5);
  ASSERT_TRUE(cw);
  expectPoint(cw->p0, 0, 15);
  expectPoint(cw->p1, 15, 0);
  // An inside arc smaller than R has no equidistant (inside_arc_radius_too_small).
  EXPECT_FALSE(equidistant(arc({4, 0}, {0, 4}, {0, 0}, true), 5));
  EXPECT_FALSE(equidistant(arc({5, 0}, {0, 5}, {0, 0}, true), 5));  // radius 0: none either
}

TEST(Contour, LineLineIntersection) {
  // inside_line_line_g17_g41: o = 5 (x 0..50) and a = 45 (y 0..40) meet at S = (45,5).
  const auto xs = intersect(line({0, 5}, {50, 5}), line({45, 0}, {45, 40}));
  ASSERT_EQ(xs.size(), 1u);
  expectPoint(xs[0].p, 45, 5);
  EXPECT_NEAR(xs[0].u1, 0.9, kTol);
  EXPECT_NEAR(xs[0].u2, 0.125, kTol);
  // g451_line_line_g17_g41: the extensions meet at (55,5): beyond the end of the first line
  // (u1 = 1.1), before the start of the second (u2 = -0.125).
  const auto ext = intersect(line({0, 5}, {50, 5}), line({55, 0}, {55, -40}));
  ASSERT_EQ(ext.size(), 1u);
  expectPoint(ext[0].p, 55, 5);
  EXPECT_NEAR(ext[0].u1, 1.1, kTol);
  EXPECT_NEAR(ext[0].u2, -0.125, kTol);
  // Parallel lines do not meet.
  EXPECT_TRUE(intersect(line({0, 5}, {50, 5}), line({0, 1}, {4, 1})).empty());
}

TEST(Contour, LineCircleIntersection) {
  // The line y = 0 through the circle about (5,0), r = 3: (2,0) and (8,0), u = 0.2 and 0.8.
  const Element half = arc({8, 0}, {2, 0}, {5, 0}, true);  // the upper half, ccw
  const auto xs = intersect(line({0, 0}, {10, 0}), half);
  ASSERT_EQ(xs.size(), 2u);
  expectPoint(xs[0].p, 2, 0);
  EXPECT_NEAR(xs[0].u1, 0.2, kTol);
  EXPECT_NEAR(xs[0].u2, 1, kTol);  // the arc's end
  expectPoint(xs[1].p, 8, 0);
  EXPECT_NEAR(xs[1].u1, 0.8, kTol);
  EXPECT_NEAR(xs[1].u2, 0, kTol);  // the arc's start
  // The order of the arguments only swaps the parameters.
  const auto swapped = intersect(half, line({0, 0}, {10, 0}));
  ASSERT_EQ(swapped.size(), 2u);
  EXPECT_NEAR(swapped[0].u1, 1, kTol);
  EXPECT_NEAR(swapped[0].u2, 0.2, kTol);
  // A tangent line touches once; a line farther away misses.
  const auto touch = intersect(line({0, 3}, {10, 3}), half);
  ASSERT_EQ(touch.size(), 1u);
  expectPoint(touch[0].p, 5, 3);
  EXPECT_NEAR(touch[0].u2, 0.5, kTol);
  EXPECT_TRUE(intersect(line({0, 4}, {10, 4}), half).empty());
}

TEST(Contour, CircleCircleIntersection) {
  // Circles of radius 5 about (0,0) and (8,0) meet at (4,3) and (4,-3).
  const Element a = fullCircle({0, 0}, 5), b = fullCircle({8, 0}, 5);
  const auto xs = intersect(a, b);
  ASSERT_EQ(xs.size(), 2u);
  expectPoint(xs[0].p, 4, 3, 1e-12);
  expectPoint(xs[1].p, 4, -3, 1e-12);
  // On a full circle every point has a parameter in [0, 1]: (4,3) lies at atan2(3,4)/(2 pi).
  EXPECT_NEAR(xs[0].u1, std::atan2(3.0, 4.0) / (2 * M_PI), kTol);
  EXPECT_NEAR(xs[1].u1, 1 - std::atan2(3.0, 4.0) / (2 * M_PI), kTol);
  for (const Crossing& x : xs) {
    EXPECT_GE(x.u1, 0);
    EXPECT_LE(x.u1, 1);
  }
  EXPECT_TRUE(intersect(a, fullCircle({0, 0}, 3)).empty());   // concentric
  EXPECT_TRUE(intersect(a, fullCircle({20, 0}, 5)).empty());  // apart
}

TEST(Contour, ToleranceWindowsAreInMillimetres) {
  // tol::onElement: from kPoint before the start to kPoint beyond the end, whatever the length.
  EXPECT_TRUE(tol::onElement(1 + 0.9e-6 / 33, 33));
  EXPECT_FALSE(tol::onElement(1 + 1.1e-6 / 33, 33));
  EXPECT_TRUE(tol::onElement(-0.9e-6 / 0.5, 0.5));
  EXPECT_FALSE(tol::onElement(-1.1e-6 / 0.5, 0.5));
  EXPECT_TRUE(tol::insideElement(0.5, 1));
  EXPECT_FALSE(tol::insideElement(0.9e-6, 1));
  EXPECT_TRUE(tol::pastEnd(1 - 0.9e-6 / 10, 10));
  EXPECT_FALSE(tol::pastEnd(1 - 1.1e-6 / 10, 10));
  // The crossing carries the lengths: a 33 mm line and the quarter circle of radius 20.
  const auto xs = intersect(line({0, 5}, {33, 5}), kQuarter);
  ASSERT_FALSE(xs.empty());
  EXPECT_NEAR(xs[0].len1, 33, kTol);
  EXPECT_NEAR(xs[0].len2, 20 * M_PI / 2, 1e-12);
}

TEST(Contour, ALinePassingACircleWithinKPointTouchesIt) {
  const Element half = arc({8, 0}, {2, 0}, {5, 0}, true);  // r = 3 about (5,0)
  const auto touch = intersect(line({0, 3 + 0.5e-6}, {10, 3 + 0.5e-6}), half);
  ASSERT_EQ(touch.size(), 1u);
  expectPoint(touch[0].p, 5, 3 + 0.5e-6);
  EXPECT_TRUE(intersect(line({0, 3 + 2e-6}, {10, 3 + 2e-6}), half).empty());
}

TEST(Contour, AnArcEqualToRHasNoEquidistant) {
  // r = R within kPoint: none (trc3/fillet_r_eq_R_*); r = R + 1e-4: a circle of radius 1e-4.
  EXPECT_FALSE(equidistant(arc({5, 0}, {0, 5}, {0, 0}, true), 5 - 0.5e-6));
  auto small = equidistant(arc({5.0001, 0}, {0, 5.0001}, {0, 0}, true), 5);
  ASSERT_TRUE(small);
  EXPECT_NEAR(small->radius(), 1e-4, 1e-12);
}

TEST(Contour, ASpiralsEquidistantKeepsDFromBothEnds) {
  // An arc from (10,0) to (0,10.002) about (0,0): start radius 10, end radius 10.002 (the end
  // point rounded, within MD21000). Its equidistant at 2 to the left (inside of the G3): radius 8
  // at the start, 8.002 at the end, each end on its own normal.
  const Element sp = arc({10, 0}, {0, 10.002}, {0, 0}, true);
  auto eq = equidistant(sp, 2);
  ASSERT_TRUE(eq);
  expectPoint(eq->p0, 8, 0);
  expectPoint(eq->p1, 0, 8.002);
  // A crossing with the spiral is on it: the line x = y meets the spiral at 45 degrees, half
  // way, where its radius is 10.001: (10.001/sqrt 2, 10.001/sqrt 2).
  const auto xs = intersect(line({0, 0}, {20, 20}), sp);
  ASSERT_FALSE(xs.empty());
  const double h = 10.001 / std::sqrt(2.0);
  expectPoint(xs.back().p, h, h, 1e-9);
  EXPECT_NEAR(xs.back().u2, 0.5, 1e-9);
}

TEST(Contour, PointAt) {
  expectPoint(pointAt(line({0, 0}, {10, 20}), 0.25), 2.5, 5);
  expectPoint(pointAt(kQuarter, 0.5), 50 + 20 * std::sqrt(0.5), 20 - 20 * std::sqrt(0.5), 1e-12);
  expectPoint(pointAt(kQuarter, 1), 70, 20, 1e-12);
}

TEST(Contour, NearestCrossingTakesTheLeastKey) {
  // The two crossings (4,-3) and (4,3) of the circles above.
  const Element a = fullCircle({0, 0}, 5), b = fullCircle({8, 0}, 5);
  auto all = [](const Crossing&) { return true; };
  // Nearest a point: (4,3) is nearer (0,10).
  auto near_top = nearestCrossing(a, b, all, [](const Crossing& x) {
    return length(x.p - Vec2{0, 10});
  });
  ASSERT_TRUE(near_top);
  expectPoint(near_top->p, 4, 3, 1e-12);
  // The least u1 on `a` (start at (5,0), ccw): (4,3) at 0.102, (4,-3) at 0.898.
  auto first_on_a = nearestCrossing(a, b, all, [](const Crossing& x) { return x.u1; });
  ASSERT_TRUE(first_on_a);
  expectPoint(first_on_a->p, 4, 3, 1e-12);
  // The greatest u1 (key -u1): (4,-3).
  auto last_on_a = nearestCrossing(a, b, all, [](const Crossing& x) { return -x.u1; });
  ASSERT_TRUE(last_on_a);
  expectPoint(last_on_a->p, 4, -3, 1e-12);
  // Only what `accept` takes counts; nothing accepted: none.
  auto lower = nearestCrossing(
      a, b, [](const Crossing& x) { return x.p.o < 0; }, [](const Crossing& x) { return x.u1; });
  ASSERT_TRUE(lower);
  expectPoint(lower->p, 4, -3, 1e-12);
  EXPECT_FALSE(nearestCrossing(
      a, b, [](const Crossing&) { return false; }, [](const Crossing& x) { return x.u1; }));
  // Equal keys: the first found.
  auto tie = nearestCrossing(a, b, all, [](const Crossing&) { return 1.0; });
  ASSERT_TRUE(tie);
  expectPoint(tie->p, intersect(a, b)[0].p.a, intersect(a, b)[0].p.o);
}

TEST(Contour, Boxes) {
  const Box l(line({10, 5}, {-2, 7}));
  EXPECT_EQ(l.lo_a, -2);
  EXPECT_EQ(l.hi_a, 10);
  EXPECT_EQ(l.lo_o, 5);
  EXPECT_EQ(l.hi_o, 7);
  // An arc's box is that of its whole circle (so of every trimmed part of it).
  const Box c(kQuarter);
  EXPECT_NEAR(c.lo_a, 30, kTol);
  EXPECT_NEAR(c.hi_a, 70, kTol);
  EXPECT_NEAR(c.lo_o, 0, kTol);
  EXPECT_NEAR(c.hi_o, 40, kTol);
  EXPECT_FALSE(l.overlaps(c));  // a = 10 ends before the circle's box starts at 30
  const Box crossing(line({60, 30}, {90, 50}));
  EXPECT_TRUE(crossing.overlaps(c));
  EXPECT_TRUE(c.overlaps(crossing));
  // Touching boxes overlap, and so do boxes 1e-6 apart (the slack); farther apart they do not.
  const Box right(line({70, 0}, {80, 1}));
  EXPECT_TRUE(c.overlaps(right));
  const Box slack(line({70 + 1e-6, 0}, {80, 1}));
  EXPECT_TRUE(c.overlaps(slack));
  const Box apart(line({70.01, 0}, {80, 1}));
  EXPECT_FALSE(c.overlaps(apart));
  EXPECT_FALSE(apart.overlaps(c));
}

TEST(Contour, FullCircle) {
  const Element f = fullCircle({1, 2}, 3);
  EXPECT_TRUE(f.arc);
  expectPoint(f.p0, 4, 2);
  expectPoint(f.p1, 4, 2);
  EXPECT_NEAR(f.sweep(), 2 * M_PI, kTol);
}

TEST(Contour, TangentPoint) {
  // kont_g450_pm_example, approach: from P0 = (35,0) to the circle about P1 = (10,10), R = 5,
  // with P1 on the right (G41): T = (9.037413, 5.093532).
  auto t = tangentPoint({35, 0}, {10, 10}, 5, 1, true);
  ASSERT_TRUE(t);
  expectPoint(*t, 9.037412889, 5.093532222, 1e-9);
  // The same circle, G42 (on the left): the other tangent point, mirrored in the line P0 P1.
  auto other = tangentPoint({35, 0}, {10, 10}, 5, -1, true);
  ASSERT_TRUE(other);
  EXPECT_NEAR(length(*other - Vec2{10, 10}), 5, 1e-12);
  EXPECT_GT(length(*other - *t), 1);
  // Retraction: the line from T2 to P2 = (-20,50) with Pe = (10,10) on the right: T2 =
  // (5.720050, 7.415038).
  auto t2 = tangentPoint({-20, 50}, {10, 10}, 5, 1, false);
  ASSERT_TRUE(t2);
  expectPoint(*t2, 5.720050252, 7.415037689, 1e-9);
  // A point inside the circle has no tangent (kont_start_inside_circle: alarm 10755).
  EXPECT_FALSE(tangentPoint({12, 11}, {10, 10}, 5, 1, true));
}

}  // namespace
}  // namespace ncoffset::geom
