#include "trc/radius_compensation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "geom/disc_curve.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
using core::TrcMode;
using core::TrcStrategy;
using geom::Element;
using geom::Vec2;

namespace {

// The tolerances, with the values they had as literals; one name per role, so that changing
// one does not change the others by accident.
// Lengths (mm) and element parameters (fractions of an element): "on the element", "the same
// point", "behind the contour".
constexpr double kEps = 1e-9;
// The turn condition of bottleneck detection: the cross product of the two unit tangents at a
// crossing (W1 2.4.8, details Q5).
constexpr double kTurnEps = 1e-9;
// "No value / no motion": a compensation value, a plane or applicate motion, a change of the
// value, the cross product of two antiparallel tangents (a reversal).
constexpr double kZero = 1e-12;
// The index of a block that never comes (for checkOpen when the window is flushed).
constexpr long kNoLaterBlock = std::numeric_limits<long>::max() / 2;
// How far the straight chords of a DISC transition curve may deviate from the curve (mm).
constexpr double kDiscTolerance = 1e-3;

[[noreturn]] void notModelled(const std::string& what) {
  raise(alarm_no::kNotModelled,
        fmt::format("{} is not modelled by ncoffset yet (tool radius compensation)", what));
}

[[noreturn]] void collision(int line, int check_blocks) {
  throw AlarmError(10751,
                   fmt::format("danger of collision due to tool radius compensation: no point of "
                               "intersection found within the reviewed {} traversing blocks "
                               "(MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS)",
                               check_blocks),
                   line);
}

}  // namespace

Element RadiusCompensation::toElement(const MotionBlock& m) const {
  PlaneAxes pa = planeAxes(m.plane);
  Element e;
  e.p0 = {m.start[pa.abscissa], m.start[pa.ordinate]};
  e.p1 = {m.end[pa.abscissa], m.end[pa.ordinate]};
  if (m.motion == Motion::G2 || m.motion == Motion::G3) {
    e.arc = true;
    e.c = {m.centre[pa.abscissa], m.centre[pa.ordinate]};
    e.ccw = m.motion == Motion::G3;
    e.turns = m.turns;
  }
  return e;
}

core::Geometry RadiusCompensation::geometry(const MotionBlock& like, const Element& e) const {
  PlaneAxes pa = planeAxes(like.plane);
  core::Geometry g{like.motion, like.start, like.end, like.centre, like.applicate, like.turns};
  g.start[pa.abscissa] = e.p0.a;
  g.start[pa.ordinate] = e.p0.o;
  g.end[pa.abscissa] = e.p1.a;
  g.end[pa.ordinate] = e.p1.o;
  if (e.arc) {
    g.motion = e.ccw ? Motion::G3 : Motion::G2;
    g.centre[pa.abscissa] = e.c.a;
    g.centre[pa.ordinate] = e.c.o;
    g.centre[pa.applicate] = g.start[pa.applicate];
    g.applicate = pa.applicate;
    g.turns = e.turns;
  } else if (g.motion == Motion::G2 || g.motion == Motion::G3) {
    g.motion = Motion::G1;
  }
  return g;
}

MotionBlock RadiusCompensation::toBlock(const MotionBlock& like, const Element& e) const {
  const core::Geometry g = geometry(like, e);
  MotionBlock b = like;
  b.motion = g.motion;
  b.start = g.start;
  b.end = g.end;
  b.centre = g.centre;
  b.applicate = g.applicate;
  b.turns = g.turns;
  return b;
}

MotionBlock RadiusCompensation::atPoint(const MotionBlock& like, Vec2 at) const {
  Element e;
  e.p0 = e.p1 = at;
  return toBlock(like, e);
}

bool RadiusCompensation::planeMotion(const MotionBlock& m) const {
  if (m.motion == Motion::G2 || m.motion == Motion::G3) return true;
  Element e = toElement(m);
  return geom::length(e.p1 - e.p0) > kZero;
}

RadiusCompensation::Piece RadiusCompensation::compensate(const MotionBlock& m, double r0,
                                                         double r1) const {
  Piece p;
  compensateInto(p, m, r0, r1);
  return p;
}

