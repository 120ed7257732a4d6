// Circle programming (src/geom/arc.hpp): centre, CR=, AR=, full circle, end point tolerance
// (MD21000/MD21010, alarm 14040) and under/over-determined circles (alarm 14045).
#include "geom/arc.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "ncoffset/alarm.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset::geom {
namespace {

constexpr double kTol = 1e-9;

ArcRequest request(Vec2 start, bool ccw) {
  ArcRequest r;
  r.start = start;
  r.ccw = ccw;
  return r;
}

int alarmOf(const ArcRequest& r) {
  try {
    solveArc(r);
  } catch (const AlarmError& e) {
    return e.number();
  }
  return 0;
}

void expectPoint(Vec2 got, double a, double o, double tol = kTol) {
  EXPECT_NEAR(got.a, a, tol);
  EXPECT_NEAR(got.o, o, tol);
}

// Signed sweep from start to end about centre in the direction of the arc (degrees, 0..360].
double sweep(Vec2 start, Vec2 end, Vec2 c, bool ccw) {
  double s = std::atan2(start.o - c.o, start.a - c.a);
  double e = std::atan2(end.o - c.o, end.a - c.a);
  double d = (ccw ? e - s : s - e) * 180 / 3.14159265358979323846;
  while (d <= 1e-9) d += 360;
  while (d > 360 + 1e-9) d -= 360;
  return d;
}

TEST(SolveArc, Centre) {
  ArcRequest r = request({0, 0}, true);
  r.end = Vec2{10, 0};
  r.centre = Vec2{5, 0};
  ArcSolution s = solveArc(r);
  expectPoint(s.centre, 5, 0);
  expectPoint(s.end, 10, 0);
  EXPECT_NEAR(s.radius, 5, kTol);
}

TEST(SolveArc, FullCircleWithCentre) {
  ArcRequest r = request({0, 0}, false);
  r.centre = Vec2{5, 0};
  ArcSolution s = solveArc(r);  // no end point: back to the start
  expectPoint(s.end, 0, 0);
  expectPoint(s.centre, 5, 0);
  EXPECT_NEAR(s.radius, 5, kTol);
  r.end = Vec2{0, 0};
  expectPoint(solveArc(r).end, 0, 0);
}

TEST(SolveArc, RadiusPositiveUpTo180Degrees) {
  // Chord 8, radius 5: centre 3 off the chord's middle.
  ArcRequest cw = request({0, 0}, false);
  cw.end = Vec2{8, 0};
  cw.cr = 5;
  ArcSolution s = solveArc(cw);
  expectPoint(s.centre, 4, -3);
  EXPECT_NEAR(s.radius, 5, kTol);
  EXPECT_LT(sweep(cw.start, s.end, s.centre, false), 180);

  ArcRequest ccw = cw;
  ccw.ccw = true;
  s = solveArc(ccw);
  expectPoint(s.centre, 4, 3);
  EXPECT_LT(sweep(ccw.start, s.end, s.centre, true), 180);
}

TEST(SolveArc, RadiusNegativeBeyond180Degrees) {
  ArcRequest cw = request({0, 0}, false);
  cw.end = Vec2{8, 0};
  cw.cr = -5;
  ArcSolution s = solveArc(cw);
  expectPoint(s.centre, 4, 3);
  EXPECT_NEAR(s.radius, 5, kTol);
  EXPECT_GT(sweep(cw.start, s.end, s.centre, false), 180);

  ArcRequest ccw = cw;
  ccw.ccw = true;
  s = solveArc(ccw);
  expectPoint(s.centre, 4, -3);
  EXPECT_GT(sweep(ccw.start, s.end, s.centre, true), 180);
}

TEST(SolveArc, RadiusInAnyDirection) {
  // Chord along -Y from (10,10) to (10,2), CR=5, G3: centre left of the travel direction.
  ArcRequest r = request({10, 10}, true);
  r.end = Vec2{10, 2};
  r.cr = 5;
  ArcSolution s = solveArc(r);
  expectPoint(s.centre, 13, 6);
  EXPECT_NEAR(std::hypot(s.end.a - s.centre.a, s.end.o - s.centre.o), 5, kTol);
  EXPECT_NEAR(std::hypot(r.start.a - s.centre.a, r.start.o - s.centre.o), 5, kTol);
}

TEST(SolveArc, RadiusHalfCircle) {
  ArcRequest r = request({0, 0}, true);
  r.end = Vec2{10, 0};
  r.cr = 5;
  expectPoint(solveArc(r).centre, 5, 0);
  r.cr = -5;
  expectPoint(solveArc(r).centre, 5, 0);
}

TEST(SolveArc, RadiusTooSmallForTheChord) {
  ArcRequest r = request({0, 0}, true);
  r.end = Vec2{10.005, 0};  // within the 0.01 tolerance: accepted as a half circle
  r.cr = 5;
  ArcSolution s = solveArc(r);
  expectPoint(s.centre, 5.0025, 0);
  r.end = Vec2{10.1, 0};
  EXPECT_EQ(alarmOf(r), toInt(AlarmNumber::CircleEndPoint));
}

TEST(SolveArc, OpeningAngleWithEndPoint) {
  ArcRequest r = request({0, 0}, true);
  r.end = Vec2{10, 0};
  r.ar = 90;
  ArcSolution s = solveArc(r);
  expectPoint(s.centre, 5, 5);
  EXPECT_NEAR(s.radius, std::sqrt(50.0), kTol);
  EXPECT_NEAR(sweep(r.start, s.end, s.centre, true), 90, 1e-9);

  r.ccw = false;
  s = solveArc(r);
  expectPoint(s.centre, 5, -5);
  EXPECT_NEAR(sweep(r.start, s.end, s.centre, false), 90, 1e-9);

  r.ccw = true;
  r.ar = 270;
  s = solveArc(r);
  expectPoint(s.centre, 5, -5);
  EXPECT_NEAR(sweep(r.start, s.end, s.centre, true), 270, 1e-9);

  r.ar = 180;
  s = solveArc(r);
  expectPoint(s.centre, 5, 0);
}

TEST(SolveArc, OpeningAngleWithCentre) {
  ArcRequest r = request({10, 0}, true);
  r.centre = Vec2{0, 0};
  r.ar = 90;
  ArcSolution s = solveArc(r);
  expectPoint(s.end, 0, 10);
  EXPECT_NEAR(s.radius, 10, kTol);

  r.ccw = false;
  expectPoint(solveArc(r).end, 0, -10);

  r.ar = 360;  // a full circle by angle
  expectPoint(solveArc(r).end, 10, 0);
}

TEST(SolveArc, EndPointTolerance) {
  ArcRequest r = request({10, 0}, true);
  r.centre = Vec2{0, 0};
  r.end = Vec2{0, 10.009};  // tolerance max(0.01, 0.001 * 10) = 0.01
  EXPECT_EQ(alarmOf(r), 0);
  EXPECT_NEAR(solveArc(r).radius, 10, kTol);  // radius from the start point
  r.end = Vec2{0, 10.011};
  EXPECT_EQ(alarmOf(r), toInt(AlarmNumber::CircleEndPoint));
  r.end = Vec2{0, 9.989};
  EXPECT_EQ(alarmOf(r), toInt(AlarmNumber::CircleEndPoint));

  // Large radius: the factor dominates (0.001 * 100 = 0.1).
  ArcRequest big = request({100, 0}, false);
  big.centre = Vec2{0, 0};
  big.end = Vec2{0, -100.09};
  EXPECT_EQ(alarmOf(big), 0);
  big.end = Vec2{0, -100.11};
  EXPECT_EQ(alarmOf(big), toInt(AlarmNumber::CircleEndPoint));

  // Machine data change the tolerance.
  r.end = Vec2{0, 10.05};
  r.tol_const = 0.1;
  EXPECT_EQ(alarmOf(r), 0);
  r.tol_const = 0.001;
  r.tol_factor = 0;
  r.end = Vec2{0, 10.002};
  EXPECT_EQ(alarmOf(r), toInt(AlarmNumber::CircleEndPoint));
}

TEST(SolveArc, NotDefined14045) {
  ArcRequest none = request({0, 0}, true);
  none.end = Vec2{10, 0};
  EXPECT_EQ(alarmOf(none), toInt(AlarmNumber::CircleProgramming));

  ArcRequest cr_centre = none;
  cr_centre.cr = 5;
  cr_centre.centre = Vec2{5, 0};
  EXPECT_EQ(alarmOf(cr_centre), toInt(AlarmNumber::CircleProgramming));

  ArcRequest cr_ar = none;
  cr_ar.cr = 5;
  cr_ar.ar = 90;
  EXPECT_EQ(alarmOf(cr_ar), toInt(AlarmNumber::CircleProgramming));

  ArcRequest ar_centre_end = none;
  ar_centre_end.ar = 90;
  ar_centre_end.centre = Vec2{5, 5};
  EXPECT_EQ(alarmOf(ar_centre_end), toInt(AlarmNumber::CircleProgramming));

  ArcRequest cr_no_end = request({0, 0}, true);
  cr_no_end.cr = 5;
  EXPECT_EQ(alarmOf(cr_no_end), toInt(AlarmNumber::CircleProgramming));

  ArcRequest cr_full = request({0, 0}, true);
  cr_full.end = Vec2{0, 0};
  cr_full.cr = 5;
  EXPECT_EQ(alarmOf(cr_full), toInt(AlarmNumber::CircleProgramming));

  ArcRequest cr_zero = none;
  cr_zero.cr = 0;
  EXPECT_EQ(alarmOf(cr_zero), toInt(AlarmNumber::CircleProgramming));

  ArcRequest centre_at_start = none;
  centre_at_start.centre = Vec2{0, 0};
  EXPECT_EQ(alarmOf(centre_at_start), toInt(AlarmNumber::CircleProgramming));

  for (double ar : {0.0, 360.0, -90.0, 400.0}) {
    ArcRequest bad_ar = none;
    bad_ar.ar = ar;
    EXPECT_EQ(alarmOf(bad_ar), toInt(AlarmNumber::CircleProgramming)) << ar;
  }

  ArcRequest ar_full = request({0, 0}, true);
  ar_full.end = Vec2{0, 0};
  ar_full.ar = 90;
  EXPECT_NE(alarmOf(ar_full), 0);
}

// maxOf is std::fmax bit for bit (solveArc's tolerance and its root): ordinary values, equal
// values of either sign, infinities and NaN in either place. Through volatile, so the compiler
// cannot fold the library call with its own rules.
TEST(SolveArc, MaxOfIsFmax) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double values[] = {0.0, -0.0, 1.0, -1.0, 0.01, 0.001 * 25, 1e-300, -1e300, inf, -inf, nan};
  for (double x : values)
    for (double y : values) {
      volatile double a = x, b = y;
      const double want = std::fmax(a, b), got = maxOf(a, b);
      EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(want))
          << x << ", " << y;
    }
}

