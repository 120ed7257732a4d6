#include "geom/arc.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncoffset/alarm.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset::geom {
namespace {
constexpr double kDeg = kRadPerDegree;
// Coordinates stay within 1e9 mm (block_executor): the squares cannot overflow, no hypot needed.
double dist(Vec2 p, Vec2 q) {
  const double a = q.a - p.a, o = q.o - p.o;
  return std::sqrt(a * a + o * o);
}

// The chord from the start to the end point of a circle given by its radius or opening angle.
struct Chord {
  double length;
  Vec2 mid, left;  // its middle and the unit normal to its left
};

Chord chord(Vec2 start, Vec2 end) {
  const double d = dist(start, end);
  if (d < 1e-9) fullCircleAlarm();
  Vec2 mid{(start.a + end.a) / 2, (start.o + end.o) / 2};
  Vec2 u{(end.a - start.a) / d, (end.o - start.o) / d};
  return {d, mid, {-u.o, u.a}};
}

}  // namespace

void fullCircleAlarm() {
  raise(AlarmNumber::CircleProgramming,
        "circle programming error: a full circle needs its centre (I, J, K)");
}

void radiusZeroAlarm() {
  raise(AlarmNumber::CircleProgramming, "circle programming error: CR=0");
}

void chordAlarm(double chord, double diameter) {
  raise(AlarmNumber::CircleEndPoint,
        fmt::format("error in end point of circle: chord {:.6g} longer than the diameter {:.6g}",
                    chord, diameter));
}

void startIsCentreAlarm() {
  raise(AlarmNumber::CircleProgramming, "circle programming error: start point is the centre");
}

void endRadiusAlarm(double start_radius, double end_radius, double tol) {
  raise(AlarmNumber::CircleEndPoint,
        fmt::format("error in end point of circle: start radius {:.6g}, end radius {:.6g}, "
                    "difference {:.6g} > {:.6g} (MD21000/MD21010)",
                    start_radius, end_radius, std::fabs(end_radius - start_radius), tol));
}

ArcSolution arcByRadius(Vec2 start, Vec2 end, double cr, bool ccw, double tol_const,
                        double tol_factor) {
  ArcSolution s;
  s.end = end;
  s.centre = centreByRadius(start, end, cr, ccw, tol_const, tol_factor);
  s.radius = std::fabs(cr);
  return s;
}

ArcSolution solveArc(const ArcRequest& r) {
  const int defs = (r.centre ? 1 : 0) + (r.cr ? 1 : 0) + (r.ar ? 1 : 0);
  if (defs == 0)
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: no centre (I, J, K), radius (CR=) or opening angle (AR=)");
  if (r.cr && (r.centre || r.ar))
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: CR= cannot be combined with a centre or AR=");
  if (r.ar && r.centre && r.end)
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: AR= with a centre needs no end point (over-determined)");

  ArcSolution s;
  if (r.centre) {
    s.centre = *r.centre;
    s.radius = dist(r.start, s.centre);
    if (s.radius < 1e-9) startIsCentreAlarm();
    if (r.ar) {
      double ang = std::atan2(r.start.o - s.centre.o, r.start.a - s.centre.a) +
                   (r.ccw ? 1 : -1) * *r.ar * kDeg;
      s.end = {s.centre.a + s.radius * std::cos(ang), s.centre.o + s.radius * std::sin(ang)};
      return s;
    }
    s.end = r.end ? *r.end : r.start;
    // radiusByCentre is the motion builder's inline twin of these lines (tests/geom/arc_test.cpp).
    double r2 = dist(s.end, s.centre);
    double tol = maxOf(r.tol_const, r.tol_factor * s.radius);
    if (std::fabs(r2 - s.radius) > tol) endRadiusAlarm(s.radius, r2, tol);
    return s;
  }
  if (!r.end) raise(AlarmNumber::CircleProgramming, "circle programming error: end point missing");
  if (r.cr) return arcByRadius(r.start, *r.end, *r.cr, r.ccw, r.tol_const, r.tol_factor);
  s.end = *r.end;
  const Chord c = chord(r.start, s.end);
  const double d = c.length;
  const Vec2 mid = c.mid, left = c.left;
  double h;
  double ar = *r.ar;
  if (!(ar > 0 && ar < 360))
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: AR= with an end point must lie between 0 and 360 degrees");
  double half = ar * kDeg / 2;
  s.radius = d / (2 * std::sin(half));
  h = s.radius * std::cos(half);  // negative beyond 180 degrees: centre on the other side
  double side = r.ccw ? 1 : -1;
  s.centre = {mid.a + side * h * left.a, mid.o + side * h * left.o};
  return s;
}

}  // namespace ncoffset::geom