void RadiusCompensation::compensateInto(Piece& p, const MotionBlock& m, double r0,
                                        double r1) const {
  // Every field is set: `p` may be a reused slot of the window (its vectors keep their memory).
  p.index = 0;
  p.valid = true;
  p.open_before = p.approach = p.restart = p.emitted = false;
  p.strategy = TrcStrategy::G460;
  p.transition.clear();
  p.waiting.clear();
  p.block = m;
  p.programmed = toElement(m);
  p.r0 = r0;
  p.r1 = r1;
  p.side = side();
  const double s = p.side;
  if (r0 == r1) {
    auto eq = geom::equidistant(p.programmed, s * r0);
    if (eq) p.compensated = *eq;
    p.valid = eq.has_value();
  } else if (!p.programmed.arc) {
    // A new value in a line: from start + R_old n to end + R_new n (details Q8).
    Vec2 n = s * geom::leftNormal(p.programmed.startTangent());
    p.compensated = p.programmed;
    p.compensated.p0 = p.programmed.p0 + r0 * n;
    p.compensated.p1 = p.programmed.p1 + r1 * n;
  } else {
    // A new value in a circle: a spiral from radius r -+ R_old to r -+ R_new (details Q8).
    const Element& e = p.programmed;
    const double r = e.radius();
    const double k = e.ccw ? -s : s;  // the left side of a ccw arc is its inside
    const double ra = r + k * r0, rb = geom::length(e.p1 - e.c) + k * r1;
    if (ra <= kEps || rb <= kEps)
      raise(10758, "curvature radius with variable compensation value too small");
    p.compensated = e;
    p.compensated.p0 = e.c + (ra / r) * (e.p0 - e.c);
    p.compensated.p1 = e.c + (rb / geom::length(e.p1 - e.c)) * (e.p1 - e.c);
  }
  p.raw = p.compensated;
  p.box = geom::Box(p.raw);  // the trimmed element always stays inside
  if (r0 != r1) {            // a varying value (spiral, inclined line): widen by the change
    const double d = std::fabs(r1 - r0);
    p.box.lo_a -= d, p.box.lo_o -= d, p.box.hi_a += d, p.box.hi_o += d;
  }
}

Element RadiusCompensation::cornerEquidistant(const Piece& p, bool at_end) const {
  if (p.r0 == p.r1) return p.compensated;
  double r = at_end ? p.r1 : p.r0;
  auto e = geom::equidistant(p.programmed, p.side * r);
  return e ? *e : p.compensated;
}

void RadiusCompensation::compensateNext(Piece& p, const MotionBlock& m) {
  const double old_side = side(), old_r = std::fabs(settings_.radius);
  const double new_r = std::fabs(m.trc.radius);
  settings_ = m.trc;
  if (sideOf(m.trc) != old_side) {
    // G41 <-> G42 (or the sign of the value) while active: the last element ends on its normal,
    // the new side starts on the normal at this block's start (PM-NC "change of compensation
    // direction"; details Q8 for the sign).
    compensateInto(p, m, new_r, new_r);
    p.restart = true;
    return;
  }
  compensateInto(p, m, old_r, std::fabs(old_r - new_r) < kZero ? old_r : new_r);
}

void RadiusCompensation::emitPiece(const Piece& p) {
  for (const MotionBlock& t : p.transition) emit(t);
  out_.element(p.block, geometry(p.block, p.compensated));  // no copy of the block
  for (const MotionBlock& w : p.waiting) emit(atPoint(w, p.compensated.p1));
}

void RadiusCompensation::checkSameSettings(const MotionBlock& m) const {
  if (m.plane != selection_.plane)
    raise(10757,
          "change of compensation plane not possible while tool radius compensation is active");
  if (!m.frame.sameAs(selection_.frame)) notModelled("a frame change while compensation is active");
}

void RadiusCompensation::blockWithoutMotion() {
  if (state_ == State::Off) return;
  if (++dummy_blocks_ > settings_.max_dummy_blocks)
    raise(10762, fmt::format("too many empty blocks between two traversing blocks with active tool "
                             "radius compensation (MD20250 = {})",
                             settings_.max_dummy_blocks));
}

