// Chamfers and roundings between two motion blocks: docs/contour-definitions.md.
#include "interp/corner_stage.hpp"

#include <cmath>

#include "core/not_modelled.hpp"
#include "geom/corner_cut.hpp"

namespace ncoffset::interp {

namespace {

using core::MotionBlock;

// PM-NC "Chamfer, rounding": no chamfer/rounding when more than three blocks without motion in
// the plane stand between the two blocks.
constexpr int kMaxBlocksBetween = 3;

bool isArc(const MotionBlock& m) {
  return m.motion == Motion::G2 || m.motion == Motion::G3;
}

geom::Element planeElement(const MotionBlock& m, PlaneAxes pa) {
  geom::Element e;
  e.arc = isArc(m);
  e.p0 = {m.start[pa.abscissa], m.start[pa.ordinate]};
  e.p1 = {m.end[pa.abscissa], m.end[pa.ordinate]};
  e.c = {m.centre[pa.abscissa], m.centre[pa.ordinate]};
  e.ccw = m.motion == Motion::G3;
  e.turns = m.turns;
  return e;
}

bool movesInPlane(const MotionBlock& m, PlaneAxes pa) {
  return isArc(m) || std::fabs(m.end[pa.abscissa] - m.start[pa.abscissa]) > geom::tol::kPoint ||
         std::fabs(m.end[pa.ordinate] - m.start[pa.ordinate]) > geom::tol::kPoint;
}

// The point of the block's geometry at fraction u (the applicate linear in u, as a helix).
Vec3 pointOf(const MotionBlock& m, PlaneAxes pa, geom::Vec2 p, double u) {
  Vec3 v = m.start;
  v[pa.abscissa] = p.a;
  v[pa.ordinate] = p.o;
  v[pa.applicate] = m.start[pa.applicate] + u * (m.end[pa.applicate] - m.start[pa.applicate]);
  return v;
}

}  // namespace

core::Feedback CornerStage::motion(const MotionBlock& m) {
  const CornerRequest req = request_;
  request_.kind = CornerRequest::Kind::None;
  MotionBlock b = m;
  if (held_) {
    const bool cut = joinable(block_, b);
    const bool left = cut ? cutCorner(b) : true;
    if (!cut) release();
    held_ = false;
    // Reduced to the whole of b (PM-NC: a value too large is reduced): nothing of b is left,
    // and a chamfer/rounding at its end has no length either.
    if (!left) return {};
  }
  if (req.kind != CornerRequest::Kind::None) {
    if (b.sar.kind != core::SarKind::None)
      core::notModelled("CHF/CHR/RND in a smooth approach block (G147..G348)",
                        "a chamfer or rounding at a SAR block is not modelled");
    block_ = b;
    held_request_ = req;
    held_ = true;
    dummies_ = 0;
    return {};
  }
  return next_.motion(b);
}

void CornerStage::blockWithoutMotion() {
  if (!held_) {
    next_.blockWithoutMotion();
    return;
  }
  if (++dummies_ > kMaxBlocksBetween) release();
}

bool CornerStage::joinable(const MotionBlock& a, const MotionBlock& b) {
  if (b.plane != a.plane || b.sar.kind != core::SarKind::None || b.frame.state() != a.frame.state())
    return false;  // a plane change: no chamfer/rounding (PM-NC); a frame change [D]
  const PlaneAxes pa = planeAxes(b.plane);
  return movesInPlane(b, pa) && movesInPlane(a, pa);
}

void CornerStage::release() {
  if (!held_) return;
  held_ = false;
  next_.motion(block_);
  replayDummies();
}

void CornerStage::replayDummies() {
  for (; dummies_ > 0; --dummies_) next_.blockWithoutMotion();
}

bool CornerStage::cutCorner(MotionBlock& b) {
  const PlaneAxes pa = planeAxes(b.plane);
  if (block_.turns > 0 || b.turns > 0)
    core::notModelled("CHF/CHR/RND next to a circle with TURN=",
                      "a chamfer or rounding at a helix with full turns is not modelled");
  const geom::Element e1 = planeElement(block_, pa), e2 = planeElement(b, pa);
  const CornerRequest& r = held_request_;
  const geom::CornerCut cut =
      r.kind == CornerRequest::Kind::Rnd
          ? geom::roundCorner(e1, e2, r.value)
          : geom::chamferCorner(e1, e2,
                                r.kind == CornerRequest::Kind::Chf ? geom::ChamferKind::Length
                                                                   : geom::ChamferKind::Leg,
                                r.value);
  if (!cut.inserted) {
    release();
    return true;
  }
  MotionBlock first = block_;
  first.end = pointOf(block_, pa, cut.q1, cut.u1);
  MotionBlock inserted = block_;  // the technology of the block before the corner
  inserted.start = first.end;
  inserted.end = pointOf(b, pa, cut.q2, cut.u2);
  inserted.turns = 0;
  if (cut.round) {
    inserted.motion = cut.ccw ? Motion::G3 : Motion::G2;
    inserted.centre = inserted.start;
    inserted.centre[pa.abscissa] = cut.centre.a;
    inserted.centre[pa.ordinate] = cut.centre.o;
    inserted.applicate = pa.applicate;
  } else {
    inserted.motion = block_.motion == Motion::G0 ? Motion::G0 : Motion::G1;
  }
  // FRC/FRCM are not active when the element is traversed at rapid (PM-NC).
  if (block_.has_feed && r.has_feed) inserted.feed = r.feed;
  b.start = inserted.end;
  const double rise2 = std::fabs(b.end[pa.applicate] - b.start[pa.applicate]);
  held_ = false;
  if (cut.u1 * geom::elementLength(e1) > geom::tol::kPoint) next_.motion(first);  // else all cut
  next_.motion(inserted);
  replayDummies();
  return (1 - cut.u2) * geom::elementLength(e2) > geom::tol::kPoint || rise2 > geom::tol::kPoint;
}

}  // namespace ncoffset::interp
