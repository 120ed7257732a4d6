#include "interp/motion_builder.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/inline_step.hpp"
#include "geom/arc.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::AxisMode;

const core::BlockFrame MotionBuilder::kNoFrame;

MotionBuilder::MotionBuilder(core::Stage& next, const MachineData& data, const FrameState& frames,
                             const tool::ToolSelection& tools)
    : next_(next),
      sar_(dynamic_cast<trc::SmoothApproach*>(&next)),
      corner_(next),
      data_(data),
      frames_(frames),
      tools_(tools),
      md_circle_const_(data.find("$MC_CIRCLE_ERROR_CONST")),
      md_circle_factor_(data.find("$MC_CIRCLE_ERROR_FACTOR")),
      md_corner_limit_(data.find("$MC_CUTCOM_CORNER_LIMIT")),
      md_insert_limit_(data.find("$MC_CUTCOM_CURVE_INSERT_LIMIT")),
      md_dummy_blocks_(data.find("$MC_CUTCOM_MAXNUM_DUMMY_BLOCKS")),
      md_check_blocks_(data.find("$MC_CUTCOM_MAXNUM_CHECK_BLOCKS")),
      md_sar_dummy_blocks_(data.find("$MC_WAB_MAXNUM_DUMMY_BLOCKS")),
      sd_frame_incr_(data.find("$SC_FRAME_OFFSET_INCR_PROG")),
      sd_tool_incr_(data.find("$SC_TOOL_OFFSET_INCR_PROG")) {}

NCOFFSET_INLINE_STEP Vec3 MotionBuilder::target(const BlockWords& w, const ModalState& modal,
                                                const Vec3& from) const {
  Vec3 target = from;
  for (int i = 0; i < 3; ++i) {
    if (!w.axis[i]) continue;
    const AxisMode mode = w.axis_mode[i];
    bool absolute = mode == AxisMode::AC || (mode == AxisMode::Default && !modal.incremental);
    // Diameter programming (docs/turning.md): a diameter is twice the radius position.
    double factor = absolute ? modal.diam_abs[i] : modal.diam_inc[i];
    if (mode > AxisMode::IC) {   // DAC, DIC, RAC, RIC: diameter or radius for this word
      if (mode >= AxisMode::DC)  // a geometry axis is linear (docs/language.md "Axes")
        raise(mode == AxisMode::DC    ? AlarmNumber::DcNotAllowed
              : mode == AxisMode::ACP ? AlarmNumber::AcpNotAllowed
                                      : AlarmNumber::AcnNotAllowed,
              fmt::format("traverse instruction DC/ACP/ACN for axis {} not allowed (a linear "
                          "axis)",
                          "XYZ"[i]));
      if (!modal.diam_permitted[i])
        raise(AlarmNumber::NoTransverseAxis,
              fmt::format("no transverse axis: DAC/DIC/RAC/RIC need {} as the transverse axis "
                          "(MD20100) or permitted by MD30460 bit 2",
                          "XYZ"[i]));
      absolute = mode == AxisMode::DAC || mode == AxisMode::RAC;
      factor = mode == AxisMode::DAC || mode == AxisMode::DIC ? 0.5 : 1;
    }
    double v = toMm(modal, w.axis_value[i]) * factor;
    target[i] = absolute ? v : from[i] + v;
    if (!(std::fabs(target[i]) <= 1e9))  // beyond, infinite or NaN: one comparison
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: position {} of axis {}", target[i], "XYZ"[i]));
  }
  return target;
}