core::Feedback RadiusCompensation::motion(const MotionBlock& m) {
  out_.programmed(m);
  switch (state_) {
    case State::Off: {
      const bool wants = m.trc.mode != TrcMode::Off && std::fabs(m.trc.radius) > kZero;
      if (!wants || !planeMotion(m)) {
        emit(m);  // no compensation, or no plane axis in the block: no selection yet (W1 2-41)
        return {};
      }
      if (m.motion != Motion::G0 && m.motion != Motion::G1)
        raise(10753, "activation of tool radius compensation only possible in linear block");
      if (m.trc.approach == Approach::KontC || m.trc.approach == Approach::KontT)
        notModelled(m.trc.approach == Approach::KontC ? "KONTC" : "KONTT");
      settings_ = m.trc;
      selection_ = m;
      state_ = State::Selecting;
      dummy_blocks_ = 0;
      return {};
    }
    case State::Selecting: {
      if (m.trc.mode == TrcMode::Off) {
        // G40 in the block after the selection block: no selection takes place (W1 2-41).
        emit(selection_);
        for (const auto& w : waiting_) emit(w);
        waiting_.clear();
        emit(m);
        state_ = State::Off;
        return {};
      }
      checkSameSettings(m);
      if (!planeMotion(m)) {
        waiting_.push_back(m);
        blockWithoutMotion();
        return {};
      }
      if (sideOf(m.trc) != side()) settings_ = m.trc;  // the side of the first element counts
      const double r = std::fabs(settings_.radius);
      Piece first = compensate(m, r, r);
      if (!first.valid) collision(m.line, settings_.check_blocks);  // no element to approach
      Piece approach;
      approach.block = selection_;
      approach.approach = true;
      approach.strategy = selection_.trc.strategy;
      approach.side = first.side;
      approach.first_tangent = first.programmed.startTangent();
      approach.programmed = toElement(selection_);
      approach.compensated.p0 = approach.programmed.p0;
      approach.compensated.p1 = first.compensated.p0;
      const Vec2 p1 = first.programmed.p0;
      const Vec2 n1 = first.side * geom::leftNormal(first.programmed.startTangent());
      if (selection_.trc.approach == Approach::Kont &&
          geom::dot(approach.programmed.p0 - p1, n1) < -kEps) {
        approach.strategy =
            TrcStrategy::G460;  // the point behind the contour: G461/G462 have no effect (Q7)
        kontApproach(approach, first);
      } else if (geom::length(approach.compensated.p1 - approach.compensated.p0) > kEps) {
        // NORM: one straight line to the normal point of the first element (details Q1); if it
        // cuts the first equidistant earlier, the intersection nearest the start of the line
        // replaces that point (G460).
        auto best = geom::nearestCrossing(
            approach.compensated, first.compensated,
            [](const geom::Crossing& x) {
              return x.u1 > kEps && x.u1 < 1 - kEps && x.u2 > -kEps && x.u2 < 1 + kEps;
            },
            [](const geom::Crossing& x) { return x.u1; });
        if (best) approach.compensated.p1 = first.compensated.p0 = best->p;
      }
      approach.raw = approach.compensated;
      approach.box = geom::Box(approach.raw);
      approach.waiting = std::move(waiting_);
      waiting_.clear();
      window_.clear();
      count_ = 1;
      first.index = 1;
      window_.pushBack() = std::move(approach);
      window_.pushBack() = std::move(first);
      dummy_blocks_ = 0;
      state_ = State::On;
      return {};
    }
    case State::On: {
      if (m.trc.mode == TrcMode::Off) {
        retract(m);
        return {};
      }
      checkSameSettings(m);
      if (!planeMotion(m)) {
        if (window_.back().emitted)  // after STOPRE: runs where the last element ended
          emit(atPoint(m, window_.back().compensated.p1));
        else
          window_.back().waiting.push_back(m);
        settings_.max_dummy_blocks = m.trc.max_dummy_blocks;
        blockWithoutMotion();
        return {};
      }
      Piece& next = window_.pushBack();
      compensateNext(next, m);
      next.index = ++count_;
      next.restart = next.restart || restart_next_;
      restart_next_ = false;
      connect(window_[window_.size() - 2], next);
      // Bottleneck detection closes junctions, never opens one: with none open before it,
      // there is nothing for checkOpen to find.
      const bool open = anyOpen();
      bridge(next, open);
      if (open) checkOpen(count_ + 1);
      release();
      dummy_blocks_ = 0;
      return {};
    }
  }
  return {};
}

