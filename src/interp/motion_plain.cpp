// The motion builder's short way (docs/performance.md §35): a block of plain words (X, Y, Z,
// G0..G3, F, CR= alone, as Interpreter::plainWord collects them) under the interpreter's modal
// state, without a frame or with the frame of the last motion unchanged and no thread motion, is
// built here without the steps its words cannot need (frame suppression, AC/IC/DC words, SAR,
// G63, frame products). The compensation settings, the tool tip and the tool length vector stay
// in the reused block while only plain lines run (settingsMayChange); of the compensation
// settings only the mode (G40/G41/G42, plain words) is written for every block.
// MotionBuilder::build is its twin: the same fields, the same values bit for bit, the same alarms
// in the same order (tests/interp/motion_fast_path_test.cpp).
#include <fmt/format.h>

#include <cmath>

#include "interp/motion_builder.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

void MotionBuilder::targetAlarm(double value, int axis) {
  raise(AlarmNumber::ValueRange,
        fmt::format("value range exceeded: position {} of axis {}", value, "XYZ"[axis]));
}

// target() for axis words without AC/IC/DAC/..., from the last programmed point.
[[gnu::always_inline]] inline Vec3 MotionBuilder::plainTarget(const BlockWords& w) const {
  Vec3 to = wcs_;
  // G90/G91, the inch factor and the diameter factors as plainSettings took them from the modal
  // state (only a line that is not plain changes them). toMm: v * 1.0 is v bit for bit, so the inch
  // factor needs no branch per axis.
  const bool inc = plain_inc_;
  const double unit = plain_unit_;
  auto axis = [&](int i, double& t) {
    if (!w.axis[i]) return;
    const double v = w.axis_value[i] * unit * plain_factor_[i];
    t = inc ? t + v : v;
    if (!(std::fabs(t) <= 1e9)) [[unlikely]]  // beyond, infinite or NaN: one comparison
      targetAlarm(t, i);
  };
  axis(0, to.x);
  axis(1, to.y);
  axis(2, to.z);
  return to;
}

// takeUpLength() without a frame, with the length vector kept since the settings were built.
[[gnu::always_inline]] inline bool MotionBuilder::plainTakeUp(const BlockWords& w,
                                                              const ModalState& modal,
                                                              const Vec3& to) {
  core::MotionBlock& m = m_;
  m.centre = {};
  m.applicate = 2;
  m.turns = 0;
  const Vec3 before = applied_offset_;
  if (!taken_up_) [[unlikely]] {
    takeUpAxes(w, modal, full_length_);
    taken_up_ = equal(applied_offset_, full_length_);
  }
  return moves((to + applied_offset_) - (bcs_ + before));
}

// arc() for a circle by CR= alone. arcByRadius's end point is the programmed one (`end` itself),
// so the target and the block's end stay as buildPlain wrote them, and of arcEnd's stores only
// the centre's, the applicate's and the turns' change the block.
void MotionBuilder::radiusArc(const BlockWords& w, const ModalState& modal, const Vec3& target) {
  const PlaneAxes pa = planeAxes(modal.plane);
  double c[3] = {wcs_.x, wcs_.y, wcs_.z};
  const double t[3] = {target.x, target.y, target.z};
  const geom::Vec2 start{c[pa.abscissa], c[pa.ordinate]}, end{t[pa.abscissa], t[pa.ordinate]};
  const geom::Vec2 centre =
      geom::arcByRadius(start, end, toMm(modal, *w.cr), m_.motion == Motion::G3,
                        data_.get(md_circle_const_), data_.get(md_circle_factor_))
          .centre;
  c[pa.abscissa] = centre.a;
  c[pa.ordinate] = centre.o;
  m_.centre = {c[0], c[1], c[2]};
  m_.applicate = pa.applicate;
  m_.turns = w.turn.value_or(0);
}

bool MotionBuilder::buildPlain(const BlockWords& w, const ModalState& modal,
                               const BlockContext& at) {
  core::MotionBlock& m = m_;
  // A frame (or a changed one: its start point, its copy into the block) or a thread motion
  // (its lead): the general way. Only a line that is not plain changes them (plain lines
  // program G0..G3 alone), so they are asked again only then.
  if (!plain_settings_) [[unlikely]] {
    if (!frames_.isIdentity() || m.frame.state() != frames_.blockFrame().state() ||
        isThreadMotion(modal.motion) || !short_way)
      return build(w, modal, at);
    plainSettings(modal);
  }
  m.trc.mode = modal.trc;  // G40/G41/G42 may be a plain line's word: not kept
  Vec3 to = plainTarget(w);
  m.motion = modal.motion;
  m.line = at.line;
  m.file = at.file;
  m.start = bcs_;  // no frame: WCS = BCS
  m.end = to;
  m.has_feed = m.motion != Motion::G0;
  if (m.has_feed && modal.feed <= 0)
    raise(AlarmNumber::FeedNotProgrammed, "no feedrate programmed (F) for G1/G2/G3");
  m.feed = m.has_feed ? modal.feed : 0;
  // checkRange: the end point, and a circle's centre (rangeAlarm names the first beyond).
  if (m.motion == Motion::G2 || m.motion == Motion::G3) {
    // CR= with the end point in the plane and nothing else: solveArc's request is that alone.
    const PlaneAxes pa = planeAxes(modal.plane);
    if (w.cr && !w.ar && !(w.centre[0] || w.centre[1] || w.centre[2]) &&
        (w.axis[pa.abscissa] || w.axis[pa.ordinate]))
      radiusArc(w, modal, to);
    else
      arc(w, modal, wcs_, true, to);
    if (outOfRange(m.end + applied_offset_) || outOfRange(m.centre)) [[unlikely]]
      rangeAlarm(true);
  } else {
    if (!plainTakeUp(w, modal, to)) {
      if (routed_) corner_.dropRequest();
      wcs_ = to;
      return false;  // zero-length block: no segment
    }
    if (outOfRange(m.end + applied_offset_)) [[unlikely]]
      rangeAlarm(true);
  }
  m.tool_offset = applied_offset_;
  ++m.seq;
  const core::Feedback back = routed_ ? routedMotion(m) : handOn(m);
  if (back.approach) [[unlikely]]
    approach_points_ = *back.approach;
  if (back.end_point) [[unlikely]]
    to = *back.end_point;
  bcs_ = wcs_ = to;
  return true;
}

bool MotionBuilder::buildBlock(const BlockWords& w, const ModalState& modal,
                               const BlockContext& at) {
  using lang::AxisMode;
  // Only these words make build() do more than buildPlain (centre words, CR=, AR= and TURN=
  // are arc()'s in both).
  const bool plain_words =
      w.suppress_frames == 0 && w.sar == core::SarKind::None && !w.tapping_chuck &&
      w.axis_mode[0] == AxisMode::Default && w.axis_mode[1] == AxisMode::Default &&
      w.axis_mode[2] == AxisMode::Default && !w.disr && !w.discl && !w.disrp && !w.fad;
  return plain_words ? buildPlain(w, modal, at) : build(w, modal, at);
}

}  // namespace ncoffset::interp