bool MotionBuilder::build(const BlockWords& w, const ModalState& modal, const BlockContext& at) {
  plain_settings_ = false;  // m_.trc may be built here from another modal state
  suppressed_ = w.suppress_frames != 0;
  // Without a frame WCS = BCS: the products are skipped (the usual case).
  const bool plain = suppressed_ || frames_.isIdentity();
  // Programming system: the WCS, or the BCS when frames are suppressed (G53/G153/SUPA).
  Vec3 from = suppressed_ ? bcs_ : wcs_;
  core::MotionBlock& m = m_;
  // The block keeps its frame from the last motion while the frame state is the same (the
  // usual case: no copy of the map per block).
  const core::BlockFrame& block_frame = suppressed_ ? kNoFrame : frames_.blockFrame();
  if (m.frame.state() != block_frame.state()) {
    if (!suppressed_ && modal.motion != Motion::G2 && modal.motion != Motion::G3)
      from = startAfterFrameChange(w, modal);
    m.frame = block_frame;
  }
  Vec3 to = target(w, modal, from);
  m.motion = modal.motion;
  // A SAR block is a linear block: its own G0/G1 (G2/G3 modal count as G1) moves P2 -> P0.
  const bool sar = w.sar != core::SarKind::None;
  if (sar && (m.motion == Motion::G2 || m.motion == Motion::G3)) m.motion = Motion::G1;
  m.line = at.line;
  m.file = at.file;
  m.start = suppressed_ ? bcs_ : frames_.toWcs(bcs_);
  m.end = to;
  m.has_feed = m.motion != Motion::G0;
  if (m.has_feed && modal.feed <= 0 && !isThreadMotion(m.motion))
    raise(AlarmNumber::FeedNotProgrammed, "no feedrate programmed (F) for G1/G2/G3");
  m.feed = m.has_feed ? modal.feed : 0;
  m.feed_unit = modal.feed_unit;
  m.lead_change = 0;
  if (isThreadMotion(m.motion) | w.tapping_chuck) [[unlikely]]
    threadFeed(w, modal, from, to);  // threads.cpp
  m.sar.kind = core::SarKind::None;
  if (m.motion == Motion::G2 || m.motion == Motion::G3) {
    arc(w, modal, from, plain, to);
  } else if (!takeUpLength(w, modal, plain, to) && !sar && !w.extra_axes) {
    // A chamfer or rounding at a block that moves nowhere has no corner: reduced to nothing.
    if (routed_) corner_.dropRequest();
    wcs_ = suppressed_ ? frames_.toWcs(bcs_) : to;
    return false;  // zero-length block: no segment
  }
  m.tool_offset = applied_offset_;
  m.plane = modal.plane;
  compensationSettings(modal);
  checkRange(plain);
  sarRequest(w, modal, at);
  ++m.seq;
  core::Feedback back = routed_ ? routedMotion(m) : handOn(m);
  if (back.approach) approach_points_ = *back.approach;
  if (back.end_point) to = *back.end_point;  // implicit retraction end point
  bcs_ = toBcs(plain, to);
  wcs_ = suppressed_ ? frames_.toWcs(bcs_) : to;
  return true;
}

Vec3 MotionBuilder::programmedTarget(const BlockWords& w, const ModalState& modal) const {
  return target(w, modal, w.suppress_frames != 0 ? bcs_ : wcs_);
}

core::Feedback MotionBuilder::routedMotion(const core::MotionBlock& m) {
  core::Feedback back = corner_.motion(m);
  routed_ = !corner_.idle();
  return back;
}

void MotionBuilder::flush() {
  output().flush();
  routed_ = !corner_.idle();
}

std::optional<Vec3> MotionBuilder::preprocessorStop(bool alarm) {
  std::optional<Vec3> at = output().preprocessorStop(alarm);
  routed_ = !corner_.idle();
  return at;
}

void MotionBuilder::arc(const BlockWords& w, const ModalState& modal, const Vec3& from, bool plain,
                        Vec3& target) {
  core::MotionBlock& m = m_;
  const PlaneAxes pa = planeAxes(modal.plane);
  const int a = pa.abscissa, o = pa.ordinate;
  if (w.centre[pa.applicate])
    raise(AlarmNumber::CircleProgramming,
          fmt::format("circle programming error: {} is not an interpolation parameter in the "
                      "active plane",
                      "IJK"[pa.applicate]));
  if (!plain) {
    const Mat3& l = frame().linear;
    Vec3 ea, eo;
    ea[a] = 1;
    eo[o] = 1;
    if (std::fabs(norm(l * ea) - norm(l * eo)) > 1e-9)
      raise(AlarmNumber::FrameNotAffine,
            "a circle under different scale factors of the plane axes is an ellipse, which is "
            "not modelled");
  }
  // The points as arrays: indexed by the plane's axes without Vec3's choice per access.
  const double f[3] = {from.x, from.y, from.z};
  double t[3] = {target.x, target.y, target.z};
  geom::ArcRequest req;
  req.start = {f[a], f[o]};
  req.ccw = m.motion == Motion::G3;
  req.tol_const = data_.get(md_circle_const_);
  req.tol_factor = data_.get(md_circle_factor_);
  if (w.axis[a] || w.axis[o]) req.end = geom::Vec2{t[a], t[o]};
  if (w.centre[a] || w.centre[o]) {
    // I, J, K are incremental from the start point unless written =AC(..); an absolute centre
    // is a diameter under DIAMON/DIAM90, an incremental one a radius (FM P1 "Transverse axes",
    // docs/turning.md).
    auto centre = [&](int ax) {
      const double v = w.centre[ax] ? toMm(modal, w.centre_value[ax]) : 0;
      return w.centre_mode[ax] == AxisMode::AC ? v * modal.diam_abs[ax] : f[ax] + v;
    };
    req.centre = geom::Vec2{centre(a), centre(o)};
  }
  if (w.cr) req.cr = toMm(modal, *w.cr);
  if (w.ar) req.ar = *w.ar;
  arcEnd(w, geom::solveArc(req), pa, f, target);
}

