// Smooth approach and retraction (SAR, W1 2.4.4, spec §6, details §4): a streaming stage in
// front of the radius compensation. It expands a G147/G247/G347 approach block into the
// sub-blocks P0 -> P1 -> P2 -> P3 -> P4 of the programmed contour once the block that defines
// the contour's start tangent is known (up to MD20202 blocks without geometry motion between),
// and a G148/G248/G348 retraction block at once from the end tangent of the last contour
// block. The radius compensation then treats the sub-blocks as if they were programmed (the
// circle's contour radius is chosen so that the tool centre runs on a circle of radius DISR).
// Readings where the manuals are silent: tests/programs/sar/README.md, docs/smooth-approach.md.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstring>
#include <optional>
#include <vector>

#include "core/stage.hpp"
#include "geom/contour.hpp"
#include "geom/tolerance.hpp"

namespace ncoffset::trc {

class SmoothApproach final : public core::Stage {
 public:
  explicit SmoothApproach(core::Stage& out) : out_(out) {}
  // Returns the approach points when an approach began or was evaluated with this block, and
  // the tool's position after a retraction block whose end point is implicit.
  core::Feedback motion(const core::MotionBlock& m) override;
  void warning(const core::MotionBlock& at, int number, const std::string& text) override {
    out_.warning(at, number, text);
  }
  // A block reaching the main run without any motion.
  void blockWithoutMotion() override;
  // STOPRE (explicit preprocessor stop): not allowed between an approach block and the block
  // that defines its tangent.
  std::optional<Vec3> preprocessorStop(bool alarm) override;
  void flush() override;
  // Nothing is held back (no approach waits for its contour).
  bool idle() const { return state_ == State::Idle; }

  // The usual block past the stage (MotionBuilder::handOn, docs/performance.md §38): a block
  // that does not need motion() (no SAR word, no approach waiting) may go to next() directly
  // after note(); that is what motion() does with it.
  bool needs(const core::MotionBlock& m) const {
    return state_ != State::Idle || m.sar.kind != core::SarKind::None;
  }
  inline void note(const core::MotionBlock& m);
  core::Stage& next() const { return out_; }

 private:
  enum class State { Idle, WaitP4, WaitTangent };

  // motion() for a SAR block or while an approach waits; out of line, so that motion() has no
  // stack frame and hands the usual block on with one call.
  [[gnu::noinline]] core::Feedback general(const core::MotionBlock& m);
  void approach(const core::MotionBlock& tangent_block);
  void retraction(const core::MotionBlock& m);
  void take(const core::MotionBlock& m);
  void pass(const core::MotionBlock& m);
  // pass() inlined into motion() for the usual block (no call per block, docs/performance.md §31).
  // Returns what the stage behind feeds back: nothing, as RadiusCompensation::motion never
  // does, so that motion() hands the block on as its one call (§38).
  core::Feedback forward(const core::MotionBlock& m);

  core::Stage& out_;
  State state_ = State::Idle;
  core::MotionBlock sar_;                // the approach block
  std::optional<core::MotionBlock> p4_;  // the block that supplies P4 (if not sar_)
  std::vector<core::MotionBlock> held_;  // geometry blocks between P4 and the tangent block
  int held_dummies_ = 0;                 // blocks without motion in between
  // The last block with plane motion that went through, as much as the retraction's tangent
  // needs: its motion and the in-plane vector end - start (line) or end - centre (arc). (Whole
  // blocks cost 100 instructions a block, start/end/centre 9 doubles; the differences are the
  // ones the plane-motion test computes anyway, docs/performance.md §38.)
  // None yet while d is NaN (no flag stored per block; a block's end and an arc's centre are
  // finite, MotionBuilder::checkRange).
  struct LastContour {
    Motion motion = Motion::G1;
    geom::Vec2 d{std::nan(""), 0};
    bool valid() const { return !std::isnan(d.a); }
  };
  LastContour last_;
  // Mode and radius of the last block: the head of its TrcSettings, copied as one 16-byte piece
  // (two instructions a block instead of four, §38).
  struct TrcHead {
    core::TrcMode mode;
    double radius;
  };
  static_assert(offsetof(TrcHead, radius) == offsetof(core::TrcSettings, radius));
  TrcHead last_trc_{core::TrcMode::Off, 0};
  core::ApproachPoints points_;  // of the last evaluated approach
  core::Feedback feedback_;      // for the block being taken
  bool has_feedback_ = false;
};

// What a later retraction needs of a block that goes through: its TRC mode and radius, and for
// a block with plane motion (hasPlaneMotion without its square root) the difference tangentOf
// takes.
void SmoothApproach::note(const core::MotionBlock& m) {
  PlaneAxes pa = planeAxes(m.plane);
  const int a = pa.abscissa, o = pa.ordinate;
  if (m.motion == Motion::G2 || m.motion == Motion::G3) {
    last_ = LastContour{m.motion, {m.end[a] - m.centre[a], m.end[o] - m.centre[o]}};
  } else {
    const geom::Vec2 d{m.end[a] - m.start[a], m.end[o] - m.start[o]};
    if (std::fabs(d.a) > geom::tol::kPoint || std::fabs(d.o) > geom::tol::kPoint)
      last_ = LastContour{m.motion, d};
  }
  std::memcpy(&last_trc_, &m.trc, sizeof last_trc_);
}

}  // namespace ncoffset::trc