void RadiusCompensation::connect(Piece& cur, Piece& next) {
  if (!cur.valid || !next.valid) {
    next.open_before = true;
    return;
  }
  const Vec2 a = cur.compensated.p1, b = next.compensated.p0;
  if (next.restart) {
    // A new side: no corner; a straight line from the old normal point to the new one, part
    // of the new block.
    if (geom::length(a - b) > kEps) {
      Element line;
      line.p0 = a;
      line.p1 = b;
      MotionBlock lb = toBlock(next.block, line);
      PlaneAxes pa = planeAxes(lb.plane);
      lb.end[pa.applicate] = lb.start[pa.applicate];
      next.transition.assign(1, lb);
    }
    return;
  }
  const Vec2 p = cur.programmed.p1;  // the corner point
  if (geom::length(a - b) < kEps) {  // tangent transition: nothing inserted
    next.compensated.p0 = a;
    return;
  }
  const Vec2 t1 = cur.programmed.endTangent(), t2 = next.programmed.startTangent();
  const double c = geom::cross(t1, t2), d = geom::dot(t1, t2);
  const double s = next.side;
  const bool reversal = std::fabs(c) < kZero && d < 0;
  const bool inside = !reversal && s * c > 0;
  const Element e1 = cornerEquidistant(cur, true), e2 = cornerEquidistant(next, false);
  if (inside) {
    // Inside corner: both elements end at the intersection of their equidistants; of several,
    // the one nearest the start of the next block (W1 2.4.3). None: the look-ahead decides.
    auto best = geom::nearestCrossing(
        e1, e2,
        [](const geom::Crossing& x) {
          return x.u1 > -kEps && x.u1 < 1 + kEps && x.u2 > -kEps && x.u2 < 1 + kEps;
        },
        [](const geom::Crossing& x) { return x.u2; });
    if (!best) {
      next.open_before = true;
      return;
    }
    cur.compensated.p1 = next.compensated.p0 = best->p;
    return;
  }
  // An outside corner by its tangents whose curved equidistants still cross within both
  // elements (an arc bending back over its neighbour): the tool cannot pass the crossing
  // without cutting into the other element, so it is treated like an inside corner [D].
  if (cur.programmed.arc || next.programmed.arc) {
    auto best = geom::nearestCrossing(
        e1, e2,
        [](const geom::Crossing& x) {
          return x.u1 > kEps && x.u1 < 1 - kEps && x.u2 > kEps && x.u2 < 1 - kEps;
        },
        [](const geom::Crossing& x) { return x.u2; });
    if (best) {
      cur.compensated.p1 = next.compensated.p0 = best->p;
      return;
    }
  }
  // Outside corner (details Q3/Q4): G450 circle unless flatter than MD20230; G451 intersection
  // unless the contour angle reaches MD20210.
  const double angle = reversal ? 180.0 : geom::angleDeg(t1, t2);
  const core::TrcSettings& t = next.block.trc;
  bool circle = t.corner == CornerMode::TransitionCircle ? !(angle < t.curve_insert_limit)
                                                         : angle >= t.corner_limit;
  if (!circle) {
    // The intersection of the extended equidistants nearest the corner point.
    auto best = geom::nearestCrossing(
        e1, e2, [](const geom::Crossing& x) { return x.u1 > 1 - kEps && x.u2 < kEps; },
        [&p](const geom::Crossing& x) { return geom::length(x.p - p); });
    if (best) {
      cur.compensated.p1 = next.compensated.p0 = best->p;
      return;
    }
  }
  // Transition circle of the tool radius about the corner point (or the DISC curve); it
  // belongs to the next block.
  const double app = next.block.start[planeAxes(next.block.plane).applicate];
  next.transition.clear();
  transition(next.transition, next.block, a, t1, b, t2, p, s,
             t.corner == CornerMode::TransitionCircle ? t.disc : 0, app, app);
}

