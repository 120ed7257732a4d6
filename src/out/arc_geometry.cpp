#include "out/arc_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace ncoffset::out {
namespace {}  // namespace

Vec3 ArcGeometry::at(double t) const {
  double a = t * sweep;
  return centre + std::cos(a) * u + std::sin(a) * w + (t * rise) * n;
}

ArcGeometry arcGeometry(const Segment& s) {
  ArcGeometry g;
  double len = norm(s.normal);
  g.n = len > 0 ? (1.0 / len) * s.normal : Vec3{0, 0, 1};
  g.centre = s.centre;
  // The centre lies in the plane of the start point; project both radius vectors into it.
  Vec3 a = s.start - s.centre;
  a = a - dot(a, g.n) * g.n;
  Vec3 b = s.end - s.centre;
  g.rise = dot(b, g.n) - dot(s.start - s.centre, g.n);
  b = b - dot(b, g.n) * g.n;
  g.u = a;
  g.w = cross(g.n, a);
  g.radius = norm(a);
  double ang = std::atan2(dot(g.n, cross(a, b)), dot(a, b));  // (-pi, pi], counter-clockwise
  bool ccw = s.motion == Motion::G3;
  double sw = ccw ? ang : -ang;
  if (sw < 0) sw += 2 * kPi;
  if (sw < 1e-12) sw = 2 * kPi;  // end on start: a full circle
  sw += 2 * kPi * std::max(0, s.turns);
  g.sweep = ccw ? sw : -sw;
  return g;
}

double segmentLength(const Segment& s) {
  if (!isArc(s)) return norm(s.end - s.start);
  ArcGeometry g = arcGeometry(s);
  return std::hypot(g.radius * std::fabs(g.sweep), g.rise);
}

void Box::add(Vec3 p) {
  for (int i = 0; i < 3; ++i) {
    lo[i] = std::min(lo[i], p[i]);
    hi[i] = std::max(hi[i], p[i]);
  }
}

void Box::add(const Segment& s) {
  add(s.start);
  add(s.end);
  if (!isArc(s)) return;
  ArcGeometry g = arcGeometry(s);
  double total = std::fabs(g.sweep);
  if (total >= 2 * kPi) {  // every angle is passed: the circle's extremes (at both levels)
    for (int i = 0; i < 3; ++i) {
      double r = std::hypot(g.u[i], g.w[i]);
      for (double level : {0.0, g.rise}) {
        lo[i] = std::min(lo[i], g.centre[i] + level * g.n[i] - r);
        hi[i] = std::max(hi[i], g.centre[i] + level * g.n[i] + r);
      }
    }
    return;
  }
  // Coordinate i along the arc: c_i + u_i cos a + w_i sin a (+ the rise): extreme where
  // tan a = w_i / u_i, at a0 and a0 + pi.
  for (int i = 0; i < 3; ++i) {
    if (std::hypot(g.u[i], g.w[i]) < 1e-300) continue;
    double a0 = std::atan2(g.w[i], g.u[i]);
    for (double a : {a0, a0 + kPi}) {
      double d = g.sweep > 0 ? a : -a;  // angle travelled to reach a
      d = std::fmod(d, 2 * kPi);
      if (d < 0) d += 2 * kPi;
      if (d <= total) add(g.at(d / total));
    }
  }
}

}  // namespace ncoffset::out
