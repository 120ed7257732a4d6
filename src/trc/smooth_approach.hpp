// Smooth approach and retraction (SAR, W1 2.4.4, spec §6, details §4): a streaming stage in
// front of the radius compensation. It expands a G147/G247/G347 approach block into the
// sub-blocks P0 -> P1 -> P2 -> P3 -> P4 of the programmed contour once the block that defines
// the contour's start tangent is known (up to MD20202 blocks without geometry motion between),
// and a G148/G248/G348 retraction block at once from the end tangent of the last contour
// block. The radius compensation then treats the sub-blocks as if they were programmed (the
// circle's contour radius is chosen so that the tool centre runs on a circle of radius DISR).
// Readings where the manuals are silent: tests/programs/sar/README.md, docs/smooth-approach.md.
#pragma once

#include <optional>
#include <vector>

#include "core/stage.hpp"
#include "geom/contour.hpp"

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

  // The last block with plane motion that went through, as much as the retraction's tangent needs
  // (copying whole blocks cost 100 instructions a block, its start, end and centre 10): its
  // motion and the plane vector of a line's end - start or an arc's end - centre.
  struct LastContour {
    bool valid = false;
    Motion motion = Motion::G1;
    geom::Vec2 d;
  };

 private:
  enum class State { Idle, WaitP4, WaitTangent };

  void approach(const core::MotionBlock& tangent_block);
  void retraction(const core::MotionBlock& m);
  void take(const core::MotionBlock& m);
  void pass(const core::MotionBlock& m);
  // What the retraction needs of a block that went through (pass() and motion() for the usual
  // block, docs/performance.md §31, §35).
  void note(const core::MotionBlock& m);

  core::Stage& out_;
  State state_ = State::Idle;
  core::MotionBlock sar_;                // the approach block
  std::optional<core::MotionBlock> p4_;  // the block that supplies P4 (if not sar_)
  std::vector<core::MotionBlock> held_;  // geometry blocks between P4 and the tangent block
  int held_dummies_ = 0;                 // blocks without motion in between
  LastContour last_;
  core::TrcMode last_trc_mode_ = core::TrcMode::Off;  // of the last block
  double last_trc_radius_ = 0;
  core::ApproachPoints points_;  // of the last evaluated approach
  core::Feedback feedback_;      // for the block being taken
  bool has_feedback_ = false;
};

}  // namespace ncoffset::trc