void MotionBuilder::arcEnd(const BlockWords& w, const geom::ArcSolution& sol, PlaneAxes pa,
                           const double (&f)[3], Vec3& target) {
  core::MotionBlock& m = m_;
  double t[3] = {target.x, target.y, target.z};
  t[pa.abscissa] = sol.end.a;
  t[pa.ordinate] = sol.end.o;
  target = {t[0], t[1], t[2]};
  m.end = target;
  double c[3] = {f[0], f[1], f[2]};
  c[pa.abscissa] = sol.centre.a;
  c[pa.ordinate] = sol.centre.o;
  m.centre = {c[0], c[1], c[2]};
  m.applicate = pa.applicate;
  m.turns = w.turn.value_or(0);
}

NCOFFSET_INLINE_STEP bool MotionBuilder::takeUpLength(const BlockWords& w, const ModalState& modal,
                                                      bool plain, const Vec3& target) {
  core::MotionBlock& m = m_;
  m.centre = {};
  m.applicate = 2;
  m.turns = 0;
  // Tool length: each BCS axis takes up the length vector with the first linear block that
  // moves it after the selection (W1 2.1, spec §2.6).
  const Vec3 full = tools_.lengthVector(modal.plane);
  const Vec3 before = applied_offset_;
  // SD42442 = 0: an incrementally programmed axis does not take up a changed length (only the
  // programmed path is traversed); asked only where the length changed.
  if (plain) {
    takeUpAxes(w, modal, full);
  } else {
    const Mat3& l = frame().linear;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i)
        if (w.axis[i] && std::fabs(l.m[static_cast<size_t>(k)][static_cast<size_t>(i)]) > 1e-12 &&
            applied_offset_[k] != full[k] && takesUpLength(w, modal, i))
          applied_offset_[k] = full[k];
  }
  return moves((toBcs(plain, target) + applied_offset_) - (bcs_ + before));
}

bool MotionBuilder::incremental(const BlockWords& w, const ModalState& modal, int axis) {
  const AxisMode mode = w.axis_mode[axis];
  return mode == AxisMode::IC || mode == AxisMode::DIC || mode == AxisMode::RIC ||
         (mode == AxisMode::Default && modal.incremental);
}

bool MotionBuilder::takesUpLength(const BlockWords& w, const ModalState& modal, int axis) const {
  // W1 "tool length compensation" / SD42442 TOOL_OFFSET_INCR_PROG: 1 (default) a changed tool
  // length is traversed also when the axis is programmed incrementally; 0 only the programmed
  // increment is traversed, the length is taken up by the next absolute programming.
  return data_.get(sd_tool_incr_) != 0 || !incremental(w, modal, axis);
}

Vec3 MotionBuilder::startAfterFrameChange(const BlockWords& w, const ModalState& modal) const {
  // K2 "Frames with G91" (FM K2 08/2005 1.3), SD42440 FRAME_OFFSET_INCR_PROG: an axis programmed
  // incrementally after a frame change counts from its last programmed WCS value (1, default:
  // the offset change is traversed with the increment) or from where the new frame sees the tool
  // (0: only the programmed path). docs/frames.md.
  Vec3 from = wcs_;
  if (data_.get(sd_frame_incr_) != 0) return from;
  const Vec3 actual = frames_.toWcs(bcs_);
  for (int i = 0; i < 3; ++i)
    if (w.axis[i] && incremental(w, modal, i)) from[i] = actual[i];
  return from;
}

NCOFFSET_INLINE_STEP void MotionBuilder::compensationSettings(const ModalState& modal) {
  core::TrcSettings& t = m_.trc;
  t.mode = modal.trc;
  t.radius = modal.offn + tools_.radius();
  t.frame_plane = modal.cut2d_frame;
  t.constant = modal.cut_constant;
  t.approach = modal.approach;
  t.corner = modal.corner;
  t.collision = modal.collision;
  t.disc = modal.disc;
  t.strategy = modal.trc_strategy;
  t.corner_limit = data_.get(md_corner_limit_);
  t.curve_insert_limit = data_.get(md_insert_limit_);
  t.max_dummy_blocks = static_cast<int>(data_.get(md_dummy_blocks_));
  t.check_blocks = static_cast<int>(data_.get(md_check_blocks_));
  // (m_.tip_at stays kTipNone: only radius compensation marks the copies it makes.)
  m_.has_tip = tools_.hasTip();  // false for every milling tool: nothing more per block
  if (m_.has_tip) m_.tip = tipVector(modal.plane);
}

