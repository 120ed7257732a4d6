// Straight lines given by an angle (PM-NC 12/2019 2.9.9.1-2.9.9.5 "Contour definitions") and the
// circles through an intermediate point (CIP) and tangential to the previous element (CT)
// (2.9.2 "Circular interpolation"): docs/contour-definitions.md.
#include <fmt/format.h>

#include <cmath>

#include "core/not_modelled.hpp"
#include "geom/contour.hpp"
#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

namespace {

using geom::Vec2;

Vec2 inPlane(const Vec3& p, PlaneAxes pa) {
  return {p[pa.abscissa], p[pa.ordinate]};
}

Vec2 direction(double degrees) {
  return {std::cos(degrees * kRadPerDegree), std::sin(degrees * kRadPerDegree)};
}

// Directions closer than this (sine of the angle between them) are the same line.
constexpr double kSameDirection = 1e-9;

}  // namespace

// ANG= in this block, or the block after an `ANG=` block. False: the block is built (its end
// point completed here); true: it is the first block of a two-angle definition and waits.
bool Interpreter::angleLine(bool builds) {
  ContourWords none;
  const ContourWords& cw = words_.contour ? contour_words_ : none;
  const PlaneAxes pa = planeAxes(modal_.plane);
  const bool ha = words_.axis[pa.abscissa], ho = words_.axis[pa.ordinate];
  const bool arc = modal_.motion == Motion::G2 || modal_.motion == Motion::G3;
  if (arc)
    raise(AlarmNumber::AngleLineInterpolation,
          "ANG= defines straight lines: not allowed with G2/G3/CIP/CT (or after an ANG= block "
          "waiting for its second line)");
  const Vec3 end = motion_.programmedTarget(words_, modal_);
  if (contour_.pending) {
    if (!builds || !ha || !ho || modal_.plane != contour_.pending->modal.plane)
      raise(AlarmNumber::AngleLineSecondBlock,
            "the block after a block with ANG= alone must end the second line: both coordinates "
            "of the plane and its angle ANG=");
    if (!cw.ang)
      raise(AlarmNumber::AngleLineSecondAngle,
            "the second block of a contour definition with two angles needs its angle ANG=");
    const Vec2 s = inPlane(contour_.pending->start, pa), e = inPlane(end, pa);
    const Vec2 d1 = direction(contour_.pending->angle), d2 = direction(*cw.ang);
    const double det = geom::cross(d1, d2);
    if (std::fabs(det) < kSameDirection)
      raise(AlarmNumber::AngleLineContradiction,
            "the two lines of the contour definition are parallel: no intersection");
    // s + t d1 = e - u d2: the first line leaves s along ANG 1, the second reaches e along ANG 2.
    const Vec2 w = e - s;
    const double t = geom::cross(w, d2) / det, u = geom::cross(d1, w) / det;
    if (t < -geom::tol::kPoint || u < -geom::tol::kPoint)
      raise(AlarmNumber::AngleLineContradiction,
            "the two lines of the contour definition meet only against their angles");
    Vec3 corner = contour_.pending->start;
    corner[pa.abscissa] = s.a + t * d1.a;
    corner[pa.ordinate] = s.o + t * d1.o;
    buildPendingLine(corner);
    return false;
  }
  const Vec2 s = inPlane(motion_.wcs(), pa), e = inPlane(end, pa), d = direction(*cw.ang);
  if (!ha && !ho) {
    if (words_.sar != core::SarKind::None)
      core::notModelled("ANG= in a SAR block", "a smooth approach along an angle");
    contour_.pending =
        PendingLine{words_,          modal_,        {line_, file_, feed_before_, motion_before_},
                    cornerRequest(), motion_.wcs(), *cw.ang};
    return true;
  }
  const Vec2 w = e - s;
  if (ha != ho) {  // one coordinate: the other from the angle (PM-NC 2.9.9.1)
    const double along = ha ? d.a : d.o, given = ha ? w.a : w.o;
    const double t = std::fabs(along) > kSameDirection ? given / along : -1;
    if (t < -geom::tol::kPoint || (std::fabs(along) <= kSameDirection))
      raise(AlarmNumber::AngleLineContradiction,
            fmt::format("the end point cannot be reached along ANG={}", *cw.ang));
    const int other = ha ? pa.ordinate : pa.abscissa;
    setAbsoluteWord(words_, modal_, other, (ha ? s.o : s.a) + t * (ha ? d.o : d.a), false);
    return false;
  }
  // Both coordinates and ANG=: the angle must be the line's (the control checks it).
  if (geom::length(w) > geom::tol::kPoint &&
      (std::fabs(geom::cross(geom::unit(w), d)) > 1e-6 || geom::dot(w, d) < 0))
    raise(AlarmNumber::AngleLineContradiction,
          fmt::format("the end point does not lie on the line of ANG={}", *cw.ang));
  return false;
}

