// The elements of the radius compensation window (W1 2.4, details Q8): a block as a plane
// element, its equidistant (also with a compensation value that changes within the block), and
// a compensated element back as a block of the channel.
#include <cmath>

#include "core/inline_step.hpp"
#include "trc/compensation_internal.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
using core::TrcStrategy;
namespace tol = geom::tol;
using geom::Element;
using geom::Vec2;

namespace {
// The block's plane element in program coordinates (toElement without the metric; inlined into
// compensateInto, which writes it straight into the slot, §31).
NCOFFSET_INLINE_STEP Element planeElement(const MotionBlock& m) {
  PlaneAxes pa = planeAxes(m.plane);
  Element e;
  e.p0 = {m.start[pa.abscissa], m.start[pa.ordinate]};
  e.p1 = {m.end[pa.abscissa], m.end[pa.ordinate]};
  if (m.motion == Motion::G2 || m.motion == Motion::G3) {
    e.arc = true;
    e.c = {m.centre[pa.abscissa], m.centre[pa.ordinate]};
    e.ccw = m.motion == Motion::G3;
    e.turns = m.turns;
  }
  return e;
}
}  // namespace

Element RadiusCompensation::toElement(const MotionBlock& m) const {
  Element e = planeElement(m);
  if (!metric_.identity) toMetric(e);
  return e;
}

void RadiusCompensation::toMetric(Element& e) const {
  // A scaling frame: the machine's lengths (plane_metric.hpp).
  e.p0 = metric_.to(e.p0);
  e.p1 = metric_.to(e.p1);
  e.c = metric_.to(e.c);
}

Element RadiusCompensation::fromMetric(const Element& e) const {
  // From the machine's lengths back to the program's coordinates (plane_metric.hpp).
  Element back = e;
  back.p0 = metric_.from(e.p0);
  back.p1 = metric_.from(e.p1);
  back.c = metric_.from(e.c);
  return back;
}

MotionBlock RadiusCompensation::toBlock(const MotionBlock& like, const Element& e) const {
  // Every block compensation makes lies on the path of S: P - S at both ends (the approach and
  // retraction lines clear one, detail::keepTipAt). Not per element: emitPiece marks those.
  const std::uint8_t tip_at = like.has_tip ? core::kTipBoth : core::kTipNone;
  return core::withGeometry(
      like, core::planeGeometry(like, metric_.identity ? e : fromMetric(e), tip_at));
}

MotionBlock RadiusCompensation::lineToEnd(const MotionBlock& m, const Element& e) const {
  MotionBlock b = m;  // (one object returned on both paths: no second copy)
  if (!metric_.identity || general_paths_ || m.motion == Motion::G2 || m.motion == Motion::G3) {
    b = toBlock(m, e);
    return b;
  }
  // toBlock without the geometry in between (§36): of the block only the plane start changes
  // (`e` ends at the block's own end, and lines stay G0/G1).
  const PlaneAxes pa = planeAxes(m.plane);
  b.start[pa.abscissa] = e.p0.a;
  b.start[pa.ordinate] = e.p0.o;
  b.tip_at = m.has_tip ? core::kTipBoth : core::kTipNone;
  return b;
}

MotionBlock RadiusCompensation::atPoint(const MotionBlock& like, Vec2 at) const {
  Element e;
  e.p0 = e.p1 = at;
  return toBlock(like, e);
}

RadiusCompensation::Piece RadiusCompensation::compensate(const MotionBlock& m, double r0,
                                                         double r1) const {
  Piece p;
  compensateInto(p, m, r0, r1);
  return p;
}

NCOFFSET_INLINE_STEP void RadiusCompensation::startPiece(Piece& p, const MotionBlock& m, double r0,
                                                         double r1) const {
  // Every field is set: `p` may be a reused slot of the window (its vectors keep their memory).
  p.index = 0;
  p.valid = true;
  p.open_before = p.approach = p.restart = p.emitted = false;
  p.strategy = TrcStrategy::G460;
  p.transition.clear();
  p.waiting.clear();
  p.block = m;
  p.r0 = r0;
  p.r1 = r1;
  p.side = side();
}

