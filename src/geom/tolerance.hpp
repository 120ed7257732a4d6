// The tolerance policy of the compensation geometry: every decision of src/geom/contour.* and
// src/trc/ that compares lengths, radii or directions uses one of these names. What each decides
// and why it has its value: docs/radius-compensation.md, "Tolerances".
//
// In short: the control computes positions to MD10200 $MN_INT_INCR_PER_MM (default 1000
// increments per mm, 1 um); ncoffset computes in doubles and promises its rows to 1e-6 mm (the
// golden cases compare to that). Geometric decisions (the same point, on an element, tangent,
// r = R) use kPoint = 1e-6 mm: far above the rounding noise of doubles on coordinates up to a few
// metres, far below the increment, so no such decision moves a point by more than the promise.
// A transition element (corner circle, DISC curve) shorter than half an increment, kInsert, is
// not inserted (the control cannot traverse it), and two curves that meet at so small an angle
// that their crossing is lost in its own error are joined where the first ends when their ends
// are within kInsert: that moves a corner along the path by at most kInsert and off the
// equidistant by at most kInsert^2 / 2R.
#pragma once

namespace ncoffset::geom::tol {

// MD10200 $MN_INT_INCR_PER_MM default: one increment of the computational resolution (mm).
inline constexpr double kIncrement = 1e-3;
// Lengths (mm). Two points closer than this are the same point (a tangent junction: the two
// equidistants' end points; a zero-length motion); a crossing this far beyond an element's end
// still lies on it; an inside arc whose radius exceeds R by no more than this has no
// equidistant (r = R); two compensation values closer than this are equal; a point this far on
// the material side of a tangent line is not behind it.
inline constexpr double kPoint = 1e-6;
// The shortest transition element radius compensation inserts at a corner (mm): a G450 circle
// or DISC curve whose chord is shorter is replaced by the intersection of the equidistants (half
// an increment: such an element has no motion on the control).
inline constexpr double kInsert = 0.5 * kIncrement;
// How far the chords of a DISC transition curve may deviate from the curve (mm): one increment.
inline constexpr double kChord = kIncrement;
// Unit directions whose cross product (the sine of their angle) is below this are parallel or
// antiparallel (a reversal is a 180 degree turn within it).
inline constexpr double kParallel = 1e-12;
// A turn whose sine is below this is no turn: the turn condition of bottleneck detection (the new
// element turns towards the compensation side at a crossing when the sine of its turn exceeds
// this, W1 2.4.8, details Q5); the tangents of a DISC curve that do not meet.
inline constexpr double kTurn = 1e-9;
// Guards of the arithmetic only, never a geometric decision: a zero denominator, a zero sweep (an
// arc whose end is its start is a full circle), concentric circles, a frame whose products are
// lengths-preserving up to their rounding, DISC = 100.
inline constexpr double kNumeric = 1e-12;

// A point at fraction u of an element of length `len` (Crossing::u1/u2, Crossing::len1/len2) lies
// on the element: from kPoint before its start to kPoint beyond its end.
inline bool onElement(double u, double len) {
  return u * len >= -kPoint && (u - 1) * len <= kPoint;
}
// Strictly inside the element: more than kPoint after its start and before its end.
inline bool insideElement(double u, double len) {
  return u * len > kPoint && (1 - u) * len > kPoint;
}
// At or beyond the end (within kPoint): on the element's extension past its end.
inline bool pastEnd(double u, double len) {
  return (u - 1) * len > -kPoint;
}
// At or before the start (within kPoint): on the extension before its start.
inline bool beforeStart(double u, double len) {
  return u * len < kPoint;
}
// More than kPoint after the start / before the end.
inline bool afterStart(double u, double len) {
  return u * len > kPoint;
}
inline bool beforeEnd(double u, double len) {
  return (1 - u) * len > kPoint;
}

}  // namespace ncoffset::geom::tol
