// The stage driver of radius compensation (W1 2.4, spec §5): selection, the dispatch of each
// motion to the window, release, flush and STOPRE. The geometry lives in pieces.cpp (the
// elements and their equidistants), corners.cpp, bottleneck.cpp and approach_retraction.cpp.
#include "trc/radius_compensation.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/inline_step.hpp"
#include "trc/compensation_internal.hpp"
#include "trc/usual_element.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
using core::TrcMode;
using geom::Element;

NCOFFSET_INLINE_STEP bool RadiusCompensation::checkSameSettings(const MotionBlock& m) {
  if (m.plane != sel_plane_)
    raise(AlarmNumber::TrcPlaneChange,
          "change of compensation plane not possible while tool radius compensation is active");
  if (!m.frame.sameAs(sel_frame_))
    detail::notModelled("a frame change while compensation is active");
  // G groups 22 and 40 in one comparison (the selection block never has CUTCONON).
  if (groupBytes(m.trc) != same_groups_) [[unlikely]]
    return rareSettings(m);
  return false;
}

[[gnu::noinline]] bool RadiusCompensation::rareSettings(const MotionBlock& m) {
  checkProjectable(m);
  if (!m.trc.constant && !constant_) return false;
  if (state_ != State::On) constantAtSelection(m);
  return keepConstant(m);
}

// CUT2D with a frame that tilts the working plane: the contour is compensated in its projection
// into the machine's plane G17..G19 (W1 "CUT2D": the plane of G17..G19; CUT2DF: the frame's).
// The projection of a circle is an ellipse and motion along the applicate moves the projection:
// neither is modelled.
[[gnu::noinline]] void RadiusCompensation::checkProjectable(const MotionBlock& m) const {
  if (m.trc.frame_plane != sel_frame_plane_)
    detail::notModelled("a change between CUT2D and CUT2DF while compensation is active");
  if (!projected_) return;
  if (m.motion == Motion::G2 || m.motion == Motion::G3)
    detail::notModelled(
        "a circle under CUT2D in a plane a frame tilts (its projection into G17..G19 is an "
        "ellipse; CUT2DF compensates in the frame's plane)");
  const int ap = planeAxes(m.plane).applicate;
  if (std::fabs(m.end[ap] - m.start[ap]) > geom::tol::kPoint)
    detail::notModelled("motion along the applicate under CUT2D in a plane a frame tilts");
}

// (planeMetric's frame other than the identity.)
geom::PlaneMetric RadiusCompensation::framedMetric(const MotionBlock& m, bool& projected) {
  // The tool radius is physical: not scaled by SCALE or a scaling settable frame (Mitsubishi
  // M700V PM 13.20, GSK980MDc p58 say so; the Siemens frame components hold no tool data;
  // docs/radius-compensation.md "Frames").
  const PlaneAxes pa = planeAxes(m.plane);
  Vec3 ea, eo;
  ea[pa.abscissa] = 1;
  eo[pa.ordinate] = 1;
  Vec3 a = m.frame.linear() * ea, o = m.frame.linear() * eo;
  // (A programmed circle under different factors is an ellipse: the interpreter stops it with
  // 99012 before it gets here.)
  // CUT2D: a frame that tilts the plane leaves the compensation in the machine's plane: the
  // lengths are those of the contour's projection into it (checkProjectable).
  if (!m.trc.frame_plane && (std::fabs(a[pa.applicate]) > geom::tol::kNumeric ||
                             std::fabs(o[pa.applicate]) > geom::tol::kNumeric)) {
    a[pa.applicate] = o[pa.applicate] = 0;
    const double det = dot(a, a) * dot(o, o) - dot(a, o) * dot(a, o);
    if (det < 1e-6)
      detail::notModelled(
          "CUT2D with a frame that turns the working plane perpendicular to "
          "G17..G19 (no projection to compensate in; CUT2DF)");
    projected = true;
  }
  return geom::PlaneMetric::fromGram(dot(a, a), dot(a, o), dot(o, o));
}

void RadiusCompensation::blockWithoutMotion() {
  if (state_ == State::Off) return;
  if (++dummy_blocks_ > settings_.max_dummy_blocks)
    raise(AlarmNumber::TrcTooManyEmptyBlocks,
          fmt::format("too many empty blocks between two traversing blocks with active tool "
                      "radius compensation (MD20250 = {})",
                      settings_.max_dummy_blocks));
}

core::Feedback RadiusCompensation::motion(const MotionBlock& m) {
  if (pass_programmed_) [[unlikely]]
    out_.programmed(m);
  // (On first: the state of most blocks of a compensated contour, one test before the call.)
  if (state_ == State::On) {
    // (G40 here, not in motionOn: its frame is not set up for the one block a lap, §48.)
    if (m.trc.mode == TrcMode::Off)
      retract(m);
    else
      motionOn(m);
  } else if (state_ == State::Off) {
    // (Here, not in startSelection: the path of every block without compensation.)
    const bool wants = m.trc.mode != TrcMode::Off && std::fabs(m.trc.radius) > geom::tol::kPoint;
    if (!wants || !planeMotion(m)) [[likely]]
      emit(m);  // no compensation, or no plane axis in the block: no selection yet (W1 2-41)
    else
      startSelection(m);
  } else {
    motionSelecting(m);
  }
  return {};
}

