// The motion builder of the channel (PM-NC "Fundamentals": G0/G1/G2/G3, G90/G91, AC/IC,
// G53/G153/SUPA): turns the collected words of a block into one core::MotionBlock (target
// point, circle, tool length take-up, compensation settings, SAR request), checks it against the
// machine's number range and hands it to the first stage. It owns the channel's position.
#pragma once

#include <cmath>

#include "core/stage.hpp"
#include "geom/arc.hpp"
#include "interp/corner_stage.hpp"
#include "interp/frame_state.hpp"
#include "interp/machine_data.hpp"
#include "interp/modal_state.hpp"
#include "tool/tool_selection.hpp"
#include "trc/smooth_approach.hpp"

namespace ncoffset::interp {

// Where the block stands and what was modal before it (the SAR request needs both).
struct BlockContext {
  int line = 0;
  int file = 0;
  double feed_before = 0;             // the modal feed before the block
  Motion motion_before = Motion::G0;  // the modal G0..G3 before the block
};

// G70/G700: inch values in mm.
inline double toMm(const ModalState& modal, double v) {
  return modal.units == Units::G70 || modal.units == Units::G700 ? v * 25.4 : v;
}

class MotionBuilder {
 public:
  MotionBuilder(core::Stage& next, const MachineData& data, const FrameState& frames,
                const tool::ToolSelection& tools);

  // Where the machine stands before the first block (RunOptions::start, MCS): no tool length is
  // taken up yet and no frame is active, so the tool tip is there in the BCS and the WCS too.
  void setStart(const Vec3& mcs) { bcs_ = wcs_ = mcs; }
  // Builds the block's motion and hands it on. False: a zero-length linear block (no segment).
  bool build(const BlockWords& w, const ModalState& modal, const BlockContext& at);
  // build() for a block whose words Interpreter::plainWord collected alone (X, Y, Z, G0..G3, F,
  // CR=; every other word absent) under the interpreter's own modal state: without a frame (or
  // the frame of the last motion) its target, the tool length and the compensation settings
  // take the short way (motion_plain.cpp); anything else goes to build(), its twin
  // (tests/interp/motion_fast_path_test.cpp).
  bool buildPlain(const BlockWords& w, const ModalState& modal, const BlockContext& at) {
    return buildPlain(w, modal, at.line, at.file, at.feed_before, at.motion_before);
  }
  // The same with the context's fields in registers (the block loop's plain line: no context
  // built in memory for every block).
  bool buildPlain(const BlockWords& w, const ModalState& modal, int line, int file,
                  double feed_before, Motion motion_before);
  // build() for a block of any words under the interpreter's own modal state (finishBlock):
  // buildPlain when its words need nothing more (no G53/G153/SUPA, AC/IC/DAC/.., SAR, G63).
  bool buildBlock(const BlockWords& w, const ModalState& modal, const BlockContext& at);
  // Something other than a plain line ran (a block of other words, a subprogram return, a new
  // run): the compensation settings, the tool length and the tool tip that buildPlain keeps in
  // the block may have changed; the next plain block builds them anew.
  void settingsMayChange() { plain_settings_ = false; }
  // False: buildPlain and buildBlock are build() (tests compare whole runs both ways).
  static inline bool short_way = true;

  // The last programmed point in the WCS ($P_EP) and the tool tip in the BCS.
  Vec3 wcs() const { return wcs_; }
  // How many motions went to the next stage in this channel (the last MotionBlock::seq).
  long long motionsSent() const { return m_.seq; }
  Vec3 bcs() const { return bcs_; }
  // The tool's position in the MCS where the last block left it ($AA_IM): the BCS point plus
  // the tool length as the axes have taken it up.
  Vec3 mcs() const { return bcs_ + applied_offset_; }
  // The linear part of the last block's WCS -> BCS map (a WCS difference into the BCS).
  const Mat3& frameLinear() const { return frame().linear; }
  // $P_APR, $P_AEP, $P_APDV as the smooth approach fed them back.
  const core::ApproachPoints& approachPoints() const { return approach_points_; }

