// Circle programming (PM-NC "Circular interpolation G2/G3"): centre from I/J/K, radius CR=,
// opening angle AR=; end point checked against MD21000/MD21010.
#pragma once

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

// Throws AlarmError 14040 (end point not on the circle), 14045 (circle not defined).
ArcSolution solveArc(const ArcRequest& r);

}  // namespace ncoffset::geom