void MotionBuilder::plainSettings(const ModalState& modal) {
  suppressed_ = false;
  compensationSettings(modal);
  full_length_ = tools_.lengthVector(modal.plane);
  taken_up_ = equal(applied_offset_, full_length_);
  // What build() sets for every block and buildPlain keeps: the same for every plain block.
  m_.plane = modal.plane;
  m_.feed_unit = modal.feed_unit;
  m_.lead_change = 0;
  m_.sar.kind = core::SarKind::None;
  plain_inc_ = modal.incremental;
  plain_unit_ = modal.units == Units::G70 || modal.units == Units::G700 ? 25.4 : 1.0;
  const double* factor = plain_inc_ ? modal.diam_inc : modal.diam_abs;
  for (int i = 0; i < 3; ++i) plain_factor_[i] = factor[i];
  plain_settings_ = true;
}

Vec3 MotionBuilder::tipVector(Plane plane) {
  // P - S of the edge (tool::ToolSelection::tipVector) with the components on the axes the
  // block's frame mirrors inverted: mirroring a plane axis mirrors the effective cutting edge
  // position (PM-NC 12/2019 p746, "D13 with SL3" becomes SL4 under mirrored Z; docs/cutting-edge-
  // positions.md). The mirror flags are read once per frame state.
  Vec3 tip = tools_.tipVector(plane);
  if (suppressed_ || frames_.isIdentity()) return tip;
  const std::uint64_t state = frames_.blockFrame().state();
  if (state != mirror_state_) {
    mirrored_ = frames_.active().mirror;
    mirror_state_ = state;
  }
  for (int i = 0; i < 3; ++i)
    if (mirrored_[static_cast<size_t>(i)]) tip[i] = -tip[i];
  return tip;
}

NCOFFSET_INLINE_STEP void MotionBuilder::checkRange(bool plain) const {
  const core::MotionBlock& m = m_;
  // Computed geometry must stay finite and within the machine's number range: a frame with a
  // huge scale or a circle with a huge radius ends here, never as NaN or 1e300 in the output.
  // The end point, and a circle's centre (a line has none). One test for the usual case; the
  // alarm names the first axis beyond (rangeAlarm).
  const bool circle = m.motion == Motion::G2 || m.motion == Motion::G3;
  if (outOfRange(toBcs(plain, m.end) + applied_offset_) ||
      (circle && outOfRange(toBcs(plain, m.centre)))) [[unlikely]]
    rangeAlarm(plain);
}

void MotionBuilder::rangeAlarm(bool plain) const {
  const core::MotionBlock& m = m_;
  const Vec3 checks[] = {toBcs(plain, m.end) + applied_offset_, toBcs(plain, m.centre)};
  const int n_checks = m.motion == Motion::G2 || m.motion == Motion::G3 ? 2 : 1;
  for (int c = 0; c < n_checks; ++c)
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = checks[c];
      if (std::fabs(p[i]) <= 1e9) continue;
      if (!std::isfinite(p[i]))
        raise(AlarmNumber::Arithmetic,
              "arithmetic error in part program: position is not a finite number");
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: position {} of axis {} beyond 1e9 mm", p[i],
                        "XYZ"[i]));
    }
}

NCOFFSET_INLINE_STEP void MotionBuilder::sarRequest(const BlockWords& w, const ModalState& modal,
                                                    const BlockContext& at) {
  if (w.sar == core::SarKind::None) {
    if (w.disr || w.discl || w.disrp || w.fad)
      raise(AlarmNumber::SyntaxError,
            "DISR, DISCL, DISRP and FAD only in a SAR block (G147..G348)");
    return;
  }
  m_.sar = core::SarRequest{};
  core::SarRequest& q = m_.sar;
  q.kind = w.sar;
  q.side = modal.sar_side;
  q.infeed = modal.sar_infeed;
  q.has_disr = w.disr.has_value();
  q.disr = w.disr.value_or(0);
  q.has_discl = w.discl.has_value();
  q.discl = w.discl.value_or(0);
  q.discl_ac = w.discl_ac;
  q.has_disrp = w.disrp.has_value();
  q.disrp = w.disrp.value_or(0);
  q.disrp_ac = w.disrp_ac;
  q.has_fad = w.fad.has_value();
  q.fad = w.fad.value_or(0);
  PlaneAxes pa = planeAxes(modal.plane);
  q.plane_axis = w.axis[pa.abscissa] || w.axis[pa.ordinate];
  q.any_axis = q.plane_axis || w.axis[pa.applicate];
  q.f_programmed = w.f.has_value();
  q.feed_value = modal.feed;
  q.feed_before = at.feed_before;
  q.rapid_before = at.motion_before == Motion::G0;
  q.max_dummy_blocks = static_cast<int>(data_.get(md_sar_dummy_blocks_));
}

}  // namespace ncoffset::interp