NCOFFSET_INLINE_STEP void RadiusCompensation::compensateConstant(Piece& p, const MotionBlock& m,
                                                                 double r) const {
  // planeElement and equidistantInto with the same arithmetic, from values in registers: each
  // field of the slot written once (the general path writes the element, reads it back and
  // copies it whole into the equidistant).
  const PlaneAxes pa = planeAxes(m.plane);
  const Vec2 a{m.start[pa.abscissa], m.start[pa.ordinate]};
  const Vec2 b{m.end[pa.abscissa], m.end[pa.ordinate]};
  const double d = p.side * r;
  Element& e = p.programmed;
  Element& o = p.compensated;
  e.p0 = a;
  e.p1 = b;
  if (m.motion != Motion::G2 && m.motion != Motion::G3) {
    e.arc = e.ccw = false;
    e.c = {};
    e.turns = 0;
    const Vec2 n = geom::leftNormal(geom::unit(b - a));
    o = e;
    o.p0 = a + d * n;
    o.p1 = b + d * n;
    return;
  }
  const Vec2 c{m.centre[pa.abscissa], m.centre[pa.ordinate]};
  e.arc = true;
  e.c = c;
  e.ccw = m.motion == Motion::G3;
  e.turns = m.turns;
  const double r0 = geom::length(a - c), r1 = geom::length(b - c);
  const double q0 = e.ccw ? r0 - d : r0 + d, q1 = e.ccw ? r1 - d : r1 + d;
  if (q0 <= tol::kPoint || q1 <= tol::kPoint) {  // r <= R: none (the slot's element stays)
    p.valid = false;
    return;
  }
  o = e;
  o.p0 = c + (q0 / r0) * (a - c);
  o.p1 = c + (q1 / r1) * (b - c);
}

void RadiusCompensation::compensateInto(Piece& p, const MotionBlock& m, double r0,
                                        double r1) const {
  startPiece(p, m, r0, r1);
  if (r0 == r1 && metric_.identity && !general_paths_) {  // the usual element (§36)
    compensateConstant(p, m, r0);
    keepRaw(p);
    return;
  }
  p.programmed = planeElement(m);
  if (!metric_.identity) toMetric(p.programmed);
  const double s = p.side;
  if (r0 == r1) {
    p.valid = geom::equidistantInto(p.programmed, s * r0, p.compensated);
  } else if (!p.programmed.arc) {
    // A new value in a line: from start + R_old n to end + R_new n (details Q8).
    Vec2 n = s * geom::leftNormal(p.programmed.startTangent());
    p.compensated = p.programmed;
    p.compensated.p0 = p.programmed.p0 + r0 * n;
    p.compensated.p1 = p.programmed.p1 + r1 * n;
  } else {
    // A new value in a circle: a spiral from radius r -+ R_old to r -+ R_new (details Q8).
    const Element& e = p.programmed;
    const double r = e.radius();
    const double k = e.ccw ? -s : s;  // the left side of a ccw arc is its inside
    const double ra = r + k * r0, rb = geom::length(e.p1 - e.c) + k * r1;
    if (ra <= tol::kPoint || rb <= tol::kPoint)
      raise(AlarmNumber::TrcCurvatureTooSmall,
            "curvature radius with variable compensation value too small");
    p.compensated = e;
    p.compensated.p0 = e.c + (ra / r) * (e.p0 - e.c);
    p.compensated.p1 = e.c + (rb / geom::length(e.p1 - e.c)) * (e.p1 - e.c);
  }
  keepRaw(p);
}

Element RadiusCompensation::cornerEquidistant(const Piece& p, bool at_end) const {
  if (p.r0 == p.r1) return p.compensated;
  double r = at_end ? p.r1 : p.r0;
  auto e = geom::equidistant(p.programmed, p.side * r);
  return e ? *e : p.compensated;
}

void RadiusCompensation::emitPiece(const Piece& p) {
  // On the path of S (the approach line starts where P stood): P - S (cutting-edge-positions.md).
  const std::uint8_t tip_at = !p.block.has_tip ? core::kTipNone
                              : p.approach     ? core::kTipEnd
                                               : core::kTipBoth;
  // The usual piece: nothing inserted before it, no block waiting after it, no scaling frame.
  // The element itself goes on, no copy of the block nor a geometry built from the two, in a
  // tail call (docs/performance.md §37).
  if (p.transition.empty() && p.waiting.empty() && metric_.identity) [[likely]]
    return out_.element(p.block, p.compensated, tip_at);
  emitWithBlocks(p, tip_at);
}

void RadiusCompensation::emitWithBlocks(const Piece& p, std::uint8_t tip_at) {
  for (const MotionBlock& t : p.transition) emit(t);
  if (metric_.identity)
    out_.element(p.block, p.compensated, tip_at);
  else
    out_.element(p.block, fromMetric(p.compensated), tip_at);
  for (const MotionBlock& w : p.waiting) emit(atPoint(w, p.compensated.p1));
}

}  // namespace ncoffset::trc
