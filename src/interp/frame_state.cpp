#include "interp/frame_state.hpp"

namespace ncoffset::interp {

FrameState::FrameState() : uifr_(kSettableFrames) {
  update();
}

Frame FrameState::active() const {
  Frame inner = chain(iframe_, chain(toolfr_, chain(wpfr_, pframe_)));
  return partfr_.isIdentity() ? inner : chain(partfr_, inner);
}

void FrameState::update() {
  act_ = active().affine();
  act_inverse_ = act_.inverse();
  act_identity_ = act_.isIdentity();
  ++act_state_;
  act_frame_ = core::BlockFrame(act_, act_state_, act_identity_);
}

}  // namespace ncoffset::interp
