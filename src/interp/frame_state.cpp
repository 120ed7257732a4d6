#include "interp/frame_state.hpp"

namespace ncoffset::interp {

FrameState::FrameState() : uifr_(kSettableFrames) {
  update();
}

void FrameState::update() {
  act_ = chain(iframe_, pframe_).affine();
  act_inverse_ = act_.inverse();
  act_identity_ = act_.isIdentity();
  ++act_state_;
  act_frame_ = core::BlockFrame(act_, act_state_, act_identity_);
}

}  // namespace ncoffset::interp
