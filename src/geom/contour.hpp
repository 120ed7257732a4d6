// Plane contour elements (lines and circular arcs in abscissa/ordinate coordinates of the active
// plane) and the primitives tool radius compensation needs: tangents, equidistants and
// intersections (W1 2.4 / spec §5, details Q1-Q5).
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "geom/arc.hpp"
#include "geom/tolerance.hpp"
#include "ncoffset/geometry.hpp"

namespace ncoffset::geom {

inline Vec2 operator+(Vec2 a, Vec2 b) {
  return {a.a + b.a, a.o + b.o};
}
inline Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.a - b.a, a.o - b.o};
}
inline Vec2 operator*(double s, Vec2 v) {
  return {s * v.a, s * v.o};
}
inline double dot(Vec2 a, Vec2 b) {
  return a.a * b.a + a.o * b.o;
}
inline double cross(Vec2 a, Vec2 b) {
  return a.a * b.o - a.o * b.a;
}
// Coordinates are limited to 1e9 mm (block_executor), so no overflow guard (hypot) is needed.
inline double length(Vec2 v) {
  return std::sqrt(v.a * v.a + v.o * v.o);
}
inline Vec2 leftNormal(Vec2 t) {
  return {-t.o, t.a};
}
// The unit vector along v; (1, 0) for the zero vector, so that a degenerate element still has
// a direction.
inline Vec2 unit(Vec2 v) {
  const double l = length(v);
  return l > 0 ? (1.0 / l) * v : Vec2{1, 0};
}
// The angle between two unit vectors in degrees, 0..180: the contour angle that MD20210
// CUTCOM_CORNER_LIMIT and MD20230 CUTCOM_CURVE_INSERT_LIMIT are compared with (details Q3/Q4).
inline double angleDeg(Vec2 t1, Vec2 t2) {
  constexpr double kDeg = kDegreePerRad;
  return std::acos(std::fmax(-1.0, std::fmin(1.0, dot(t1, t2)))) * kDeg;
}

// A line (arc == false) or a circular arc from p0 to p1 about c, turning ccw (G3) or cw (G2).
// `turns` full revolutions are added to the sweep (TURN=). An arc whose end radius differs from
// its start radius (within MD21000/MD21010, or a compensation value changing in the block) is
// the spiral between them: the radius changes linearly with the angle; radius() is the start
// radius.
struct Element {
  bool arc = false;
  Vec2 p0, p1, c;
  bool ccw = false;
  int turns = 0;
  double radius() const { return length(p0 - c); }
  // Unit tangent in the direction of travel at the start / end.
  Vec2 startTangent() const;
  Vec2 endTangent() const;
  // Signed sweep angle in radians (positive ccw), 2*pi for a full circle.
  double sweep() const;
};

// The equidistant at signed distance d (d > 0: to the left of the direction of travel). For an
// arc the radius becomes r - d (ccw) or r + d (cw), at its start and at its end (a spiral keeps
// its change of radius: both ends lie at |d| from the element's ends); an arc whose radius
// becomes tol::kPoint or less there (an inside arc with r <= R) has no equidistant.
std::optional<Element> equidistant(const Element& e, double d);
// The same into `o` (left as it was when there is none; `o` may be `e`): no optional to copy
// (radius compensation, once a block; docs/performance.md §31). Inline: compensateInto's
// equidistant without a call and a line's tangent without a second one (§36).
inline bool equidistantInto(const Element& e, double d, Element& o) {
  Vec2 p0, p1;  // (computed before `o` is written: it may be `e`)
  if (!e.arc) {
    const Vec2 n = leftNormal(unit(e.p1 - e.p0));  // startTangent() of a line
    p0 = e.p0 + d * n;
    p1 = e.p1 + d * n;
  } else {
    // The left side of a ccw arc is its inside. Each end keeps |d| from its own end point, so a
    // spiral keeps its change of radius.
    const double r0 = e.radius(), r1 = length(e.p1 - e.c);
    const double q0 = e.ccw ? r0 - d : r0 + d, q1 = e.ccw ? r1 - d : r1 + d;
    if (q0 <= tol::kPoint || q1 <= tol::kPoint) return false;  // r <= R: none
    p0 = e.c + (q0 / r0) * (e.p0 - e.c);
    p1 = e.c + (q1 / r1) * (e.p1 - e.c);
  }
  o = e;
  o.p0 = p0;
  o.p1 = p1;
  return true;
}

