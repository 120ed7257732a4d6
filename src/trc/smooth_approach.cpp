#include "trc/smooth_approach.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "core/inline_step.hpp"
#include "geom/tolerance.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
using core::SarInfeed;
using core::SarRequest;
using core::SarSide;
using core::TrcMode;
using core::TrcSettings;
using geom::unit;
using geom::Vec2;

namespace {

namespace tol = geom::tol;  // the tolerances of radius compensation (geom/tolerance.hpp)
constexpr double kEps = tol::kPoint;

Vec2 inPlane(const MotionBlock& m, const Vec3& v) {
  PlaneAxes pa = planeAxes(m.plane);
  return {v[pa.abscissa], v[pa.ordinate]};
}

bool isArc(const MotionBlock& m) {
  return m.motion == Motion::G2 || m.motion == Motion::G3;
}

bool hasPlaneMotion(const MotionBlock& m) {
  return isArc(m) || geom::length(inPlane(m, m.end) - inPlane(m, m.start)) > tol::kPoint;
}

// The unit tangent of an element in its plane from its motion and `d`: end - start for a line,
// the radius vector (point - centre) at the point for an arc.
Vec2 tangentOf(Motion motion, Vec2 d) {
  if (motion != Motion::G2 && motion != Motion::G3) return unit(d);
  const Vec2 t = geom::leftNormal(unit(d));
  return motion == Motion::G3 ? t : -1.0 * t;
}

// The unit tangent of a block in its plane at its start.
Vec2 startTangent(const MotionBlock& m) {
  return tangentOf(
      m.motion, inPlane(m, isArc(m) ? m.start : m.end) - inPlane(m, isArc(m) ? m.centre : m.start));
}

// +1: compensation left of the travel, -1: right, 0: off (spec §5.1, a negative value flips).
double trcSide(const TrcSettings& t) {
  if (t.mode == TrcMode::Off || std::fabs(t.radius) <= tol::kPoint) return 0;
  double s = t.mode == TrcMode::Left ? 1.0 : -1.0;
  return t.radius < 0 ? -s : s;
}

[[noreturn]] void sarAlarm(AlarmNumber number, const std::string& text, int line) {
  throw AlarmError(number, text, line);
}

// The plane part of the SAR contour (details §4.3): P3's plane position, and for circles the
// centre, sense and contour radius.
struct Shape {
  Vec2 p3, centre;
  bool arc = false, ccw = false;
};

Shape construct(const MotionBlock& s, const TrcSettings& trc, Vec2 p4, Vec2 t, Vec2 ref,
                bool approach) {
  const SarRequest& q = s.sar;
  const int kind = core::sarShape(q.kind);  // 1 line, 2 quadrant, 3 semicircle
  const double side = trcSide(trc), radius = side != 0 ? std::fabs(trc.radius) : 0.0;
  const Vec2 n = geom::leftNormal(t);
  Shape out;
  if (!q.has_disr)
    sarAlarm(AlarmNumber::SarInvalidDistance, "SAR: distance DISR not programmed", s.line);
  if (kind == 1) {
    // The line is the distance of the tool edge: R + DISR (R counted only if positive, details
    // §4.3; PM-F 11/2006 p372).
    const double length = radius + q.disr;
    if (length <= kEps)
      sarAlarm(AlarmNumber::SarInvalidDistance,
               fmt::format("SAR: invalid distance DISR={} (with the compensation value {} the "
                           "approach line has no length)",
                           q.disr, radius),
               s.line);
    out.p3 = approach ? p4 - length * t : p4 + length * t;
    return out;
  }
  if (q.disr <= kEps)
    sarAlarm(AlarmNumber::SarInvalidDistance,
             fmt::format("SAR: invalid distance DISR={} for a circle (must be > 0)", q.disr),
             s.line);
  // Side of the circle: G141 left, G142 right, G140 the compensation side (G143 without
  // compensation), G143 the side of the start / end point relative to the tangent at P4.
  double sigma = 0;
  if (q.side == SarSide::G141)
    sigma = 1;
  else if (q.side == SarSide::G142)
    sigma = -1;
  else if (q.side == SarSide::G140 && side != 0)
    sigma = side;
  else
    sigma = geom::cross(t, ref - p4) >= 0 ? 1 : -1;
  // The contour radius that puts the tool centre on a circle of radius DISR.
  const double r = side == 0 ? q.disr : sigma == side ? q.disr + radius : q.disr - radius;
  if (r <= kEps)
    sarAlarm(AlarmNumber::SarInvalidDistance,
             fmt::format("SAR: invalid distance DISR={}: the contour circle for the compensation "
                         "value {} has no radius",
                         q.disr, radius),
             s.line);
  out.arc = true;
  out.ccw = sigma > 0;
  out.centre = p4 + (r * sigma) * n;
  if (kind == 2)
    out.p3 = approach ? out.centre - r * t : out.centre + r * t;
  else
    out.p3 = p4 + (2 * r * sigma) * n;
  return out;
}

Vec3 point(const MotionBlock& like, Vec2 p, double app) {
  PlaneAxes pa = planeAxes(like.plane);
  Vec3 v;
  v[pa.abscissa] = p.a;
  v[pa.ordinate] = p.o;
  v[pa.applicate] = app;
  return v;
}

// All movements perpendicular to the plane in one direction (spec §6.1 DISCL).
void checkMonotonic(std::initializer_list<double> apps, int line) {
  int dir = 0;
  double prev = *apps.begin();
  for (double a : apps) {
    const double d = a - prev;
    prev = a;
    if (std::fabs(d) < kEps) continue;
    const int sd = d > 0 ? 1 : -1;
    if (dir != 0 && sd != dir)
      sarAlarm(AlarmNumber::SarInfeedReversal, "SAR: direction reversal of the infeed movement",
               line);
    dir = sd;
  }
}

// A sub-block of `like` from `from` to `to` with its motion and feed.
MotionBlock subBlock(const MotionBlock& like, const Vec3& from, const Vec3& to, Motion mo,
                     double feed) {
  MotionBlock b = like;
  b.sar.kind = core::SarKind::None;
  b.start = from;
  b.end = to;
  b.motion = mo;
  b.feed = mo == Motion::G0 ? 0 : feed;
  b.has_feed = mo != Motion::G0;
  if (b.has_feed && feed <= 0)
    raise(AlarmNumber::FeedNotProgrammed, "no feedrate programmed (F) for the SAR movement");
  return b;
}

// The SAR curve from `from` to `to` as a sub-block of `like`: a line, or the arc (a helix when
// the applicate changes) about the shape's centre at the applicate of its start.
MotionBlock curveBlock(const MotionBlock& like, const Vec3& from, const Vec3& to,
                       const Shape& shape, double feed) {
  MotionBlock b = subBlock(like, from, to, Motion::G1, feed);
  if (shape.arc) {
    const int app = planeAxes(like.plane).applicate;
    b.motion = shape.ccw ? Motion::G3 : Motion::G2;
    b.centre = point(like, shape.centre, from[app]);
    b.applicate = app;
    b.turns = 0;
  }
  return b;
}

}  // namespace

