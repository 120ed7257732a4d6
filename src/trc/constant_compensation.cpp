// Keep tool radius compensation constant, CUTCONON / CUTCONOF (G group 40; FM W1 "Tool radius
// compensation 2D", "Keep tool radius compensation constant"; docs/radius-compensation.md
// "CUTCONON"):
//
// * The last traversing block before CUTCONON ends on the normal at its end point (its offset
//   point): no corner with what follows.
// * Every following block with CUTCONON is traversed without compensation, shifted by the
//   vector from that block's end point to its offset point, whatever its interpolation.
// * The block that ends the suppression (CUTCONOF) is compensated normally and starts at the
//   offset point of its start point; a straight line is inserted from the end of the last
//   shifted block to it.
//
// This is what a preprocessor stop does to the window (radius_compensation.cpp), with the
// shifted blocks in between; so the same flush and restart serve both.
#include <cmath>

#include "trc/compensation_internal.hpp"
#include "trc/radius_compensation.hpp"
#include "trc/usual_element.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
using geom::Vec2;

bool RadiusCompensation::keepConstant(const MotionBlock& m) {
  if (!m.trc.constant) {
    // CUTCONOF: the ordinary path; after a suppression this block starts anew on the normal at
    // its start point, joined by a straight line (restartLine). (G40 while CUTCONON is active
    // does not come here: the retraction runs from where the tool stands.)
    constant_ = false;
    setRare(projected_);
    return false;
  }
  if (!planeMotion(m)) {
    if (!constant_) return false;  // not begun: waits on the last compensated block as usual
    // Stands where the last shifted block ended. (No MD20250 count: no intersection is looked
    // for across the suppressed blocks. docs/radius-compensation.md "CUTCONON", decision.)
    emit(atPoint(m, window_.back().compensated.p1));
    return true;
  }
  if (!constant_) beginConstant();
  emitShifted(m);
  setSettings(m.trc);  // a new D takes effect whole in the block that ends the suppression
  dummy_blocks_ = 0;
  return true;
}

void RadiusCompensation::beginConstant() {
  const Piece last = window_.back();
  if (!last.valid) detail::collision(last.block.line, settings_.check_blocks);
  // The window is written with the last element ending on its normal (as before STOPRE).
  flushAll();
  constant_offset_ = last.compensated.p1 - last.programmed.p1;
  constant_ = true;
  setRare(true);
  restart_next_ = true;
}

void RadiusCompensation::emitShifted(const MotionBlock& m) {
  window_.clear();
  maybe_open_ = true;
  Piece& p = window_.pushBack();
  const double r = std::fabs(m.trc.radius);
  startPiece(p, r, r, ++count_, false);
  p.side = sideOf(m.trc);  // (the block's, not the stage's)
  p.block = m;
  p.programmed = toElement(m);
  p.compensated = p.programmed;
  p.compensated.p0 = p.programmed.p0 + constant_offset_;
  p.compensated.p1 = p.programmed.p1 + constant_offset_;
  p.compensated.c = p.programmed.c + constant_offset_;  // a circle keeps its radius
  keepRaw(p);
  emitPiece(p);
  p.emitted = true;  // kept only for the next block to start from (and a G40 line)
}

void RadiusCompensation::constantAtSelection(const MotionBlock& m) {
  throw AlarmError(AlarmNumber::NotModelled,
                   "the selection of tool radius compensation (G41/G42) while CUTCONON is active "
                   "is not modelled by ncoffset (W1 describes CUTCONON within an active "
                   "compensation only; program CUTCONOF before G41/G42)",
                   m.line);
}

}  // namespace ncoffset::trc