// Intersections of the two elements taken as whole lines / circles (a spiral: the circle of the
// radius it has at the crossing), each with the parameter of the point on either element: for lines
// the fraction along p0->p1, for arcs the fraction of the sweep from p0 (values outside 0..1 lie on
// the extensions), and the elements' lengths, so that a window on the parameters is a window in mm
// (tol::onElement and the like). A line passing a circle, or two circles passing each other, within
// tol::kPoint touch it.
struct Crossing {
  Vec2 p;
  double u1, u2;
  double len1 = 0, len2 = 0;  // the elements' lengths (an arc: its radius times its sweep)
};
std::vector<Crossing> intersect(const Element& e1, const Element& e2);

// A test of a crossing's fraction u on an element of length len (tol::onElement and the like).
using FractionTest = bool (*)(double u, double len);
// u passes `test` (nullptr: every u passes).
inline bool passesTest(FractionTest test, double u, double len) {
  return test == nullptr || test(u, len);
}

// At most two crossings: what two lines or circles have.
struct CrossingPair {
  Crossing x[2];
  int n = 0;
  const Crossing* begin() const { return x; }
  const Crossing* end() const { return x + n; }
};

// The crossings of intersect(e1, e2) whose fraction on e1 passes `on1` and on e2 passes `on2`
// (nullptr: any), in the same order with the same values, into `out`, without a heap vector; a
// line's test is asked before an arc's fraction (its angles) is computed. false for a spiral
// (take intersect). The fast path of nearestCrossing (docs/performance.md §31).
bool filteredCrossings(const Element& e1, const Element& e2, FractionTest on1, FractionTest on2,
                       CrossingPair& out);

// Of the crossings in `xs` that `accept` takes, the one with the least `key` (of equal keys the
// first found).
template <typename Crossings, typename Accept, typename Key>
std::optional<Crossing> nearestOf(const Crossings& xs, Accept accept, Key key) {
  std::optional<Crossing> best;
  double best_key = 0;
  for (const Crossing& x : xs) {
    if (!accept(x)) continue;
    const double k = key(x);
    if (!best || k < best_key) {
      best = x;
      best_key = k;
    }
  }
  return best;
}

// Of the crossings of e1 and e2 that `accept` takes, the one with the least `key` (of equal
// keys the first found). Every "which crossing counts" rule of radius compensation is one of
// these: nearest the start of e2 (key u2), nearest the start of e1 (u1), nearest the end of e1
// (-u1), nearest a point (the distance to it).
template <typename Accept, typename Key>
std::optional<Crossing> nearestCrossing(const Element& e1, const Element& e2, Accept accept,
                                        Key key) {
  return nearestOf(intersect(e1, e2), accept, key);
}

// The same with the crossings accepted by their fractions alone, on1(u1, len1) and on2(u2,
// len2) (nullptr: any): those tests filter before an arc's angles are computed
// (filteredCrossings); a spiral takes intersect with the same tests.
// Two lines, e2 starting exactly where e1 ends, whose only crossing `on1` refuses without being
// computed: crossingPoints finds it at u1 = cross(d1, d2) / cross(d1, d2), which is 1 exactly (or
// the lines are parallel: none). The approach line into a line and a line into the retraction
// line, where the G460 test refuses the end of e1 (docs/performance.md §36).
inline bool joinedLinesMiss(const Element& e1, const Element& e2, FractionTest on1) {
  return !e1.arc && !e2.arc && e2.p0.a == e1.p1.a && e2.p0.o == e1.p1.o &&
         !passesTest(on1, 1.0, length(e1.p1 - e1.p0));
}

// An arc's change of radius from its start to its end (0: a line, or a circle; else a spiral,
// which intersect follows in steps).
double radiusChange(const Element& e);

