// The G450 transition curve with DISC > 0 (W1 2.4.5 "DISC", details Q3, model [D]): the manuals
// say only that DISC = 0 is the circle of radius R about the corner point and DISC = 100 the
// intersection of the equidistants, with the overshoot growing in between. Model: the rational
// quadratic Bezier curve from A (end of the first equidistant) to B (start of the second) with
// the middle control point S, where the tangents at A and B meet, and the weight that puts the
// curve's middle at the distance o = R + DISC/100 * (|PS| - R) from the corner point P along
// the bisector. DISC = 0 gives weight cos(delta/2), which is exactly the circle.
#pragma once

#include <optional>
#include <vector>

#include "geom/contour.hpp"

namespace ncoffset::geom {

struct DiscCurve {
  Vec2 a, s, b;
  double w = 1;
  bool corner = false;  // DISC = 100: the curve is the corner A - S - B itself
  Vec2 at(double t) const;
};

// nullopt when the tangents do not meet ahead of A and B (a reversal): the circle is used.
// `p` is the corner point, `disc` 0..100.
std::optional<DiscCurve> discCurve(Vec2 a, Vec2 ta, Vec2 b, Vec2 tb, Vec2 p, double disc);

// Points of the curve after A up to and including B, so that the chords between them deviate
// from the curve by at most `tolerance` (uniform in the curve parameter, doubling the count).
std::vector<Vec2> chords(const DiscCurve& c, double tolerance);

}  // namespace ncoffset::geom