NCOFFSET_INLINE_STEP core::Feedback SmoothApproach::forward(const MotionBlock& m) {
  note(m);
  return out_.motion(m);
}

void SmoothApproach::pass(const MotionBlock& m) {
  forward(m);
}

NCOFFSET_ONE_CALL core::Feedback SmoothApproach::motion(const MotionBlock& m) {
  if (!needs(m)) return forward(m);  // the usual block
  return general(m);
}

core::Feedback SmoothApproach::general(const MotionBlock& m) {
  take(m);
  if (!has_feedback_) return {};
  has_feedback_ = false;
  return std::exchange(feedback_, {});
}

void SmoothApproach::take(const MotionBlock& m) {
  switch (state_) {
    case State::Idle:
      if (m.sar.approach()) {
        sar_ = m;
        p4_.reset();
        held_.clear();
        held_dummies_ = 0;
        points_.valid = false;  // $P_APR/$P_AEP still belong to an older approach
        feedback_.approach = points_;
        has_feedback_ = true;
        state_ = sar_.sar.plane_axis ? State::WaitTangent : State::WaitP4;
        return;
      }
      if (m.sar.retraction()) {
        retraction(m);
        return;
      }
      pass(m);
      return;
    case State::WaitP4:
    case State::WaitTangent:
      if (m.sar.kind != core::SarKind::None)
        sarAlarm(AlarmNumber::SarProgrammedTwice,
                 "SAR programmed several times: the previous approach is not complete", m.line);
      if (state_ == State::WaitP4) {
        // The next block with geometry motion supplies P4; the SAR contour runs in it.
        p4_ = m;
        state_ = State::WaitTangent;
        return;
      }
      if (!hasPlaneMotion(m)) {  // no tangent yet: an infeed; counts against MD20202 too
        if (static_cast<int>(held_.size()) + held_dummies_ >= sar_.sar.max_dummy_blocks)
          sarAlarm(AlarmNumber::SarTooManyBlocks,
                   fmt::format("SAR: too many blocks without plane motion between the SAR block "
                               "and the block that defines the approach direction (MD20202 = {})",
                               sar_.sar.max_dummy_blocks),
                   m.line);
        held_.push_back(m);
        return;
      }
      approach(m);
      state_ = State::Idle;
      pass(m);
      return;
  }
}

