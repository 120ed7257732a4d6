// Geometry of one output segment for the writers that draw, measure or re-program the path:
// the sweep of an arc about its normal (G2/G3 seen from +normal, PM-NC "Circular interpolation
// G2/G3"), helix rise and TURN= full turns (PM-NC "Helical interpolation"), points along it,
// its length and its axis-parallel bounding box.
#pragma once

#include <limits>

#include "ncoffset/path.hpp"

namespace ncoffset::out {

inline bool isArc(const Segment& s) {
  return s.motion == Motion::G2 || s.motion == Motion::G3;
}

// An arc as c + cos(t*sweep) u + sin(t*sweep) w + t*rise*n, t in [0, 1]: u from the centre to
// the start point, w = n x u (so a positive sweep turns counter-clockwise seen from +n).
struct ArcGeometry {
  Vec3 centre, u, w, n;
  double radius = 0;
  double sweep = 0;  // radians, signed about n: G3 > 0, G2 < 0; full turns included
  double rise = 0;   // helix: travel along n from start to end
  Vec3 at(double t) const;
};

// Valid for G2/G3 segments only. The end point on the start point (in the arc's plane) is a
// full circle, as on the control.
ArcGeometry arcGeometry(const Segment& s);

// Path length of a line or an arc (helix: along the screw line).
double segmentLength(const Segment& s);

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
  bool empty() const { return lo.x > hi.x; }
  void add(Vec3 p);
  // The whole segment, arcs with their extreme points (exact for an axis-parallel normal).
  void add(const Segment& s);
};

}  // namespace ncoffset::out