  // Contour definitions (contour_definition.cpp): the block being built gets a chamfer or
  // rounding at its end; the blocks go through the corner stage until it holds nothing.
  void cornerRequest(const CornerRequest& r) {
    corner_.request(r);
    routed_ = true;
  }
  // The stage after the interpreter for the calls that are not motions.
  core::Stage& output() { return routed_ ? static_cast<core::Stage&>(corner_) : next_; }
  void flush();
  std::optional<Vec3> preprocessorStop(bool alarm);
  // The block's end point as programmed (G90/G91, AC/IC, diameters) from the last point.
  Vec3 programmedTarget(const BlockWords& w, const ModalState& modal) const;
  // The last block handed on (CT: the tangent of the previous element).
  const core::MotionBlock& lastBlock() const { return m_; }

 private:
  Vec3 target(const BlockWords& w, const ModalState& modal, const Vec3& from) const;
  // G2/G3: end point and centre by geom::solveArc (PM-NC "Circular interpolation").
  void arc(const BlockWords& w, const ModalState& modal, const Vec3& from, bool plain,
           Vec3& target);
  // arc()'s last step: the solution's end point and centre into the block (`f`: the start).
  void arcEnd(const BlockWords& w, const geom::ArcSolution& sol, PlaneAxes pa, const double (&f)[3],
              Vec3& target);
  // arc() for buildPlain from the last programmed point: `to` by value, so that buildPlain's
  // target has no address (and stays in registers).
  [[gnu::noinline]] Vec3 generalArc(const BlockWords& w, const ModalState& modal, Vec3 to);
  // arc() for a circle by CR= alone (no centre, AR=) whose end point is programmed (buildPlain).
  void radiusArc(const BlockWords& w, const ModalState& modal, const Vec3& target);
  // arc() for a circle by its centre alone (I, J, K from the start, no CR=, AR=) (buildPlain).
  void centreArc(const BlockWords& w, const ModalState& modal, const Vec3& target);
  // G0/G1: the tool length taken up by each axis the block moves (W1 2.1, spec §2.6). False
  // when the block moves nowhere.
  // A thread or tapping line (threads.cpp): its feed is the lead; G63 names the block's G1.
  void threadFeed(const BlockWords& w, const ModalState& modal, const Vec3& from, const Vec3& to);
  bool takeUpLength(const BlockWords& w, const ModalState& modal, bool plain, const Vec3& target);
  void compensationSettings(const ModalState& modal);
  // buildPlain's steps (motion_plain.cpp): the target of the axis words without frame, and the
  // linear block's tool length take-up; false when the block moves nowhere.
  Vec3 plainTarget(const BlockWords& w) const;
  bool plainTakeUp(const BlockWords& w, const ModalState& modal, const Vec3& to);
  // The block's compensation mode (buildPlain), stored with the kept radius in one piece.
  void plainMode(core::TrcMode mode);
  // compensationSettings() for buildPlain, with the tool length vector it keeps.
  void plainSettings(const ModalState& modal);
  [[gnu::cold, noreturn]] static void targetAlarm(double value, int axis);
  // Without a frame: each programmed BCS axis takes up the length `full` if it may (SD42442).
  void takeUpAxes(const BlockWords& w, const ModalState& modal, const Vec3& full);
  // The block moves the tool (BCS plus tool length) by more than 1e-12 mm on some axis.
  static bool moves(const Vec3& moved) {
    return !(std::fabs(moved.x) < 1e-12 && std::fabs(moved.y) < 1e-12 &&
             std::fabs(moved.z) < 1e-12);
  }
  // Every axis as takeUpLength compares them (NaN is not equal).
  static bool equal(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
  // Beyond the machine's number range or not a number (|v| <= 1e9 is false for NaN). Without
  // branches: the usual block is within.
  static bool outOfRange(const Vec3& p) {
    return !(std::fabs(p.x) <= 1e9) | !(std::fabs(p.y) <= 1e9) | !(std::fabs(p.z) <= 1e9);
  }
  // The axis is programmed incrementally in this block (G91, IC, DIC, RIC).
  static bool incremental(const BlockWords& w, const ModalState& modal, int axis);
  // SD42442: whether the programmed axis takes up a changed tool length in this block.
  bool takesUpLength(const BlockWords& w, const ModalState& modal, int axis) const;
  // The point a linear block's axes count from after a frame change (SD42440 for incremental
  // axes, K2; the other axes from the last programmed point, docs/frames.md).
  Vec3 startAfterFrameChange(const BlockWords& w, const ModalState& modal) const;
  // The edge's P - S under the block's frame (turning tools only).
  Vec3 tipVector(Plane plane);
  void checkRange(bool plain) const;
  [[gnu::cold]] void rangeAlarm(bool plain) const;  // what checkRange found
  void sarRequest(const BlockWords& w, const ModalState& modal, const BlockContext& at);
  Vec3 toBcs(bool plain, const Vec3& p) const { return plain ? p : frame().apply(p); }
  const Affine& frame() const { return suppressed_ ? kNoFrame.map() : frames_.map(); }

  static const core::BlockFrame kNoFrame;
  core::Feedback routedMotion(const core::MotionBlock& m);
  // next_.motion(m), past the SAR stage when it has nothing to do with the block (§38).
  core::Feedback handOn(const core::MotionBlock& m);

  core::Stage& next_;
  // next_ when it is the SAR stage (the channel's chain): the usual block goes past it to the
  // compensation, with the stage's note of it; nullptr: every block goes to next_.motion().
  trc::SmoothApproach* sar_;
  CornerStage corner_;
  bool routed_ = false;  // corner_ holds a block or has a request: motions go through it
  const MachineData& data_;
  const FrameState& frames_;
  const tool::ToolSelection& tools_;
  // Machine data read per block, looked up once.
  int md_circle_const_, md_circle_factor_, md_corner_limit_, md_insert_limit_, md_dummy_blocks_,
      md_check_blocks_, md_sar_dummy_blocks_, sd_frame_incr_, sd_tool_incr_;
  core::MotionBlock m_;             // the one block, reused: every member is set for each motion
  bool suppressed_ = false;         // G53/G153/SUPA in the block being built
  Vec3 applied_offset_;             // BCS length vector as taken up axis by axis by linear blocks
  std::uint64_t mirror_state_ = 0;  // the frame state `mirrored_` belongs to
  std::array<bool, 3> mirrored_{};  // the axes that frame mirrors
  Vec3 wcs_;
  Vec3 bcs_;
  core::ApproachPoints approach_points_;
  // m_.trc (but its mode, G40..G42, written for every block), m_.has_tip, m_.tip and full_length_
  // were built by buildPlain from the interpreter's modal state and tool, and only plain lines ran
  // since (settingsMayChange): they still hold.
  // (So are m_.plane, m_.feed_unit, m_.lead_change, m_.sar.kind; the frame is the last motion's,
  // the identity, and the modal motion no thread: only other lines change them.)
  bool plain_settings_ = false;
  Vec3 full_length_;       // tools_.lengthVector(plane) when plain_settings_
  bool taken_up_ = false;  // applied_offset_ == full_length_: nothing to take up
  // plainTarget's G90/G91, inch factor (1 or 25.4) and diameter factors, when plain_settings_.
  bool plain_inc_ = false;
  double plain_unit_ = 1;
  double plain_factor_[3] = {1, 1, 1};
};

// The SAR stage's motion() for the usual block is note() and the stage behind's motion()
// (SmoothApproach::forward): done here, the block skips the stage's entry and its virtual call.
// (In the header: every place that hands a built block on takes it, docs/performance.md §38.)
inline core::Feedback MotionBuilder::handOn(const core::MotionBlock& m) {
  if (sar_ != nullptr && !sar_->needs(m)) {
    sar_->note(m);
    return sar_->next().motion(m);
  }
  return next_.motion(m);
}

inline void MotionBuilder::takeUpAxes(const BlockWords& w, const ModalState& modal,
                                      const Vec3& full) {
  for (int i = 0; i < 3; ++i)
    if (w.axis[i] && applied_offset_[i] != full[i] && takesUpLength(w, modal, i))
      applied_offset_[i] = full[i];
}

}  // namespace ncoffset::interp