// The random tests' numbers (a 64-bit linear congruential generator: the same sequences on every
// run): next(n) in 0 .. n-1, and coordinates, 0 one time in four, else -100..100 mm to three
// decimals.
struct Random64 {
  std::uint64_t state;
  int operator()(int n) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<int>((state >> 33) % static_cast<std::uint64_t>(n));
  }
  double coordinate() { return (*this)(4) == 0 ? 0.0 : ((*this)(200001) - 100000) / 1000.0; }
};

// centreByRadius against the centre as arcByRadius computed it before (docs/performance.md §47:
// the chord's midpoint plus (side * h) times its unit normal; now h times (side * normal)), bit
// for bit, on random chords and radii of both signs and both directions, down to a half circle
// (h == 0) and zero coordinates.
TEST(SolveArc, CentreByRadiusAsBefore) {
  auto before = [](Vec2 s, Vec2 e, double cr, bool ccw) {
    const double a = e.a - s.a, o = e.o - s.o;
    const double d = std::sqrt(a * a + o * o);
    const Vec2 mid{(s.a + e.a) / 2, (s.o + e.o) / 2};
    const Vec2 u{(e.a - s.a) / d, (e.o - s.o) / d};
    const Vec2 left{-u.o, u.a};
    const double rad = std::fabs(cr);
    const double h = std::sqrt(maxOf(0.0, rad * rad - d * d / 4));
    const double side = (ccw == (cr > 0)) ? 1 : -1;
    return Vec2{mid.a + side * h * left.a, mid.o + side * h * left.o};
  };
  Random64 next{47};
  for (int i = 0; i < 20000; ++i) {
    const Vec2 s{next.coordinate(), next.coordinate()}, e{next.coordinate(), next.coordinate()};
    const double d = std::sqrt((e.a - s.a) * (e.a - s.a) + (e.o - s.o) * (e.o - s.o));
    if (d < 1e-6) continue;
    const double rad = next(3) == 0 ? d / 2 : d / 2 + next(100000) / 997.0;  // a half circle too
    const double cr = next(2) ? rad : -rad;
    const bool ccw = next(2) != 0;
    const Vec2 got = centreByRadius(s, e, cr, ccw, 0.01, 0.001), want = before(s, e, cr, ccw);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got.a), std::bit_cast<std::uint64_t>(want.a)) << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(got.o), std::bit_cast<std::uint64_t>(want.o)) << i;
  }
}