void SmoothApproach::blockWithoutMotion() {
  if (state_ == State::Idle) {
    out_.blockWithoutMotion();
    return;
  }
  if (++held_dummies_ + static_cast<int>(held_.size()) > sar_.sar.max_dummy_blocks)
    raise(AlarmNumber::SarTooManyBlocks,
          fmt::format("SAR: too many blocks without traversing motion between the SAR block "
                      "and the block that defines the approach direction (MD20202 = {})",
                      sar_.sar.max_dummy_blocks));
}

std::optional<Vec3> SmoothApproach::preprocessorStop(bool alarm) {
  if (state_ != State::Idle)
    raise(AlarmNumber::SarPreprocessorStop,
          "SAR: preprocessor stop between the SAR block and the block that defines the "
          "approach direction");
  return out_.preprocessorStop(alarm);
}

void SmoothApproach::flush() {
  if (state_ != State::Idle)
    sarAlarm(AlarmNumber::SarNoDirection,
             "SAR: no valid approach direction: no traversing block follows the SAR block",
             (p4_ ? *p4_ : sar_).line);
  out_.flush();
}

void SmoothApproach::approach(const MotionBlock& tangent_block) {
  const MotionBlock& s = sar_;
  const SarRequest& q = s.sar;
  const MotionBlock& p4b = p4_ ? *p4_ : s;
  PlaneAxes pa = planeAxes(s.plane);
  const int app = pa.applicate;
  const Vec3 p0 = s.start, p4 = p4b.end;
  const Vec2 t = startTangent(tangent_block);
  const Shape shape = construct(s, s.trc, inPlane(s, p4), t, inPlane(s, p0), true);
  // Applicates (details §4.2): DISCL / DISRP measured along +applicate from the plane of P4,
  // or absolute with =AC(..); a missing DISCL counts as 0.
  const double app4 = p4[app];
  const double app2 = q.discl_ac ? q.discl : app4 + (q.has_discl ? q.discl : 0.0);
  const double app1 = q.has_disrp ? (q.disrp_ac ? q.disrp : app4 + q.disrp) : p0[app];
  const double app3 = q.infeed == SarInfeed::G340 ? app2 : app4;
  checkMonotonic({p0[app], app1, app2, app3, app4}, s.line);
  const Vec3 p1 = point(s, shape.p3, app1), p2 = point(s, shape.p3, app2),
             p3 = point(s, shape.p3, app3);
  points_ = {p3, p4, true};
  feedback_.approach = points_;
  has_feedback_ = true;

  // Velocities (PM-NC p280, readings V1-V3): P0 -> P2 with the motion and feed of the block
  // before; the slow infeed (G341) with FAD; the contour with FAD (G340) or the block's F.
  const double sar_f = q.f_programmed ? q.feed_value : q.feed_before;
  const Motion fast = q.rapid_before ? Motion::G0 : Motion::G1;
  const auto sub = subBlock;
  auto emit = [&](const MotionBlock& b) {
    if (norm(b.end - b.start) > tol::kPoint) pass(b);
  };
  emit(sub(s, p0, p1, fast, q.feed_before));
  if (q.infeed == SarInfeed::G340) {
    emit(sub(s, p1, p3, fast, q.feed_before));
  } else {
    emit(sub(s, p1, p2, fast, q.feed_before));
    emit(sub(s, p2, p3, Motion::G1, q.has_fad ? q.fad : sar_f));
  }
  const double contour_f = q.infeed == SarInfeed::G340 && q.has_fad  ? q.fad
                           : p4_ && p4_->has_feed && !q.f_programmed ? p4_->feed
                                                                     : sar_f;
  const MotionBlock curve = curveBlock(p4b, p3, p4, shape, contour_f);
  for (int i = 0; i < held_dummies_; ++i) out_.blockWithoutMotion();
  held_dummies_ = 0;
  emit(curve);
  for (const MotionBlock& h : held_) pass(h);
  held_.clear();
}

