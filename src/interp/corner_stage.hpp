// Chamfers and roundings between two motion blocks (PM-NC 12/2019 "Chamfer, rounding (CHF, CHR,
// RND, RNDM, FRC, FRCM)"): the block with CHF=/CHR=/RND= (or under RNDM) is held until the next
// block that moves in the plane; then the corner between them is cut and the chamfer or rounding
// goes on as a block of its own, as if programmed, before the next block (so radius compensation
// offsets it like any element). The MotionBuilder routes its blocks through this stage only
// while a request or a held block exists: the plain path never enters it.
#pragma once

#include <cstdint>

#include "core/stage.hpp"

namespace ncoffset::interp {

struct CornerRequest {
  enum class Kind : std::uint8_t { None, Chf, Chr, Rnd };
  Kind kind = Kind::None;
  double value = 0;       // mm
  bool has_feed = false;  // FRC= / FRCM=: the inserted element's feed (else the block's F)
  double feed = 0;
};

class CornerStage final : public core::Stage {
 public:
  explicit CornerStage(core::Stage& next) : next_(next) {}

  // The request of the block being built (the next motion() call).
  void request(const CornerRequest& r) { request_ = r; }
  void dropRequest() { request_.kind = CornerRequest::Kind::None; }
  bool idle() const { return !held_ && request_.kind == CornerRequest::Kind::None; }

  core::Feedback motion(const core::MotionBlock& m) override;
  void warning(const core::MotionBlock& at, int number, const std::string& text) override {
    next_.warning(at, number, text);
  }
  void blockWithoutMotion() override;
  std::optional<Vec3> preprocessorStop(bool alarm) override {
    release();
    return next_.preprocessorStop(alarm);
  }
  void flush() override {
    release();
    next_.flush();
  }

 private:
  // The held block goes on as programmed (no partner: no chamfer/rounding), then the blocks
  // without motion that came after it.
  void release();
  static bool joinable(const core::MotionBlock& a, const core::MotionBlock& b);
  // Cuts the corner between the held block and `b`: sends the held block's kept part and the
  // inserted element; `b` keeps its part after the corner. False when nothing of `b` is left.
  bool cutCorner(core::MotionBlock& b);
  void replayDummies();

  core::Stage& next_;
  CornerRequest request_;
  CornerRequest held_request_;
  bool held_ = false;
  int dummies_ = 0;  // blocks without motion since the held block
  core::MotionBlock block_;
};

}  // namespace ncoffset::interp