// radiusByCentre (the motion builder's short way for I, J, K) against solveArc with a centre and
// an end point: the same radius bit for bit, and the same alarm (14045 start point on the centre,
// 14040 end point off the circle beyond MD21000/MD21010) where solveArc raises one.
TEST(SolveArc, RadiusByCentreAsSolveArc) {
  Random64 next{2212};
  int alarms = 0;
  for (int i = 0; i < 20000; ++i) {
    ArcRequest r = request({next.coordinate(), next.coordinate()}, next(2) != 0);
    const Vec2 c = next(8) == 0 ? r.start : Vec2{next.coordinate(), next.coordinate()};
    const double rad =
        std::sqrt((c.a - r.start.a) * (c.a - r.start.a) + (c.o - r.start.o) * (c.o - r.start.o));
    // An end on the circle to 4 decimals, off it by up to 0.03 mm, or anywhere.
    const double angle = next(3600) / 10.0 * kRadPerDegree, off = (next(7) - 3) / 100.0;
    const Vec2 e = next(5) == 0
                       ? Vec2{next.coordinate(), next.coordinate()}
                       : Vec2{std::round((c.a + (rad + off) * std::cos(angle)) * 1e4) / 1e4,
                              std::round((c.o + (rad + off) * std::sin(angle)) * 1e4) / 1e4};
    r.centre = c;
    r.end = e;
    const int want_alarm = alarmOf(r);
    int got_alarm = 0;
    double got = 0;
    try {
      got = radiusByCentre(r.start, e, c, r.tol_const, r.tol_factor);
    } catch (const AlarmError& err) {
      got_alarm = err.number();
    }
    EXPECT_EQ(got_alarm, want_alarm) << i;
    alarms += want_alarm != 0;
    if (want_alarm == 0) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(solveArc(r).radius))
          << i;
    }
  }
  EXPECT_GT(alarms, 2000);  // both outcomes compared
  EXPECT_LT(alarms, 18000);
}

}  // namespace
}  // namespace ncoffset::geom