void SmoothApproach::retraction(const MotionBlock& s) {
  const SarRequest& q = s.sar;
  if (!last_.valid())
    sarAlarm(AlarmNumber::SarNoDirection,
             "SAR: no valid retraction direction: no contour block before the SAR block", s.line);
  PlaneAxes pa = planeAxes(s.plane);
  const int app = pa.applicate;
  const Vec3 p4 = s.start;
  const Vec2 t = tangentOf(last_.motion, last_.d);
  TrcSettings active = s.trc;  // with G40 in the block: the side active before it
  if (s.trc.mode == TrcMode::Off) {
    active.mode = last_trc_.mode;
    active.radius = last_trc_.radius;
  }
  if (!q.plane_axis &&
      (q.side == SarSide::G143 || (q.side == SarSide::G140 && trcSide(active) == 0)))
    sarAlarm(AlarmNumber::SarRetractionDirection,
             "SAR: retraction direction not defined: G143 needs the end point in the SAR block",
             s.line);
  Vec3 p0 = s.end;
  const Shape shape = construct(s, active, inPlane(s, p4), t, inPlane(s, p0), false);
  const double app4 = p4[app];
  const double app2 = q.discl_ac ? q.discl : app4 + (q.has_discl ? q.discl : 0.0);
  const double app3 = q.infeed == SarInfeed::G340 ? app2 : app4;
  // The end point: from the SAR block; without any geometry axis the retraction ends in P2,
  // with only the perpendicular axis in P1 (details §4.3, PM-F 10.2004 8-50).
  if (!q.any_axis)
    p0 = point(s, shape.p3, app2);
  else if (!q.plane_axis)
    p0 = point(s, shape.p3, s.end[app]);
  const double app1 = q.has_disrp ? (q.disrp_ac ? q.disrp : app4 + q.disrp) : p0[app];
  checkMonotonic({app4, app3, app2, app1, p0[app]}, s.line);
  const Vec3 p1 = point(s, shape.p3, app1), p2 = point(s, shape.p3, app2),
             p3 = point(s, shape.p3, app3);
  if (!q.plane_axis) {
    feedback_.end_point = p0;
    has_feedback_ = true;
  }

  // Velocities reversed (PM-NC p280, readings K2/K3): the contour with the old feed (FAD with
  // G340), the slow lift with FAD, from P2 on the block's own motion and feed.
  const double old_f = q.feed_before;
  const Motion own = s.motion == Motion::G0 ? Motion::G0 : Motion::G1;
  std::vector<MotionBlock> subs;
  auto keep = [&](const MotionBlock& b) {  // sub-blocks without length give no row
    if (norm(b.end - b.start) > tol::kPoint) subs.push_back(b);
  };
  auto sub = [&](const Vec3& from, const Vec3& to, Motion mo, double feed) {
    keep(subBlock(s, from, to, mo, feed));
  };
  keep(curveBlock(s, p4, p3, shape, q.infeed == SarInfeed::G340 && q.has_fad ? q.fad : old_f));
  if (q.infeed == SarInfeed::G341) {
    sub(p3, p2, Motion::G1, q.has_fad ? q.fad : old_f);
    sub(p2, p1, own, q.feed_value);
  } else {
    sub(p3, p1, own, q.feed_value);
  }
  sub(p1, p0, own, q.feed_value);
  // A G40 in the retraction block deselects in its last sub-block (reading K1); the ones
  // before still run compensated on the side active before.
  for (size_t i = 0; i < subs.size(); ++i) subs[i].trc = i + 1 < subs.size() ? active : s.trc;
  for (const MotionBlock& b : subs) pass(b);
}

}  // namespace ncoffset::trc