void RadiusCompensation::transition(std::vector<MotionBlock>& out, const MotionBlock& like, Vec2 a,
                                    Vec2 ta, Vec2 b, Vec2 tb, Vec2 p, double s, double disc,
                                    double app0, double app1) const {
  PlaneAxes pa = planeAxes(like.plane);
  if (disc > 0) {
    if (auto curve = geom::discCurve(a, ta, b, tb, p, disc)) {
      // DISC: the curve as straight chords within kDiscTolerance (the applicate, if it moves,
      // is spread over them).
      const std::vector<Vec2> pts = geom::chords(*curve, kDiscTolerance);
      Vec2 from = a;
      for (size_t i = 0; i < pts.size(); ++i) {
        Element chord;
        chord.p0 = from;
        chord.p1 = pts[i];
        MotionBlock cb = toBlock(like, chord);
        cb.motion = like.motion == Motion::G0 ? Motion::G0 : Motion::G1;
        const double f0 = static_cast<double>(i) / pts.size(),
                     f1 = static_cast<double>(i + 1) / pts.size();
        cb.start[pa.applicate] = app0 + f0 * (app1 - app0);
        cb.end[pa.applicate] = app0 + f1 * (app1 - app0);
        out.push_back(cb);
        from = pts[i];
      }
      return;
    }
  }
  Element arc;
  arc.arc = true;
  arc.p0 = a;
  arc.p1 = b;
  arc.c = p;
  arc.ccw = s < 0;  // around the outside: clockwise for G41, counter-clockwise for G42
  MotionBlock tb_block = toBlock(like, arc);
  tb_block.start[pa.applicate] = app0;
  tb_block.end[pa.applicate] = app1;
  tb_block.centre[pa.applicate] = app0;
  tb_block.turns = 0;
  out.push_back(tb_block);
}

std::optional<geom::Crossing> RadiusCompensation::bridgeCrossing(
    const Piece& c, const Element& target, bool extension, const Element& later, double side) {
  auto accept = [&](const geom::Crossing& x) {
    const bool on_target =
        extension ? (!target.arc ? x.u1 > -kEps : true) : x.u1 > kEps && x.u1 < 1 - kEps;
    if (!on_target || x.u2 < -kEps || x.u2 > 1 - kEps) return false;
    // Like an inside corner: the later element turns towards the compensation side.
    // (With an extension the approach becomes the straight line to the point.)
    const Vec2 t1 = extension    ? geom::unit(x.p - c.compensated.p0)
                    : target.arc ? geom::tangentAt(target, x.p)
                                 : geom::unit(target.p1 - target.p0);
    return !(side * geom::cross(t1, geom::tangentAt(later, x.p)) < kTurnEps);
  };
  // Nearest the start of the later element.
  return geom::nearestCrossing(target, later, accept, [](const geom::Crossing& x) { return x.u2; });
}

bool RadiusCompensation::anyOpen() const {
  for (size_t i = 0; i < window_.size(); ++i)
    if (window_[i].open_before || !window_[i].valid) return true;
  return false;
}

