#include "geom/contour.hpp"

#include <cmath>
#include <limits>

#include "geom/tolerance.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset::geom {
namespace {

double angleOf(Vec2 c, Vec2 p) {
  return std::atan2(p.o - c.o, p.a - c.a);
}

// The sweep of an arc from start angle a0 (Element::sweep without computing a0 again).
double sweepFrom(const Element& e, double a0) {
  double s = e.ccw ? angleOf(e.c, e.p1) - a0 : a0 - angleOf(e.c, e.p1);
  s = std::fmod(s, 2 * kPi);
  if (s < 0) s += 2 * kPi;
  if (s < tol::kNumeric) s = 2 * kPi;  // end on start: a full circle
  s += 2 * kPi * e.turns;
  return e.ccw ? s : -s;
}

// What intersect needs of an element, computed once for all its crossings: for a line its
// direction, for an arc its start angle and sweep; and its length.
struct Param {
  Vec2 d;            // line: p1 - p0
  double dd = 0;     // line: |d|^2
  double a0 = 0;     // arc: angle of p0 about c
  double total = 0;  // arc: |sweep|
  double len = 0;
};

// (Inlined, as fractionAt: a call each cost about a third of a line's parameters, §36.)
[[gnu::always_inline]] inline Param paramOf(const Element& e) {
  Param q;
  if (!e.arc) {
    q.d = e.p1 - e.p0;
    q.dd = dot(q.d, q.d);
    q.len = std::sqrt(q.dd);
  } else {
    q.a0 = angleOf(e.c, e.p0);
    q.total = std::fabs(sweepFrom(e, q.a0));
    q.len = e.radius() * q.total;
  }
  return q;
}

// Fraction of the element at point p (on its line / circle). For an arc: of the sweep, measured
// from p0 in the direction of travel; in [0, 1] on the arc, the rest of the circle maps to the
// nearer extension.
[[gnu::always_inline]] inline double fractionAt(const Element& e, const Param& q, Vec2 p) {
  if (!e.arc) return q.dd > 0 ? dot(p - e.p0, q.d) / q.dd : 0.0;
  const double ang = angleOf(e.c, p);
  double d = e.ccw ? ang - q.a0 : q.a0 - ang;
  d = std::fmod(d, 2 * kPi);
  if (d < 0) d += 2 * kPi;
  double u = d / q.total;
  // Beyond the end: closer to the end or (going backwards) to the start?
  if (u > 1) {
    double past_end = d - q.total, before_start = 2 * kPi - d;
    if (before_start < past_end) u = -before_start / q.total;
  }
  return u;
}
}  // namespace

