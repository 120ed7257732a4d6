// The usual element of the radius compensation window: one compensation value, no scaling
// frame. Its steps are inline here for compensateInto (pieces.cpp) and motionOn
// (radius_compensation.cpp), which builds it without a call (docs/performance.md §42); and a
// block's plane element (toElement), inline for every caller.
#pragma once

#include "core/inline_step.hpp"
#include "trc/compensation_internal.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {

// The block's plane element in program coordinates (toElement without the metric; inlined into
// compensateInto, which writes it straight into the slot, §31).
NCOFFSET_INLINE_STEP geom::Element planeElement(const core::MotionBlock& m) {
  PlaneAxes pa = planeAxes(m.plane);
  geom::Element e;
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

// (Inline: the approach and the retraction write it straight into the slot or a local, §42.)
inline geom::Element RadiusCompensation::toElement(const core::MotionBlock& m) const {
  geom::Element e = planeElement(m);
  if (!metric_.identity) toMetric(e);
  return e;
}

NCOFFSET_INLINE_STEP void RadiusCompensation::startPiece(Piece& p, double r0, double r1, long index,
                                                         bool restart) const {
  // Every field is set: `p` may be a reused slot of the window (its vectors keep their memory).
  p.index = index;
  p.valid = true;
  p.restart = restart;
  p.open_before = p.approach = p.emitted = false;
  p.strategy = core::TrcStrategy::G460;
  p.transition.clear();
  p.waiting.clear();
  p.r0 = r0;
  p.r1 = r1;
  p.side = side();
}

NCOFFSET_INLINE_STEP void RadiusCompensation::compensateConstant(Piece& p,
                                                                 const core::MotionBlock& m,
                                                                 double r, double length,
                                                                 PlaneAxes pa) const {
  // planeElement and equidistantInto with the same arithmetic, from values in registers: each
  // field of the slot written once, and the equidistant's ends kept (keepRaw) from the same
  // registers (the general path writes the element, reads it back and copies it whole into the
  // equidistant).
  const geom::Vec2 a = planePoint(m.start, pa), b = planePoint(m.end, pa);
  const double d = p.side * r;
  geom::Element& e = p.programmed;
  geom::Element& o = p.compensated;
  e.p0 = a;
  e.p1 = b;
  if (m.motion != Motion::G2 && m.motion != Motion::G3) {
    e.arc = o.arc = e.ccw = o.ccw = false;
    e.c = o.c = {};
    e.turns = o.turns = 0;
    // geom::unit(b - a) with the length motionOn measured (> kPoint, so > 0): the same root.
    const geom::Vec2 t = length > 0 ? (1.0 / length) * (b - a) : geom::unit(b - a);
    const geom::Vec2 n = geom::leftNormal(t);
    o.p0 = p.raw_start = a + d * n;
    o.p1 = p.raw_end = b + d * n;
    return;
  }
  const geom::Vec2 c = planePoint(m.centre, pa);
  e.arc = true;
  e.c = c;
  e.ccw = m.motion == Motion::G3;
  e.turns = m.turns;
  const double r0 = geom::length(a - c), r1 = geom::length(b - c);
  const double q0 = e.ccw ? r0 - d : r0 + d, q1 = e.ccw ? r1 - d : r1 + d;
  if (q0 <= geom::tol::kPoint || q1 <= geom::tol::kPoint) {
    p.valid = false;  // r <= R: none (the slot's element stays)
    p.raw_start = o.p0;
    p.raw_end = o.p1;
    return;
  }
  o.arc = true;
  o.c = c;
  o.ccw = e.ccw;
  o.turns = e.turns;
  o.p0 = p.raw_start = c + (q0 / r0) * (a - c);
  o.p1 = p.raw_end = c + (q1 / r1) * (b - c);
}

// The slot's block is copied last: nothing is kept in registers across the copy's call.
// (keepRaw's ends are written by compensateConstant.)
NCOFFSET_INLINE_STEP void RadiusCompensation::compensateUsual(Piece& p, const core::MotionBlock& m,
                                                              double r, long index, bool restart,
                                                              double length, PlaneAxes pa) const {
  startPiece(p, r, r, index, restart);
  compensateConstant(p, m, r, length, pa);
  p.box_known = false;
  copyBlock(p.block, m);
}

// (Inline: release writes an element a block, now without the call, §48.)
NCOFFSET_INLINE_STEP void RadiusCompensation::emitPiece(const Piece& p) {
  // On the path of S (the approach line starts where P stood): P - S (cutting-edge-positions.md).
  const std::uint8_t tip_at = !p.block.has_tip ? core::kTipNone
                              : p.approach     ? core::kTipEnd
                                               : core::kTipBoth;
  // The usual piece: nothing inserted before it, no block waiting after it, no scaling frame.
  // The element itself goes on, no copy of the block nor a geometry built from the two
  // (docs/performance.md §37).
  if (p.transition.empty() && p.waiting.empty() && metric_.identity) [[likely]]
    return out_.element(p.block, p.compensated, tip_at);
  emitWithBlocks(p, tip_at);
}

// (Inline: retract's, once a lap, §48.)
NCOFFSET_INLINE_STEP void RadiusCompensation::lineToEnd(core::MotionBlock& b,
                                                        const core::MotionBlock& m,
                                                        const geom::Element& e) const {
  if (!metric_.identity || general_paths_ || m.motion == Motion::G2 || m.motion == Motion::G3) {
    b = toBlock(m, e);
    return;
  }
  copyBlock(b, m);
  // toBlock without the geometry in between (§36): of the block only the plane start changes
  // (`e` ends at the block's own end, and lines stay G0/G1).
  const PlaneAxes pa = planeAxes(m.plane);
  b.start[pa.abscissa] = e.p0.a;
  b.start[pa.ordinate] = e.p0.o;
  b.tip_at = m.has_tip ? core::kTipBoth : core::kTipNone;
}

}  // namespace ncoffset::trc