// The first block of a two-angle definition, now that its end point is known.
void Interpreter::buildPendingLine(const Vec3& end) {
  PendingLine p = *contour_.pending;
  contour_.pending.reset();
  const PlaneAxes pa = planeAxes(p.modal.plane);
  setAbsoluteWord(p.words, p.modal, pa.abscissa, end[pa.abscissa], false);
  setAbsoluteWord(p.words, p.modal, pa.ordinate, end[pa.ordinate], false);
  if (p.request.kind != CornerRequest::Kind::None) motion_.cornerRequest(p.request);
  motion_.build(p.words, p.modal, p.at);
}

// The block's circle under CIP or CT: its centre and direction from the points.
void Interpreter::circleForm() {
  if (words_.centre[0] || words_.centre[1] || words_.centre[2] || words_.cr || words_.ar)
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: CIP/CT take the end point only (and I1=, J1=, K1= for CIP)");
  const PlaneAxes pa = planeAxes(modal_.plane);
  const Vec3 from = motion_.wcs(), to = motion_.programmedTarget(words_, modal_);
  if (contour_.circle == CircleForm::Cip)
    cipCircle(pa, from, to);
  else
    ctCircle(pa, from, to);
}

// CIP: the circle through the start, the intermediate point I1=, J1=, K1= and the end point.
// I1.. are absolute under G90 and relative to the start under G91 (AC/IC for one value).
void Interpreter::cipCircle(PlaneAxes pa, const Vec3& from, const Vec3& to) {
  const ContourWords& cw = contour_words_;
  Vec3 mid = from;
  for (int i = 0; i < 3; ++i) {
    if (!words_.contour || !cw.inter[i]) continue;
    const lang::AxisMode m = cw.inter_mode[i];
    const bool abs =
        m == lang::AxisMode::AC || (m == lang::AxisMode::Default && !modal_.incremental);
    const double v = toMm(cw.inter_value[i]);
    mid[i] = abs ? v * modal_.diam_abs[i] : from[i] + v * modal_.diam_inc[i];
  }
  if (words_.turn)
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: TURN= is not allowed with CIP");
  if (std::fabs(mid[pa.applicate] - from[pa.applicate]) > geom::tol::kPoint ||
      std::fabs(to[pa.applicate] - from[pa.applicate]) > geom::tol::kPoint)
    core::notModelled("CIP with points off the working plane",
                      "ncoffset models CIP circles in a plane parallel to G17/G18/G19 = the active "
                      "plane; select that plane");
  const Vec2 s = inPlane(from, pa), m = inPlane(mid, pa), e = inPlane(to, pa);
  const Vec2 b = m - s, c = e - s;
  const double det = 2 * geom::cross(b, c);
  if (std::fabs(det) < 1e-12 * (geom::dot(b, b) + geom::dot(c, c)) ||
      geom::length(c) <= geom::tol::kPoint)
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: the start, intermediate and end point of CIP lie on one line "
          "(or coincide): no circle");
  // The circumcentre relative to s: |x - b|^2 = |x|^2 = |x - c|^2.
  const double bb = geom::dot(b, b), ccc = geom::dot(c, c);
  const Vec2 centre{s.a + (c.o * bb - b.o * ccc) / det, s.o + (b.a * ccc - c.a * bb) / det};
  modal_.motion = det > 0 ? Motion::G3 : Motion::G2;  // s -> m -> e counter-clockwise: G3
  setAbsoluteWord(words_, modal_, pa.abscissa, centre.a, true);
  setAbsoluteWord(words_, modal_, pa.ordinate, centre.o, true);
}

// CT: the circle from the start, tangent to the previous element there, to the end point.
void Interpreter::ctCircle(PlaneAxes pa, const Vec3& from, const Vec3& to) {
  const core::MotionBlock& prev = motion_.lastBlock();
  Vec2 t;
  if (motion_.motionsSent() > 0 && prev.plane == modal_.plane) {
    const Vec2 p0 = inPlane(prev.start, pa), p1 = inPlane(prev.end, pa);
    if (prev.motion == Motion::G2 || prev.motion == Motion::G3) {
      const Vec2 radial = p1 - inPlane(prev.centre, pa);
      t = prev.motion == Motion::G3 ? geom::leftNormal(radial) : -1.0 * geom::leftNormal(radial);
    } else {
      t = p1 - p0;
    }
  }
  if (geom::length(t) <= geom::tol::kPoint)
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: CT needs a previous element moving in the plane");
  const Vec2 s = inPlane(from, pa), e = inPlane(to, pa), n = geom::leftNormal(geom::unit(t));
  const Vec2 w = e - s;
  const double q = geom::dot(w, n);
  if (std::fabs(q) <= geom::tol::kPoint)
    raise(AlarmNumber::CircleProgramming,
          "circle programming error: the end point of CT lies on the tangent: no circle");
  const double rho = geom::dot(w, w) / (2 * q);  // > 0: the centre on the left, G3
  modal_.motion = rho > 0 ? Motion::G3 : Motion::G2;
  setAbsoluteWord(words_, modal_, pa.abscissa, s.a + rho * n.a, true);
  setAbsoluteWord(words_, modal_, pa.ordinate, s.o + rho * n.o, true);
}

}  // namespace ncoffset::interp
