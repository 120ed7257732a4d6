// The motion builder's short way (docs/performance.md §35, §53): a block of plain words (X, Y, Z,
// G0..G3, F, CR=, I, J, K alone, as Interpreter::plainWord collects them) under the interpreter's
// modal state, without a frame or with the frame of the last motion unchanged and no thread motion,
// is built here without the steps its words cannot need (frame suppression, AC/IC/DC words, SAR,
// G63, frame products). The compensation settings, the tool tip and the tool length vector stay
// in the reused block while only plain lines run (settingsMayChange); of the compensation
// settings only the mode (G40/G41/G42, plain words) is written for every block.
// MotionBuilder::build is its twin: the same fields, the same values bit for bit, the same alarms
// in the same order (tests/interp/motion_fast_path_test.cpp).
#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

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

// m_.trc.mode = mode, written with the kept radius behind it as one 16-byte store: the SAR
// stage's note loads the settings' head (mode and radius) as one piece, and a load that spans
// a narrower store waits until that store has left the processor (a store-forwarding stall of
// every block, perf annotate, docs/performance.md §47).
[[gnu::always_inline]] inline void MotionBuilder::plainMode(core::TrcMode mode) {
  using Pair = double __attribute__((vector_size(16)));
  static_assert(offsetof(core::TrcSettings, radius) == 8 && sizeof(Pair) == 16);
  std::uint64_t low = 0;  // the mode's byte and the padding behind it
  std::memcpy(&low, &mode, sizeof mode);
  const Pair head = {std::bit_cast<double>(low), m_.trc.radius};
  std::memcpy(static_cast<void*>(&m_.trc), &head, sizeof head);  // trivially copyable
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

namespace {

// The centre of buildPlain's circle into the block, with the applicate: `solve(sa, so, ea, eo,
// a, o)` gives it in the active plane from the start `f` (sa, so) to the end `t` (ea, eo),
// abscissa first (a, o: the plane's axes); the applicate's coordinate is the start's. Each plane
// written out with its axes by name: the points and the centre stay in registers (through
// arrays on the stack and a returned ArcSolution, loads wider than the stores before them waited
// for those, behind the square roots: docs/performance.md §47).
template <class Solve>
[[gnu::always_inline]] inline void centreInPlane(core::MotionBlock& m, Plane plane, const Vec3& f,
                                                 const Vec3& t, Solve&& solve) {
  if (plane == Plane::G18) {  // Z X
    const geom::Vec2 k = solve(f.z, f.x, t.z, t.x, 2, 0);
    m.centre = {k.o, f.y, k.a};
    m.applicate = 1;
  } else if (plane == Plane::G19) {  // Y Z
    const geom::Vec2 k = solve(f.y, f.z, t.y, t.z, 1, 2);
    m.centre = {f.x, k.a, k.o};
    m.applicate = 0;
  } else {  // G17: X Y
    const geom::Vec2 k = solve(f.x, f.y, t.x, t.y, 0, 1);
    m.centre = {k.a, k.o, f.z};
    m.applicate = 2;
  }
}

}  // namespace

// arc() for a circle by CR= alone. arcByRadius's end point is the programmed one (`end` itself),
// so the target and the block's end stay as buildPlain wrote them, and of arcEnd's stores only
// the centre's, the applicate's and the turns' change the block. Inline (centreInPlane).
[[gnu::always_inline]] inline void MotionBuilder::radiusArc(const BlockWords& w,
                                                            const ModalState& modal,
                                                            const Vec3& target) {
  const double cr = toMm(modal, *w.cr);
  const bool ccw = m_.motion == Motion::G3;
  const double tol_const = data_.get(md_circle_const_), tol_factor = data_.get(md_circle_factor_);
  // Inline in each of the three planes (one call after choosing the points cost 5 instructions
  // more).
  centreInPlane(
      m_, modal.plane, wcs_, target,
      [&](double sa, double so, double ea, double eo, int, int) __attribute__((always_inline)) {
        return geom::centreByRadius({sa, so}, {ea, eo}, cr, ccw, tol_const, tol_factor);
      });
  m_.turns = w.turn.value_or(0);
}

// arc() for a circle by its centre: I, J, K of the plane's axes from the start point (none
// written =AC(..)), no CR=, AR=. The end point is the target as buildPlain wrote it (arc's
// request takes the programmed end, or the start's where no plane axis is programmed, which is
// what the target holds there: a full circle), so only the centre, the applicate and the turns
// change the block. The centre is computed as arc() computes it (the start plus I, J, K in mm,
// bit for bit) and checked by geom::radiusByCentre, solveArc's twin. Inline: out of line it
// saved the circle by radius 3 instructions a block, but the contour's run took 6 % longer
// (docs/performance.md §53).
[[gnu::always_inline]] inline void MotionBuilder::centreArc(const BlockWords& w,
                                                            const ModalState& modal,
                                                            const Vec3& target) {
  const double tol_const = data_.get(md_circle_const_), tol_factor = data_.get(md_circle_factor_);
  auto offset = [&](int ax) { return w.centre[ax] ? toMm(modal, w.centre_value[ax]) : 0; };
  centreInPlane(
      m_, modal.plane, wcs_, target,
      [&](double sa, double so, double ea, double eo, int a, int o) __attribute__((always_inline)) {
        const geom::Vec2 c{sa + offset(a), so + offset(o)};
        geom::radiusByCentre({sa, so}, {ea, eo}, c, tol_const, tol_factor);
        return c;
      });
  m_.turns = w.turn.value_or(0);
}

Vec3 MotionBuilder::generalArc(const BlockWords& w, const ModalState& modal, Vec3 to) {
  arc(w, modal, wcs_, true, to);
  return to;
}

bool MotionBuilder::buildPlain(const BlockWords& w, const ModalState& modal, int line, int file,
                               double feed_before, Motion motion_before) {
  core::MotionBlock& m = m_;
  // A frame (or a changed one: its start point, its copy into the block) or a thread motion
  // (its lead): the general way. Only a line that is not plain changes them (plain lines
  // program G0..G3 alone), so they are asked again only then.
  if (!plain_settings_) [[unlikely]] {
    if (!frames_.isIdentity() || m.frame.state() != frames_.blockFrame().state() ||
        isThreadMotion(modal.motion) || !short_way)
      return build(w, modal, {line, file, feed_before, motion_before});
    plainSettings(modal);
  }
  plainMode(modal.trc);  // G40/G41/G42 may be a plain line's word: not kept
  Vec3 to = plainTarget(w);
  m.motion = modal.motion;
  m.line = line;
  m.file = file;
  m.start = bcs_;  // no frame: WCS = BCS
  m.end = to;
  m.has_feed = m.motion != Motion::G0;
  if (m.has_feed && modal.feed <= 0)
    raise(AlarmNumber::FeedNotProgrammed, "no feedrate programmed (F) for G1/G2/G3");
  m.feed = m.has_feed ? modal.feed : 0;
  // checkRange: the end point, and a circle's centre (rangeAlarm names the first beyond).
  if (m.motion == Motion::G2 || m.motion == Motion::G3) {
    // CR= with the end point in the plane and nothing else: solveArc's request is that alone.
    // A circle by its centre: I, J, K of the plane alone, none =AC(..) (arc()'s alarm for the
    // applicate's and its absolute centre stay there).
    const PlaneAxes pa = planeAxes(modal.plane);
    const bool centre = w.centre[0] || w.centre[1] || w.centre[2];
    if (w.cr) {
      if (!w.ar && !centre && (w.axis[pa.abscissa] || w.axis[pa.ordinate]))
        radiusArc(w, modal, to);
      else
        to = generalArc(w, modal, to);
    } else if (centre && !w.ar && !w.centre[pa.applicate] &&
               w.centre_mode[pa.abscissa] != lang::AxisMode::AC &&
               w.centre_mode[pa.ordinate] != lang::AxisMode::AC) {
      centreArc(w, modal, to);
    } else {
      to = generalArc(w, modal, to);
    }
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