void RadiusCompensation::startSelection(const MotionBlock& m) {
  if (m.trc.constant) constantAtSelection(m);
  if (m.motion != Motion::G0 && m.motion != Motion::G1)
    raise(AlarmNumber::TrcSelectionNotLinear,
          "activation of tool radius compensation only possible in linear block");
  if (m.trc.approach == Approach::KontC || m.trc.approach == Approach::KontT)
    detail::notModelled(m.trc.approach == Approach::KontC ? "KONTC" : "KONTT");
  constant_ = false;  // (a G40 while CUTCONON was active left it set)
  setSettings(m.trc);
  window_.clear();  // (empty: the window is written and cleared when compensation ends)
  copyBlock(window_.pushBack().block, m);
  sel_plane_ = m.plane;
  sel_frame_ = m.frame;
  sel_groups_ = groupBytes(m.trc);
  sel_frame_plane_ = m.trc.frame_plane;
  metric_ = planeMetric(m, projected_);
  setRare(projected_);
  state_ = State::Selecting;
  dummy_blocks_ = 0;
}

void RadiusCompensation::motionSelecting(const MotionBlock& m) {
  if (m.trc.mode == TrcMode::Off) {
    // G40 in the block after the selection block: no selection takes place (W1 2-41).
    emit(selection());
    for (const auto& w : waiting_) emit(w);
    waiting_.clear();
    window_.clear();
    emit(m);
    state_ = State::Off;
    return;
  }
  checkSameSettings(m);  // (CUTCONON here: alarm 99010, constantAtSelection)
  // planeMotion, with a line's length kept, as in motionOn (§48).
  const bool arc = m.motion == Motion::G2 || m.motion == Motion::G3;
  const PlaneAxes pa = planeAxes(m.plane);
  const double length = arc ? kUnmeasured : lineLength(m, pa);
  if (!arc && !(length > geom::tol::kPoint)) {
    waiting_.push_back(m);
    blockWithoutMotion();
    return;
  }
  if (sideOf(m.trc) != side()) setSettings(m.trc);  // the side of the first element counts
  // The first element starts at the value of the selection block; a new value programmed in it
  // (D, T) is spread over it like in any later block (details Q8).
  const double r0 = std::fabs(selection().trc.radius), r1 = std::fabs(m.trc.radius);
  const double r_end = std::fabs(r1 - r0) <= geom::tol::kPoint ? r0 : r1;
  // The approach line and the first element are built in the window's first two slots (the
  // first holds the selection block), not as Pieces moved in (docs/performance.md §31, §36).
  window_.pushBack();
  Piece& first = window_[1];
  // (The usual element without compensateInto's call, with the length measured above, §48.)
  if (r0 == r_end && metric_.identity && !general_paths_)
    compensateUsual(first, m, r0, 0, false, length, pa);
  else
    compensateInto(first, m, r0, r_end);
  if (!first.valid) detail::collision(m.line, settings_.check_blocks);  // no element to approach
  Piece& approach = window_[0];
  approachLine(approach, first);
  setSettings(m.trc);               // the next block starts from this one's value
  approach.waiting.swap(waiting_);  // (both keep their memory)
  waiting_.clear();
  count_ = 1;
  first.index = 1;
  maybe_open_ = general_paths_;  // both valid, neither open
  dummy_blocks_ = 0;
  state_ = State::On;
}

// (Here, inlined into motionOn, its one caller: once a block, docs/performance.md §36.)
NCOFFSET_INLINE_STEP void RadiusCompensation::compensateNext(Piece& p, const MotionBlock& m,
                                                             long index, bool restart,
                                                             double length, PlaneAxes pa) {
  // The usual block: the value and G41/G42 of the last one. The general path below gives the
  // same value at both ends, fabs(radius), and the same side (sideOf reads just these two), so
  // only the settings are kept (§48).
  if (m.trc.radius == settings_.radius && m.trc.mode == settings_.mode && metric_.identity &&
      !general_paths_) {
    settings_ = m.trc;
    return compensateUsual(p, m, std::fabs(settings_.radius), index, restart, length, pa);
  }
  const double old_side = side(), old_r = std::fabs(settings_.radius);
  const double new_r = std::fabs(m.trc.radius);
  setSettings(m.trc);
  double r0 = old_r, r1 = std::fabs(old_r - new_r) <= geom::tol::kPoint ? old_r : new_r;
  // G41 <-> G42 (or the sign of the value) while active: the last element ends on its normal,
  // the new side starts on the normal at this block's start (PM-NC "change of compensation
  // direction"; details Q8 for the sign).
  const bool new_side = side_ != old_side;
  if (new_side) r0 = r1 = new_r;
  // The usual element built here, without a call (§42).
  if (r0 == r1 && metric_.identity && !general_paths_)
    compensateUsual(p, m, r0, index, restart || new_side, length, pa);
  else
    compensateInto(p, m, r0, r1, index, restart || new_side);
}

