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

#include "geom/contour.hpp"
#include "place/placement.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {

class SmoothApproach {
 public:
  explicit SmoothApproach(RadiusCompensation& out) : out_(out) {}
  SmoothApproach(const SmoothApproach&) = delete;  // sar_.sar points into the object
  SmoothApproach& operator=(const SmoothApproach&) = delete;
  void motion(const place::MotionBlock& m);
  // A block reaching the main run without any motion.
  void blockWithoutMotion();
  // STOPRE (explicit preprocessor stop): not allowed between an approach block and the block
  // that defines its tangent.
  void preprocessorStop();
  void finish();
  // Waiting for the blocks that complete an approach, or compensation active.
  bool active() const { return state_ != State::Idle || out_.active(); }
  // After a retraction block whose end point is implicit: where the tool is (WCS).
  std::optional<Vec3> takeEndOverride() {
    auto e = end_override_;
    end_override_.reset();
    return e;
  }
  // MD20202 $MC_WAB_MAXNUM_DUMMY_BLOCKS.
  void setMaxDummyBlocks(int n) { max_dummy_blocks_ = n; }

  // $P_APR, $P_AEP (WCS, of the last evaluated approach), $P_APDV.
  Vec3 apr() const { return apr_; }
  Vec3 aep() const { return aep_; }
  bool apdv() const { return apdv_; }

 private:
  enum class State { Idle, WaitP4, WaitTangent };

  void approach(const place::MotionBlock& tangent_block);
  void retraction(const place::MotionBlock& m);
  void pass(const place::MotionBlock& m);

  RadiusCompensation& out_;
  State state_ = State::Idle;
  place::MotionBlock sar_;                // the approach block
  SarRequest request_;                    // its request (sar_.sar points here)
  std::optional<place::MotionBlock> p4_;  // the block that supplies P4 (if not sar_)
  std::vector<place::MotionBlock> held_;  // geometry blocks between P4 and the tangent block
  int held_dummies_ = 0;                  // blocks without motion in between
  int max_dummy_blocks_ = 5;
  // The last block with plane motion that went through (for the retraction's tangent).
  // (Only what the tangent needs: copying whole blocks cost 100 instructions a block.)
  struct LastContour {
    Plane plane = Plane::G17;
    Motion motion = Motion::G1;
    Vec3 start, end, centre;
  };
  std::optional<LastContour> last_;
  int last_trc_mode_ = 40;  // G40/G41/G42 of the last block
  double last_trc_radius_ = 0;
  std::optional<Vec3> end_override_;
  Vec3 apr_, aep_;
  bool apdv_ = false;
};

}  // namespace ncoffset::trc