double Element::sweep() const {
  if (!arc) return 0;
  return sweepFrom(*this, angleOf(c, p0));
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
  Element o;
  if (!equidistantInto(e, d, o)) return std::nullopt;
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

namespace {
// std::fmax(0.0, v) without the call to libm: the same for every v a difference of two squares
// (or products of a value with itself) can be: a NaN gives 0 as with fmax, and such a
// difference is never -0 (x - y is -0 only for x = -0; a square is +0 at the least).
inline double atLeastZero(double v) {
  return v > 0 ? v : 0.0;
}

// The points where the lines and circles of e1 and e2 (an arc: its circle through p0) cross,
// each passed to point(p, u) with u the fraction on e1 for two lines (else NaN: the caller
// computes it). One generator for intersect and filteredCrossings, so that both compute every
// point with the same arithmetic (docs/performance.md §31). q1, q2: the lines' parameters (an
// arc's are not used here).
template <typename Point>
void crossingPoints(const Element& e1, const Element& e2, const Param& q1, const Param& q2,
                    Point point) {
  if (!e1.arc && !e2.arc) {
    const Vec2 d1 = q1.d, d2 = q2.d;
    double den = cross(d1, d2);
    if (std::fabs(den) < tol::kNumeric * q1.len * q2.len) return;  // parallel
    double u = cross(e2.p0 - e1.p0, d2) / den;
    point(e1.p0 + u * d1, u);
    return;
  }
  constexpr double kNoFraction = std::numeric_limits<double>::quiet_NaN();
  if (e1.arc != e2.arc) {
    const Element& l = e1.arc ? e2 : e1;
    const Element& c = e1.arc ? e1 : e2;
    const double r = c.radius();
    Vec2 d = unit(l.p1 - l.p0);
    Vec2 f = l.p0 - c.c;
    double b = dot(f, d), cc = dot(f, f) - r * r;
    double disc = b * b - cc;  // r^2 - (distance of the centre from the line)^2
    // Missing the circle by no more than tol::kPoint: touching it.
    if (disc < -2 * r * tol::kPoint) return;
    double s = std::sqrt(atLeastZero(disc));
    for (double t : {-b - s, -b + s}) {
      point(l.p0 + t * d, kNoFraction);
      if (s == 0) break;
    }
    return;
  }
  // Circle-circle.
  double r1 = e1.radius(), r2 = e2.radius();
  Vec2 dc = e2.c - e1.c;
  double dist = length(dc);
  if (dist < tol::kNumeric) return;  // concentric
  double a = (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist);
  double h2 = r1 * r1 - a * a;
  // Passing each other by no more than about tol::kPoint: touching.
  if (h2 < -2 * tol::kPoint * r1 * r2 / (r1 + r2)) return;
  double h = std::sqrt(atLeastZero(h2));
  Vec2 m = e1.c + (a / dist) * dc;
  Vec2 perp = leftNormal((1.0 / dist) * dc);
  for (double sgn : {1.0, -1.0}) {
    point(m + (sgn * h) * perp, kNoFraction);
    if (h == 0) break;
  }
}

// The crossings of the lines and circles of e1 and e2, with the parameters of q1, q2 (which may
// belong to other elements of the same lines / circles).
std::vector<Crossing> intersectCircles(const Element& e1, const Element& e2, const Param& q1,
                                       const Param& q2) {
  std::vector<Crossing> out;
  crossingPoints(e1, e2, q1, q2, [&](Vec2 p, double u) {
    Crossing x{p, fractionAt(e1, q1, p), fractionAt(e2, q2, p), q1.len, q2.len};
    if (!e1.arc && !e2.arc) x.u1 = u;
    out.push_back(x);
  });
  return out;
}

// The element's circle at the spiral's radius at fraction u (beyond its ends the spiral goes
// on: a row from a point of an extension to a point of the element is the same spiral).
Element atFraction(const Element& e, double change, double u) {
  Element o = e;
  const double r0 = e.radius();
  o.p0 = e.c + ((r0 + u * change) / r0) * (e.p0 - e.c);
  return o;
}
}  // namespace

double radiusChange(const Element& e) {
  if (!e.arc) return 0;
  const double d = length(e.p1 - e.c) - e.radius();
  return std::fabs(d) > tol::kNumeric * (1 + e.radius()) ? d : 0;
}

std::vector<Crossing> intersect(const Element& e1, const Element& e2) {
  const Param q1 = paramOf(e1), q2 = paramOf(e2);
  const double c1 = radiusChange(e1), c2 = radiusChange(e2);
  if (c1 == 0 && c2 == 0) return intersectCircles(e1, e2, q1, q2);
  // A spiral (an arc whose radii differ): the crossings with its circle at the radius it has
  // there, found from the crossings with the circles of its start and of its end radius (of
  // each spiral) in a few steps. Where the steps do not converge (the curves meet at a very small
  // angle, so that a change of radius moves the crossing far along them), the crossing with the
  // nearer of the two circles is kept: near its end the spiral is that circle.
  std::vector<Crossing> out;
  for (int seed = 0; seed < 4; ++seed) {
    const double s1 = seed & 1, s2 = seed >> 1;  // start (0) or end (1) circle of each
    if ((c1 == 0 && s1 != 0) || (c2 == 0 && s2 != 0)) continue;
    const Element a0 = c1 != 0 ? atFraction(e1, c1, s1) : e1;
    const Element b0 = c2 != 0 ? atFraction(e2, c2, s2) : e2;
    for (const Crossing& x0 : intersectCircles(a0, b0, q1, q2)) {
      Crossing x = x0;
      double moved = 1e300;
      bool converged = false;
      for (int step = 0; step < 4 && !converged; ++step) {
        const Element a = c1 != 0 ? atFraction(e1, c1, x.u1) : e1;
        const Element b = c2 != 0 ? atFraction(e2, c2, x.u2) : e2;
        std::optional<Crossing> nearest;
        for (const Crossing& y : intersectCircles(a, b, q1, q2))
          if (!nearest || length(y.p - x.p) < length(nearest->p - x.p)) nearest = y;
        if (!nearest) break;
        const double d = length(nearest->p - x.p);
        if (d > 0.5 * moved) break;  // not converging
        moved = d;
        x = *nearest;
        converged = d < tol::kNumeric * (1 + length(x.p));
      }
      if (!converged) {
        // Keep the seed's crossing where it lies on the seed circles' halves of the spirals.
        if ((c1 != 0 && std::fabs(x0.u1 - s1) > 0.5) || (c2 != 0 && std::fabs(x0.u2 - s2) > 0.5))
          continue;
        x = x0;
      }
      bool known = false;
      for (const Crossing& y : out) known = known || length(y.p - x.p) < tol::kPoint;
      if (!known) out.push_back(x);
    }
  }
  return out;
}

namespace {
// An arc's fraction at p, its parameters computed at the first call.
double lazyFraction(const Element& e, Param& q, bool& known, Vec2 p) {
  if (!known) q = paramOf(e), known = true;
  return fractionAt(e, q, p);
}
}  // namespace

bool filteredCrossings(const Element& e1, const Element& e2, FractionTest on1, FractionTest on2,
                       CrossingPair& out) {
  out.n = 0;
  if (radiusChange(e1) != 0 || radiusChange(e2) != 0) return false;  // a spiral: intersect
  // A line's parameters now (cheap, and the crossing of two lines needs them); an arc's (two
  // angles and a remainder) only for the first crossing that passed the line's test.
  Param q1 = e1.arc ? Param{} : paramOf(e1), q2 = e2.arc ? Param{} : paramOf(e2);
  bool known1 = !e1.arc, known2 = !e2.arc;
  crossingPoints(e1, e2, q1, q2, [&](Vec2 p, double u) {
    double u1 = 0, u2 = 0;
    // The lines' tests first (no angle), as intersect computes their fractions.
    if (!e1.arc) {
      u1 = e2.arc ? fractionAt(e1, q1, p) : u;
      if (!passesTest(on1, u1, q1.len)) return;
    }
    if (!e2.arc) {
      u2 = fractionAt(e2, q2, p);
      if (!passesTest(on2, u2, q2.len)) return;
    }
    if (e1.arc) {
      u1 = lazyFraction(e1, q1, known1, p);
      if (!passesTest(on1, u1, q1.len)) return;
    }
    if (e2.arc) {
      u2 = lazyFraction(e2, q2, known2, p);
      if (!passesTest(on2, u2, q2.len)) return;
    }
    out.x[out.n++] = Crossing{p, u1, u2, q1.len, q2.len};
  });
  return true;
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
  if (d <= r + tol::kPoint) return std::nullopt;
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