void RadiusCompensation::bridge(Piece& next, bool needed) {
  // `next` is the window's last element.
  if (!next.valid || window_.size() < 3 || (!needed && settings_.collision != CollisionCheck::Cdon))
    return;
  // Search back from the element before the last one (the last one was tried as the corner);
  // CDOF stops at the first intersection found, CDON keeps searching and takes the last found
  // (W1 2.4.8, details Q5).
  const long oldest = next.index - settings_.check_blocks;
  // The later element at its start value (details Q8); with a constant value it is the piece
  // itself, with its box (no copy).
  Element changed;
  if (next.r0 != next.r1) changed = cornerEquidistant(next, false);
  const Element& later = next.r0 == next.r1 ? next.compensated : changed;
  const geom::Box later_box = next.r0 == next.r1 ? next.box : geom::Box(later);
  std::optional<std::pair<size_t, Vec2>> found;
  for (size_t j = window_.size() - 2; j-- > 0;) {
    const Piece& c = window_[j];
    if (c.index < oldest || c.emitted) break;
    if (!c.valid || (c.approach && !needed)) continue;
    // The element itself, then for an approach line with G461 a circle of the tool radius about
    // the end point of the uncompensated approach block, with G462 the line's extension; both
    // only to find an intersection (W1 2.4.10, details Q7).
    std::optional<geom::Crossing> best;
    if (c.box.overlaps(later_box)) best = bridgeCrossing(c, c.compensated, false, later, next.side);
    if (!best && c.approach &&
        (c.strategy == TrcStrategy::G461 || c.strategy == TrcStrategy::G462)) {
      Element extension;
      if (c.strategy == TrcStrategy::G461) {
        extension = geom::fullCircle(c.programmed.p1, std::fabs(next.r0));
      } else {
        // G462: the first element's equidistant extended backwards from the approach point
        // along its start tangent, the mirror image of the retraction's extension (details Q7).
        extension.p0 = c.compensated.p1;
        extension.p1 = c.compensated.p1 - c.first_tangent;
      }
      best = bridgeCrossing(c, extension, true, later, next.side);
    }
    if (!best) continue;
    found = {j, best->p};
    if (settings_.collision != CollisionCheck::Cdon) break;
  }
  if (!found) return;
  auto [j, at] = *found;
  window_[j].compensated.p1 = at;
  next.compensated.p0 = at;
  next.transition.clear();
  next.open_before = false;
  omitAfter(j, at, true);
}

void RadiusCompensation::omitAfter(size_t keep, Vec2 at, bool keep_last) {
  PlaneAxes pa = planeAxes(selection_.plane);
  const size_t end = keep_last ? window_.size() - 1 : window_.size();
  for (size_t i = keep + 1; i < end; ++i) {
    Piece& p = window_[i];
    out_.warning(p.block, 10763,
                 "path component of the block in the compensation plane becomes zero: block "
                 "omitted by bottleneck detection of tool radius compensation");
    // Everything but the plane motion runs at the intersection, in program order (Q5).
    if (std::fabs(p.block.end[pa.applicate] - p.block.start[pa.applicate]) > kZero)
      window_[keep].waiting.push_back(atPoint(p.block, at));
    for (auto& w : p.waiting) window_[keep].waiting.push_back(std::move(w));
  }
  if (keep_last && end > keep + 1) window_[keep + 1] = std::move(window_.back());
  window_.truncate(keep_last ? keep + 2 : keep + 1);
}

void RadiusCompensation::checkOpen(long next_index) const {
  for (size_t i = 1; i < window_.size(); ++i) {
    const Piece& p = window_[i];
    if (!p.open_before && p.valid) continue;
    const Piece& pred = window_[i - 1];
    if (pred.index < next_index - settings_.check_blocks)
      collision(p.valid ? pred.block.line : p.block.line, settings_.check_blocks);
  }
}

void RadiusCompensation::release() {
  const long reach = count_ + 1 - settings_.check_blocks;
  while (window_.size() > 1 && window_.front().index < reach) {
    if (!window_.front().emitted) emitPiece(window_.front());
    window_.popFront();
  }
}

void RadiusCompensation::flushAll() {
  checkOpen(kNoLaterBlock);  // no later block: every open junction stays open
  for (size_t i = 0; i < window_.size(); ++i)
    if (!window_[i].emitted) emitPiece(window_[i]);
  window_.clear();
}