void RadiusCompensation::waitOn(const MotionBlock& m) {
  if (window_.back().emitted)  // after STOPRE: runs where the last element ended
    emit(atPoint(m, window_.back().compensated.p1));
  else
    window_.back().waiting.push_back(m);
  settings_.max_dummy_blocks = m.trc.max_dummy_blocks;
  blockWithoutMotion();
}

void RadiusCompensation::motionOn(const MotionBlock& m) {
  if (checkSameSettings(m)) return;  // handled by CUTCONON (constant_compensation.cpp)
  // planeMotion, with a line's length kept for its unit vector (compensateConstant, §48).
  const bool arc = m.motion == Motion::G2 || m.motion == Motion::G3;
  const PlaneAxes pa = planeAxes(m.plane);
  const double length = arc ? kUnmeasured : lineLength(m, pa);
  if (!arc && !(length > geom::tol::kPoint)) return waitOn(m);
  Piece& next = window_.pushBack();
  compensateNext(next, m, ++count_, restart_next_, length, pa);  // (an arc's: kUnmeasured)
  restart_next_ = false;
  Piece& cur = window_.before(next);
  if (!joinTangent(cur, next)) connect(cur, next);  // a tangent junction without the call
  // Bottleneck detection closes junctions, never opens one: with none open before it,
  // there is nothing for checkOpen to find.
  const bool open = openWith(next);
  // (The CDOF test of bridge here: on a contour without open junctions no call.)
  if (open || settings_.collision == CollisionCheck::Cdon) bridge(next, open);
  if (open) checkOpen(count_ + 1);
  maybe_open_ = open || general_paths_;
  release();
  dummy_blocks_ = 0;
}

NCOFFSET_INLINE_STEP void RadiusCompensation::release() {
  const long reach = count_ + 1 - settings_.check_blocks;
  while (window_.size() > 1) {
    const Piece& f = window_.front();
    if (f.index >= reach) break;
    if (!f.emitted) emitPiece(f);
    window_.popFront();
  }
}

void RadiusCompensation::flushAll() {
  // No later block: every open junction stays open. (With none open, checkOpen finds none.)
  if (maybe_open_) checkOpen(detail::kNoLaterBlock);
  for (size_t i = 0; i < window_.size(); ++i)
    if (!window_[i].emitted) emitPiece(window_[i]);
  window_.clear();
}

std::optional<Vec3> RadiusCompensation::preprocessorStop(bool alarm) {
  if (state_ == State::Off) return std::nullopt;
  if (alarm)
    raise(AlarmNumber::TrcPreprocessorStop,
          "preprocessor stop with active tool radius compensation (SD42480 = 1)");
  // "Traversing continues to the offset point in the last block. Correspondingly, the offset
  // point in the start point is approached in the first block after a preprocessing stop."
  // (FM-W1 08/2005 2.4.11). The contour may be violated, as the manual warns.
  Piece anchor;
  std::optional<Vec3> stands;  // the end of the last block written: where the tool stands
  if (state_ == State::Selecting) {
    const double r = std::fabs(settings_.radius);
    anchor = compensate(selection(), r, r);
    Element approach;
    approach.p0 = anchor.programmed.p0;
    approach.p1 = anchor.compensated.p1;
    MotionBlock line = toBlock(selection(), approach);
    detail::keepTipAt(line, core::kTipEnd);
    emit(line);
    for (const MotionBlock& w : waiting_) emit(atPoint(w, approach.p1));
    stands = atPoint(waiting_.empty() ? selection() : waiting_.back(), approach.p1).end;
    waiting_.clear();
    state_ = State::On;
    count_ = 0;
  } else {
    anchor = window_.back();
    flushAll();
    stands = atPoint(anchor.waiting.empty() ? anchor.block : anchor.waiting.back(),
                     anchor.compensated.p1)
                 .end;
  }
  anchor.emitted = true;
  anchor.waiting.clear();
  anchor.transition.clear();
  window_.clear();
  window_.pushBack() = std::move(anchor);
  maybe_open_ = true;
  restart_next_ = true;
  return stands;
}

void RadiusCompensation::flush() {
  if (state_ == State::Selecting) {
    // No contour element follows the selection block: it ends on its own normal.
    const double r = std::fabs(settings_.radius);
    Piece only = compensate(selection(), r, r);
    Element approach;
    approach.p0 = only.programmed.p0;
    approach.p1 = only.compensated.p1;
    MotionBlock line = toBlock(selection(), approach);
    detail::keepTipAt(line, core::kTipEnd);
    emit(line);
    for (const MotionBlock& w : waiting_) emit(atPoint(w, approach.p1));
  } else if (state_ == State::On) {
    flushAll();
  }
  waiting_.clear();
  window_.clear();
  state_ = State::Off;
}

}  // namespace ncoffset::trc
