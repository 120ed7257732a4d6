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

// solveArc for a circle by its radius CR= (negative: more than a semicircle) from `start` to
// `end`: what solveArc does with a request of only these (the motion builder's short way calls
// it without building one).
ArcSolution arcByRadius(Vec2 start, Vec2 end, double cr, bool ccw, double tol_const,
                        double tol_factor);

// Throws AlarmError 14040 (end point not on the circle), 14045 (circle not defined).
ArcSolution solveArc(const ArcRequest& r);

}  // namespace ncoffset::geom
