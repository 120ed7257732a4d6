// The frame state of the channel (K2, PM-NC "Frames"): the settable frames $P_UIFR[0..99], the
// active settable frame ($P_IFRAME, selected by G500/G54..G57/G505..G599), the programmable frame
// ($P_PFRAME: TRANS/ROT/SCALE/MIRROR and their A forms, G58/G59) and their product, the active
// frame, as the map WCS -> BCS that the blocks carry (core::BlockFrame).
#pragma once

#include <cstdint>
#include <vector>

#include "core/block_frame.hpp"
#include "ncoffset/frame.hpp"

namespace ncoffset::interp {

class FrameState {
 public:
  static constexpr size_t kSettableFrames = 100;  // $P_UIFR[0..99] (MD28080 at most)

  FrameState();

  // $P_UIFR[n], $P_IFRAME, $P_PFRAME for reading and writing; after writing the active
  // settable or the programmable frame, call update().
  Frame& settable(size_t n) { return uifr_[n]; }
  Frame& settableActive() { return iframe_; }
  Frame& programmable() { return pframe_; }
  const Frame& settableActive() const { return iframe_; }
  const Frame& programmable() const { return pframe_; }

  // G500 (n = 0), G54..G57 (1..4), G505..G599 (5..99): $P_IFRAME becomes a copy of $P_UIFR[n].
  void select(size_t n) { iframe_ = uifr_[n]; }

  // The system frames of an orientable toolholder (W1 2.5, docs/toolholders.md): the table
  // offset $P_PARTFR (outside $P_IFRAME) and the rotations of TOROT/TOFRAME ($P_TOOLFR) and PAROT
  // ($P_WPFRAME) between $P_IFRAME and $P_PFRAME. Call update() after a change.
  Frame& partFrame() { return partfr_; }
  Frame& toolFrame() { return toolfr_; }
  Frame& workpieceFrame() { return wpfr_; }

  // The active frame: [$P_PARTFR :] $P_IFRAME [: $P_TOOLFR : $P_WPFRAME] : $P_PFRAME, recomputed
  // after a change.
  void update();
  Frame active() const;
  const Affine& map() const { return act_; }
  const Affine& inverse() const { return act_inverse_; }
  bool isIdentity() const { return act_identity_; }
  // The active frame as blocks carry it (a new state number after every update()).
  const core::BlockFrame& blockFrame() const { return act_frame_; }
  Vec3 toBcs(Vec3 wcs) const { return act_identity_ ? wcs : act_.apply(wcs); }
  Vec3 toWcs(Vec3 bcs) const { return act_identity_ ? bcs : act_inverse_.apply(bcs); }

 private:
  std::vector<Frame> uifr_;
  Frame iframe_;
  Frame pframe_;
  Frame partfr_, toolfr_, wpfr_;
  Affine act_;
  Affine act_inverse_;
  bool act_identity_ = true;     // act_ is exactly the identity: the products are skipped
  std::uint64_t act_state_ = 1;  // counts the changes of act_ (core::BlockFrame::state)
  core::BlockFrame act_frame_;
};

}  // namespace ncoffset::interp