void RadiusCompensation::retract(const MotionBlock& m) {
  // Deselection with G40 (NORM): the last element ends on its normal at its end point, then a
  // straight line to the programmed end point (details Q1).
  if (m.motion != Motion::G0 && m.motion != Motion::G1)
    raise(10754, "deactivation of tool radius compensation only possible in linear block");
  if (m.trc.approach == Approach::KontC || m.trc.approach == Approach::KontT)
    notModelled(m.trc.approach == Approach::KontC ? "KONTC" : "KONTT");
  Piece& last = window_.back();
  if (!last.valid) collision(last.block.line, settings_.check_blocks);
  const Vec2 pe = last.programmed.p1;
  const Vec2 ne = last.side * geom::leftNormal(last.programmed.endTangent());
  Element retract = toElement(m);
  if (m.trc.approach == Approach::Kont && !last.emitted && geom::dot(retract.p1 - pe, ne) < -kEps) {
    kontRetraction(m);
    return;
  }
  if (last.open_before && !last.emitted &&
      (m.trc.strategy == TrcStrategy::G461 || m.trc.strategy == TrcStrategy::G462)) {
    // G461/G462: the last element, which meets no earlier one, is extended by a circle about
    // its programmed end point (radius R) or along its end tangent; the intersection with an
    // earlier element ends that element and starts the retraction (W1 2.4.10, details Q7).
    Element ext;
    if (m.trc.strategy == TrcStrategy::G461) {
      ext = geom::fullCircle(pe, std::fabs(last.r1));
    } else {
      ext.p0 = last.raw.p1;
      ext.p1 = last.raw.p1 + last.programmed.endTangent();
    }
    const long oldest = count_ + 1 - settings_.check_blocks;
    std::optional<std::pair<size_t, Vec2>> found;
    for (size_t j = window_.size() - 1; j-- > 0;) {
      const Piece& c = window_[j];
      if (c.index < oldest) break;
      if (!c.valid) continue;
      // On the earlier element (a line extension only forwards), nearest its end.
      auto best = geom::nearestCrossing(
          c.compensated, ext,
          [&ext](const geom::Crossing& x) {
            return x.u1 > kEps && x.u1 < 1 + kEps && (ext.arc || x.u2 > -kEps);
          },
          [](const geom::Crossing& x) { return -x.u1; });
      if (!best) continue;
      found = {j, best->p};
      if (m.trc.collision != CollisionCheck::Cdon) break;
    }
    if (found) {
      window_[found->first].compensated.p1 = found->second;
      omitAfter(found->first, found->second, false);
    }
  }
  // G460: if the retraction line cuts the last equidistant before its end, that intersection
  // (the one nearest the end of the equidistant) replaces the normal point (details Q1).
  Piece& fin = window_.back();
  retract.p0 = fin.compensated.p1;
  if (!fin.approach && !fin.emitted && geom::length(retract.p1 - retract.p0) > kEps) {
    auto best = geom::nearestCrossing(
        fin.compensated, retract,
        [](const geom::Crossing& x) {
          return x.u1 > -kEps && x.u1 < 1 - kEps && x.u2 > kEps && x.u2 < 1 + kEps;
        },
        [](const geom::Crossing& x) { return -x.u1; });
    if (best) fin.compensated.p1 = best->p;
    retract.p0 = fin.compensated.p1;
  }
  flushAll();
  emit(toBlock(m, retract));
  state_ = State::Off;
}

// KONT with the start point behind the contour (details Q2): a straight line tangent to the
// circle of radius R about the contour start point, then (G450) an arc on that circle to the
// normal point of the first element, or (G451, below MD20210) the line extended to the first
// equidistant. Both belong to the selection block.
void RadiusCompensation::kontApproach(Piece& approach, Piece& first) {
  const Vec2 p0 = approach.programmed.p0;
  const Vec2 p1 = first.programmed.p0;
  const double r = std::fabs(settings_.radius), s = first.side;
  std::optional<Vec2> t = geom::tangentPoint(p0, p1, r, s, true);
  if (!t)
    throw AlarmError(
        10755,
        "activation of tool radius compensation via KONT not possible in current start point",
        selection_.line);  // the selection block is the one to change
  Element line;
  line.p0 = p0;
  line.p1 = *t;
  const Vec2 dir = geom::unit(*t - p0);
  const double angle = geom::angleDeg(dir, first.programmed.startTangent());
  if (settings_.corner == CornerMode::Intersection && angle < settings_.corner_limit) {
    // The line extended meets the first equidistant extended backwards: nearest the contour
    // start point.
    auto best = geom::nearestCrossing(
        line, first.compensated, [](const geom::Crossing& x) { return x.u1 > kEps && x.u2 < kEps; },
        [&p1](const geom::Crossing& x) { return geom::length(x.p - p1); });
    if (best) {
      approach.compensated.p1 = best->p;
      first.compensated.p0 = best->p;
      return;
    }
  }
  PlaneAxes pa = planeAxes(selection_.plane);
  approach.compensated.p1 = *t;
  approach.block.end[pa.applicate] = approach.block.start[pa.applicate];  // moves with the circle
  first.transition.clear();
  transition(first.transition, selection_, *t, dir, first.compensated.p0,
             first.programmed.startTangent(), p1, s,
             settings_.corner == CornerMode::TransitionCircle ? settings_.disc : 0,
             approach.block.end[pa.applicate], selection_.end[pa.applicate]);
}

