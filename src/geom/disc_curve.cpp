#include "geom/disc_curve.hpp"

#include <cmath>

#include "geom/tolerance.hpp"

namespace ncoffset::geom {

Vec2 DiscCurve::at(double t) const {
  const double u = 1 - t, k0 = u * u, k1 = 2 * w * t * u, k2 = t * t;
  return (1.0 / (k0 + k1 + k2)) * (k0 * a + k1 * s + k2 * b);
}

std::optional<DiscCurve> discCurve(Vec2 a, Vec2 ta, Vec2 b, Vec2 tb, Vec2 p, double disc) {
  // S: the tangent at A (direction ta) meets the tangent at B (direction tb).
  const double den = cross(ta, tb);
  if (std::fabs(den) < tol::kTurn) return std::nullopt;  // no turn: no control point
  const double ua = cross(b - a, tb) / den, ub = cross(b - a, ta) / den;
  if (ua <= 0 || ub >= 0) return std::nullopt;
  DiscCurve c{a, a + ua * ta, b};
  const Vec2 m = 0.5 * (a + b);
  const double h = length(m - p), ps = length(c.s - p);
  const double r = 0.5 * (length(a - p) + length(b - p));
  const double o = r + disc / 100.0 * (ps - r);
  if (ps - o < tol::kNumeric) {
    c.corner = true;  // DISC = 100: the intersection of the equidistants' tangents
    return c;
  }
  c.w = (o - h) / (ps - o);
  return c;
}

std::vector<Vec2> chords(const DiscCurve& c, double tolerance) {
  if (c.corner) return {c.s, c.b};
  for (int n = 2;; n *= 2) {
    std::vector<Vec2> pts;
    bool ok = true;
    Vec2 prev = c.a;
    for (int i = 1; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      const Vec2 q = c.at(t), mid = c.at(t - 0.5 / n);
      const Vec2 chord = q - prev;
      const double len = length(chord);
      if (len > 0 && std::fabs(cross(chord, mid - prev)) / len > tolerance) ok = false;
      pts.push_back(q);
      prev = q;
    }
    if (ok || n >= 4096) return pts;
  }
}

}  // namespace ncoffset::geom
