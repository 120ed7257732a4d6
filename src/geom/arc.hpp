// Circle programming (PM-NC "Circular interpolation G2/G3"): centre from I/J/K, radius CR=,
// opening angle AR=; end point checked against MD21000/MD21010.
#pragma once

#include <cmath>
#include <optional>

namespace ncoffset::geom {

struct Vec2 {
  double a = 0, o = 0;  // abscissa, ordinate of the active plane
};

struct ArcRequest {
  Vec2 start;
  std::optional<Vec2> end;     // programmed end point (else: from AR and centre)
  std::optional<Vec2> centre;  // absolute centre (I/J/K resolved)
  std::optional<double> cr;    // CR=: radius, negative for more than a semicircle
  std::optional<double> ar;    // AR=: opening angle in degrees
  bool ccw = false;            // G3
  double tol_const = 0.01;     // MD21000 CIRCLE_ERROR_CONST (mm)
  double tol_factor = 0.001;   // MD21010 CIRCLE_ERROR_FACTOR
};

struct ArcSolution {
  Vec2 centre;
  Vec2 end;
  double radius = 0;
};

// std::fmax as glibc's x86-64 fmax computes it (NaN gives the other operand; of two equal values
// the first), inline: the library call cost solveArc two calls per circle. Its twin is std::fmax
// (tests/geom/arc_test.cpp).
inline double maxOf(double a, double b) {
  if (std::isnan(a)) return b;
  if (std::isnan(b)) return a;
  return a < b ? b : a;
}

// The alarms of a circle by its radius (out of line: the usual circle raises none).
[[noreturn, gnu::cold]] void fullCircleAlarm();
[[noreturn, gnu::cold]] void radiusZeroAlarm();
[[noreturn, gnu::cold]] void chordAlarm(double chord, double diameter);
// The alarms of a circle by its centre.
[[noreturn, gnu::cold]] void startIsCentreAlarm();
[[noreturn, gnu::cold]] void endRadiusAlarm(double start_radius, double end_radius, double tol);

// The centre of a circle by its radius CR= (negative: more than a semicircle) from `start` to
// `end`, with its alarms in solveArc's order; inline, so that the motion builder's short way
// keeps the coordinates in registers (a call returned them through memory, and GCC packed them
// into vectors through the stack, where loads wait for the stores: docs/performance.md §47).
// The chord's unit normal times ±1 is formed before h is known: (side * h) * l is
// h * (side * l) bit for bit (side is ±1), one multiplication fewer behind the square roots.
[[gnu::always_inline]] inline Vec2 centreByRadius(Vec2 start, Vec2 end, double cr, bool ccw,
                                                  double tol_const, double tol_factor) {
  const double da = end.a - start.a, dor = end.o - start.o;
  // Coordinates stay within 1e9 mm (block_executor): the squares cannot overflow, no hypot.
  const double d = std::sqrt(da * da + dor * dor);
  if (d < 1e-9) fullCircleAlarm();
  const double mid_a = (start.a + end.a) / 2, mid_o = (start.o + end.o) / 2;
  const double left_a = -(dor / d), left_o = da / d;  // the unit normal to the chord's left
  const double rad = std::fabs(cr);
  if (rad < 1e-9) radiusZeroAlarm();
  const double tol = maxOf(tol_const, tol_factor * rad);
  if (d > 2 * rad + tol) chordAlarm(d, 2 * rad);
  const double side = (ccw == (cr > 0)) ? 1 : -1;  // CR>0: arc up to 180 degrees
  const double h = std::sqrt(maxOf(0.0, rad * rad - d * d / 4));
  return {mid_a + h * (side * left_a), mid_o + h * (side * left_o)};
}

// The radius of a circle by its centre from `start` to `end` (the end on the circle within
// MD21000/MD21010), with its alarms in solveArc's order; inline for the motion builder's short
// way as centreByRadius.
[[gnu::always_inline]] inline double radiusByCentre(Vec2 start, Vec2 end, Vec2 centre,
                                                    double tol_const, double tol_factor) {
  // Coordinates stay within 1e9 mm (block_executor): the squares cannot overflow, no hypot.
  const double sa = centre.a - start.a, so = centre.o - start.o;
  const double radius = std::sqrt(sa * sa + so * so);
  if (radius < 1e-9) startIsCentreAlarm();
  const double ea = centre.a - end.a, eo = centre.o - end.o;
  const double r2 = std::sqrt(ea * ea + eo * eo);
  const double tol = maxOf(tol_const, tol_factor * radius);
  if (std::fabs(r2 - radius) > tol) endRadiusAlarm(radius, r2, tol);
  return radius;
}

// solveArc for a circle by its radius CR= from `start` to `end`: what solveArc does with a
// request of only these.
ArcSolution arcByRadius(Vec2 start, Vec2 end, double cr, bool ccw, double tol_const,
                        double tol_factor);

// Throws AlarmError 14040 (end point not on the circle), 14045 (circle not defined).
ArcSolution solveArc(const ArcRequest& r);

}  // namespace ncoffset::geom
