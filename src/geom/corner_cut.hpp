// Chamfers and roundings between two contour elements (PM-NC "Chamfer, rounding (CHF, CHR, RND,
// RNDM, FRC, FRCM)"): where the first element is cut back, where the second starts again and
// what is inserted between them. Lines and arcs in the active plane's (abscissa, ordinate).
#pragma once

#include "geom/contour.hpp"

namespace ncoffset::geom {

// The result of cutting the corner where e1 ends and e2 starts (e1.p1 == e2.p0).
struct CornerCut {
  bool inserted = false;  // false: nothing inserted (tangent junction, value reduced to 0)
  bool round = false;     // a rounding arc (else a chamfer line)
  double u1 = 1, u2 = 0;  // e1 is kept over [0, u1], e2 over [u2, 1] (fractions as pointAt)
  Vec2 q1, q2;            // the inserted element's start (on e1) and end (on e2)
  Vec2 centre;            // rounding: its centre
  bool ccw = false;       // rounding: G3 in the plane
  double value = 0;       // the value used (reduced when the elements are too short)
};

// The length of a line or an arc (radius times sweep).
double elementLength(const Element& e);

enum class ChamferKind { Length, Leg };  // CHF= (the chamfer's length), CHR= (the legs)

// A chamfer of the given kind and value. The manual: a value too large for the elements is
// reduced to what fits; so is this one (legs at most the elements' lengths).
CornerCut chamferCorner(const Element& e1, const Element& e2, ChamferKind kind, double value);

// A rounding arc of radius r tangent to both elements, reduced as a chamfer is.
CornerCut roundCorner(const Element& e1, const Element& e2, double r);

}  // namespace ncoffset::geom