// KONT retraction with the end point behind the contour (details Q2): from the normal point of
// the last element, an arc about its end point to the tangent point of the line through the
// programmed end point (G450), or the last equidistant extended to that line (G451); then the
// straight line to the programmed end point. Both belong to the G40 block.
void RadiusCompensation::kontRetraction(const MotionBlock& m) {
  Piece& last = window_.back();
  const Vec2 pe = last.programmed.p1;
  const Vec2 p2 = toElement(m).p1;
  const double r = std::fabs(last.r1), s = last.side;
  std::optional<Vec2> t = geom::tangentPoint(p2, pe, r, s, false);
  if (!t)
    raise(10756,
          "deactivation of tool radius compensation via KONT not possible at programmed end point");
  Element line;
  line.p0 = *t;
  line.p1 = p2;
  PlaneAxes pa = planeAxes(m.plane);
  const Vec2 dir = geom::unit(p2 - *t);
  const double angle = geom::angleDeg(last.programmed.endTangent(), dir);
  if (m.trc.corner == CornerMode::Intersection && angle < settings_.corner_limit) {
    // The last equidistant extended meets the line extended backwards: nearest the contour
    // end point.
    auto best = geom::nearestCrossing(
        last.compensated, line,
        [](const geom::Crossing& x) { return x.u1 > 1 - kEps && x.u2 < 1 - kEps; },
        [&pe](const geom::Crossing& x) { return geom::length(x.p - pe); });
    if (best) {
      last.compensated.p1 = best->p;
      line.p0 = best->p;
      flushAll();
      emit(toBlock(m, line));
      state_ = State::Off;
      return;
    }
  }
  std::vector<MotionBlock> around;
  transition(around, m, last.compensated.p1, last.programmed.endTangent(), *t, dir, pe, s,
             m.trc.corner == CornerMode::TransitionCircle ? m.trc.disc : 0, m.start[pa.applicate],
             m.start[pa.applicate]);
  flushAll();
  for (const MotionBlock& b : around) emit(b);
  emit(toBlock(m, line));
  state_ = State::Off;
}

void RadiusCompensation::preprocessorStop(bool alarm) {
  if (state_ == State::Off) return;
  if (alarm) raise(10778, "preprocessor stop with active tool radius compensation (SD42480 = 1)");
  // "Traversing continues to the offset point in the last block. Correspondingly, the offset
  // point in the start point is approached in the first block after a preprocessing stop."
  // (FM-W1 08/2005 2.4.11). The contour may be violated, as the manual warns.
  Piece anchor;
  if (state_ == State::Selecting) {
    const double r = std::fabs(settings_.radius);
    anchor = compensate(selection_, r, r);
    Element approach;
    approach.p0 = anchor.programmed.p0;
    approach.p1 = anchor.compensated.p1;
    emit(toBlock(selection_, approach));
    for (const MotionBlock& w : waiting_) emit(atPoint(w, approach.p1));
    waiting_.clear();
    state_ = State::On;
    count_ = 0;
  } else {
    anchor = window_.back();
    flushAll();
  }
  anchor.emitted = true;
  anchor.waiting.clear();
  anchor.transition.clear();
  window_.clear();
  window_.pushBack() = std::move(anchor);
  restart_next_ = true;
}

void RadiusCompensation::flush() {
  if (state_ == State::Selecting) {
    // No contour element follows the selection block: it ends on its own normal.
    const double r = std::fabs(settings_.radius);
    Piece only = compensate(selection_, r, r);
    Element approach;
    approach.p0 = only.programmed.p0;
    approach.p1 = only.compensated.p1;
    emit(toBlock(selection_, approach));
    for (const MotionBlock& w : waiting_) emit(atPoint(w, approach.p1));
  } else if (state_ == State::On) {
    flushAll();
  }
  waiting_.clear();
  window_.clear();
  state_ = State::Off;
}

}  // namespace ncoffset::trc