// A line joined to the circle of an arc (not a spiral) at one of its own ends, whose crossings
// with that circle filteredCrossings would all refuse: `into` (the approach line, nearestCrossing
// (line, arc) with tol::insideElement on the line): the line ends at the arc's start, running into
// the circle; else (the retraction line, nearestCrossing(arc, line) with tol::afterStart on the
// line): it starts at the arc's end, running out of it. A line entering a circle at E meets it
// again beyond E, one leaving it before E; the other crossing is computed at E within far less
// than tol::kPoint once the line's slope to the circle, the distance w / |line| of that other
// crossing from E, exceeds 1e-4 (1 + G) with G = |centre - line start|^2 + radius^2 (the
// rounding of crossingPoints is some 1e-16 G / (w / |line|)). Squares: no root computed
// (docs/performance.md §42).
inline bool joinedLineArcMiss(const Element& line, const Element& arc, bool into) {
  const Vec2 at = into ? arc.p0 : arc.p1;  // where the line must end / start
  const Vec2 end = into ? line.p1 : line.p0;
  if (line.arc || !arc.arc || end.a != at.a || end.o != at.o) return false;
  const Vec2 d = line.p1 - line.p0, f = line.p0 - arc.c, rv = arc.p0 - arc.c;
  const double w = into ? -dot(at - arc.c, d) : dot(f, d);  // > 0: in / out
  const double g = 1e-4 * (1 + dot(f, f) + dot(rv, rv));
  return w > 0 && w * w > g * g * dot(d, d) && radiusChange(arc) == 0;
}

template <typename Key>
std::optional<Crossing> nearestCrossing(const Element& e1, const Element& e2, FractionTest on1,
                                        FractionTest on2, Key key) {
  if (joinedLinesMiss(e1, e2, on1)) return std::nullopt;
  CrossingPair xs;
  if (filteredCrossings(e1, e2, on1, on2, xs))
    return nearestOf(
        xs, [](const Crossing&) { return true; }, key);
  auto accept = [on1, on2](const Crossing& x) {
    return passesTest(on1, x.u1, x.len1) && passesTest(on2, x.u2, x.len2);
  };
  return nearestCrossing(e1, e2, accept, key);
}

// A full circle about c (radius r) as an element: every point of it has a parameter in [0, 1]
// (so a crossing with it is never on an "extension").
Element fullCircle(Vec2 c, double r);

// The tangent point T on the circle about c (radius r) of a line through p that keeps c on its
// right (s > 0) or its left (s < 0) when travelled p -> T (`towards`) or T -> p. nullopt when p
// lies inside the circle (or on it, within tol::kPoint).
std::optional<Vec2> tangentPoint(Vec2 p, Vec2 c, double r, double s, bool towards);

// The point at fraction u of an element (same parametrisation as Crossing).
Vec2 pointAt(const Element& e, double u);

// An axis-parallel box around an element (arcs: around their whole circle, of the larger of
// their two radii), for a cheap test before intersecting two elements.
struct Box {
  double lo_a = 0, lo_o = 0, hi_a = 0, hi_o = 0;
  Box() = default;
  explicit Box(const Element& e) {
    if (e.arc) {
      const Vec2 d0 = e.p0 - e.c, d1 = e.p1 - e.c;
      const double q0 = dot(d0, d0), q1 = dot(d1, d1), r = std::sqrt(q0 > q1 ? q0 : q1);
      lo_a = e.c.a - r, hi_a = e.c.a + r, lo_o = e.c.o - r, hi_o = e.c.o + r;
    } else {
      // Finite coordinates (block_executor): plain comparisons, no fmin/fmax calls.
      lo_a = e.p0.a < e.p1.a ? e.p0.a : e.p1.a, hi_a = e.p0.a < e.p1.a ? e.p1.a : e.p0.a;
      lo_o = e.p0.o < e.p1.o ? e.p0.o : e.p1.o, hi_o = e.p0.o < e.p1.o ? e.p1.o : e.p0.o;
    }
  }
  bool overlaps(const Box& b) const {
    constexpr double kSlack = tol::kPoint;  // at least the windows of the crossings
    return lo_a <= b.hi_a + kSlack && b.lo_a <= hi_a + kSlack && lo_o <= b.hi_o + kSlack &&
           b.lo_o <= hi_o + kSlack;
  }
};

// The unit tangent in the direction of travel at point p of the element (p on its line/circle).
Vec2 tangentAt(const Element& e, Vec2 p);

}  // namespace ncoffset::geom
