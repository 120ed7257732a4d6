// Chamfer and rounding geometry (PM-NC 12/2019 "Chamfer, rounding"): docs/contour-definitions.md.
#include "geom/corner_cut.hpp"

#include <algorithm>
#include <cmath>

namespace ncoffset::geom {

double elementLength(const Element& e) {
  return e.arc ? e.radius() * std::fabs(e.sweep()) : length(e.p1 - e.p0);
}

namespace {

// The longest chord from the corner end of the element that stays on it (an arc's chord grows
// up to its diameter).
double maxChord(const Element& e) {
  if (!e.arc) return length(e.p1 - e.p0);
  const double sweep = std::fabs(e.sweep());
  return 2 * e.radius() * (sweep >= kPi ? 1.0 : std::sin(sweep / 2));
}

// The fraction of e at chord distance s from its end (from_end) or from its start.
double fractionAtChord(const Element& e, bool from_end, double s) {
  double f = 0;
  if (!e.arc) {
    const double len = length(e.p1 - e.p0);
    f = len > 0 ? s / len : 0;
  } else {
    const double r = e.radius(), sweep = std::fabs(e.sweep());
    const double phi = 2 * std::asin(std::min(1.0, s / (2 * r)));
    f = sweep > 0 ? phi / sweep : 0;
  }
  f = std::clamp(f, 0.0, 1.0);
  return from_end ? 1 - f : f;
}

bool tangentJunction(const Element& e1, const Element& e2) {
  const Vec2 t1 = e1.endTangent(), t2 = e2.startTangent();
  return std::fabs(cross(t1, t2)) < tol::kTurn;  // straight on, or a reversal
}

// The rounding's centre for radius r: the crossing of the two equidistants on the inside of the
// corner whose feet lie on both elements, nearest the corner.
// `slack`: how far (mm) a tangent point may lie beyond an element's end.
std::optional<Crossing> roundingCentre(const Element& e1, const Element& e2, double d,
                                       double slack) {
  const auto q1 = equidistant(e1, d), q2 = equidistant(e2, d);
  if (!q1 || !q2) return std::nullopt;
  const double l1 = elementLength(e1), l2 = elementLength(e2);
  auto on = [slack](double u, double len) { return u * len >= -slack && (u - 1) * len <= slack; };
  return nearestCrossing(
      *q1, *q2, [&](const Crossing& x) { return on(x.u1, l1) && on(x.u2, l2); },
      [&](const Crossing& x) { return (1 - x.u1) * l1 + x.u2 * l2; });
}

}  // namespace

CornerCut chamferCorner(const Element& e1, const Element& e2, ChamferKind kind, double value) {
  CornerCut cut;
  cut.q1 = e1.p1;
  cut.q2 = e2.p0;
  if (tangentJunction(e1, e2) || value <= 0) return cut;
  const double smax = std::min(maxChord(e1), maxChord(e2));
  auto chord = [&](double s) {
    return length(pointAt(e2, fractionAtChord(e2, false, s)) -
                  pointAt(e1, fractionAtChord(e1, true, s)));
  };
  double s = std::min(value, smax);
  if (kind == ChamferKind::Length && chord(smax) > value) {
    // Equal legs whose chord is the chamfer's length: the chord grows with the legs.
    double lo = 0, hi = smax;
    for (int i = 0; i < 100 && hi - lo > 1e-15 * (1 + hi); ++i) {
      const double mid = 0.5 * (lo + hi);
      (chord(mid) < value ? lo : hi) = mid;
    }
    s = 0.5 * (lo + hi);
  }
  if (s <= tol::kInsert) return cut;
  cut.u1 = fractionAtChord(e1, true, s);
  cut.u2 = fractionAtChord(e2, false, s);
  cut.q1 = pointAt(e1, cut.u1);
  cut.q2 = pointAt(e2, cut.u2);
  cut.inserted = true;
  cut.value = kind == ChamferKind::Leg ? s : length(cut.q2 - cut.q1);
  return cut;
}

CornerCut roundCorner(const Element& e1, const Element& e2, double r) {
  CornerCut cut;
  cut.q1 = e1.p1;
  cut.q2 = e2.p0;
  if (tangentJunction(e1, e2) || r <= 0) return cut;
  const bool left = cross(e1.endTangent(), e2.startTangent()) > 0;
  const double side = left ? 1.0 : -1.0;
  std::optional<Crossing> x = roundingCentre(e1, e2, side * r, tol::kPoint);
  double used = r;
  if (!x) {
    // Too large for the elements: the largest radius that fits (the manual: reduced).
    double lo = 0, hi = r;
    for (int i = 0; i < 100 && hi - lo > 1e-15 * (1 + hi); ++i) {
      const double mid = 0.5 * (lo + hi);
      (roundingCentre(e1, e2, side * mid, 0) ? lo : hi) = mid;
    }
    used = lo;
    if (used <= tol::kInsert) return cut;
    x = roundingCentre(e1, e2, side * used, 0);
    if (!x) return cut;
  }
  cut.u1 = std::clamp(x->u1, 0.0, 1.0);
  cut.u2 = std::clamp(x->u2, 0.0, 1.0);
  cut.q1 = pointAt(e1, cut.u1);
  cut.q2 = pointAt(e2, cut.u2);
  cut.centre = x->p;
  cut.ccw = left;
  cut.round = true;
  cut.inserted = true;
  cut.value = used;
  return cut;
}

}  // namespace ncoffset::geom
