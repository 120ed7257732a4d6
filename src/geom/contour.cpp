#include "geom/contour.hpp"

#include <cmath>

#include "ncoffset/geometry.hpp"

namespace ncoffset::geom {
namespace {

double angleOf(Vec2 c, Vec2 p) {
  return std::atan2(p.o - c.o, p.a - c.a);
}

// Fraction of the arc's sweep at which angle `ang` lies, measured from p0 in the direction of
// travel; in [0, 1] on the arc, the rest of the circle maps to the nearer extension.
double arcFraction(const Element& e, double ang) {
  double s = e.sweep();
  double a0 = angleOf(e.c, e.p0);
  double d = e.ccw ? ang - a0 : a0 - ang;
  d = std::fmod(d, 2 * kPi);
  if (d < 0) d += 2 * kPi;
  double total = std::fabs(s);
  double u = d / total;
  // Beyond the end: closer to the end or (going backwards) to the start?
  if (u > 1) {
    double past_end = d - total, before_start = 2 * kPi - d;
    if (before_start < past_end) u = -before_start / total;
  }
  return u;
}
}  // namespace

double Element::sweep() const {
  if (!arc) return 0;
  double a0 = angleOf(c, p0), a1 = angleOf(c, p1);
  double s = ccw ? a1 - a0 : a0 - a1;
  s = std::fmod(s, 2 * kPi);
  if (s < 0) s += 2 * kPi;
  if (s < 1e-12) s = 2 * kPi;  // end on start: a full circle
  s += 2 * kPi * turns;
  return ccw ? s : -s;
}

Vec2 Element::startTangent() const {
  if (!arc) return unit(p1 - p0);
  Vec2 r = unit(p0 - c);
  return ccw ? leftNormal(r) : -1.0 * leftNormal(r);
}

Vec2 Element::endTangent() const {
  if (!arc) return unit(p1 - p0);
  Vec2 r = unit(p1 - c);
  return ccw ? leftNormal(r) : -1.0 * leftNormal(r);
}

std::optional<Element> equidistant(const Element& e, double d) {
  Element o = e;
  if (!e.arc) {
    Vec2 n = leftNormal(e.startTangent());
    o.p0 = e.p0 + d * n;
    o.p1 = e.p1 + d * n;
    return o;
  }
  double r = e.radius();
  double r2 = e.ccw ? r - d : r + d;  // the left side of a ccw arc is its inside
  if (r2 <= 1e-9) return std::nullopt;
  double k = r2 / r;
  o.p0 = e.c + k * (e.p0 - e.c);
  o.p1 = e.c + k * (e.p1 - e.c);
  return o;
}

Vec2 pointAt(const Element& e, double u) {
  if (!e.arc) return e.p0 + u * (e.p1 - e.p0);
  double a = angleOf(e.c, e.p0) + u * e.sweep();
  double r = e.radius();
  return {e.c.a + r * std::cos(a), e.c.o + r * std::sin(a)};
}

Vec2 tangentAt(const Element& e, Vec2 p) {
  if (!e.arc) return unit(e.p1 - e.p0);
  Vec2 r = unit(p - e.c);
  return e.ccw ? leftNormal(r) : -1.0 * leftNormal(r);
}

std::vector<Crossing> intersect(const Element& e1, const Element& e2) {
  std::vector<Crossing> out;
  auto lineParam = [](const Element& l, Vec2 p) {
    Vec2 d = l.p1 - l.p0;
    double dd = dot(d, d);
    return dd > 0 ? dot(p - l.p0, d) / dd : 0.0;
  };
  auto param = [&](const Element& e, Vec2 p) {
    return e.arc ? arcFraction(e, angleOf(e.c, p)) : lineParam(e, p);
  };
  if (!e1.arc && !e2.arc) {
    Vec2 d1 = e1.p1 - e1.p0, d2 = e2.p1 - e2.p0;
    double den = cross(d1, d2);
    if (std::fabs(den) < 1e-12 * length(d1) * length(d2)) return out;  // parallel
    double u = cross(e2.p0 - e1.p0, d2) / den;
    Vec2 p = e1.p0 + u * d1;
    out.push_back({p, u, lineParam(e2, p)});
    return out;
  }
  if (e1.arc != e2.arc) {
    const Element& l = e1.arc ? e2 : e1;
    const Element& c = e1.arc ? e1 : e2;
    Vec2 d = unit(l.p1 - l.p0);
    Vec2 f = l.p0 - c.c;
    double b = dot(f, d), cc = dot(f, f) - c.radius() * c.radius();
    double disc = b * b - cc;
    if (disc < -1e-12) return out;
    double s = std::sqrt(std::fmax(0.0, disc));
    for (double t : {-b - s, -b + s}) {
      Vec2 p = l.p0 + t * d;
      double ul = lineParam(l, p), uc = param(c, p);
      out.push_back(e1.arc ? Crossing{p, uc, ul} : Crossing{p, ul, uc});
      if (s == 0) break;
    }
    return out;
  }
  // Circle-circle.
  double r1 = e1.radius(), r2 = e2.radius();
  Vec2 dc = e2.c - e1.c;
  double dist = length(dc);
  if (dist < 1e-12) return out;  // concentric
  double a = (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist);
  double h2 = r1 * r1 - a * a;
  if (h2 < -1e-9 * r1 * r1) return out;
  double h = std::sqrt(std::fmax(0.0, h2));
  Vec2 m = e1.c + (a / dist) * dc;
  Vec2 perp = leftNormal((1.0 / dist) * dc);
  for (double sgn : {1.0, -1.0}) {
    Vec2 p = m + (sgn * h) * perp;
    out.push_back({p, param(e1, p), param(e2, p)});
    if (h == 0) break;
  }
  return out;
}

Element fullCircle(Vec2 c, double r) {
  Element e;
  e.arc = true;
  e.c = c;
  e.p0 = e.p1 = {c.a + r, c.o};
  e.ccw = true;
  return e;
}

std::optional<Vec2> tangentPoint(Vec2 p, Vec2 c, double r, double s, bool towards) {
  Vec2 v = p - c;
  double d = length(v);
  if (d <= r + 1e-9) return std::nullopt;
  double phi = std::atan2(v.o, v.a), alpha = std::acos(r / d);
  for (double ang : {phi + alpha, phi - alpha}) {
    Vec2 t{c.a + r * std::cos(ang), c.o + r * std::sin(ang)};
    Vec2 dir = towards ? t - p : p - t;
    double sidedness = cross(dir, c - (towards ? p : t));
    if (s * sidedness < 0) return t;
  }
  return std::nullopt;
}

}  // namespace ncoffset::geom
