#include "trc/radius_compensation.hpp"

#include <fmt/format.h>

#include <cmath>

#include "ncoffset/alarm.hpp"

namespace ncoffset::trc {

using geom::Element;
using geom::Vec2;
using place::MotionBlock;

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr double kEps = 1e-9;

[[noreturn]] void notModelled(const std::string& what) {
  raise(alarm_no::kNotModelled,
        fmt::format("{} is not modelled by ncoffset yet (tool radius compensation)", what));
}

bool sameAffine(const Affine& a, const Affine& b) {
  for (size_t i = 0; i < 3; ++i) {
    if (std::fabs(a.offset[static_cast<int>(i)] - b.offset[static_cast<int>(i)]) > 1e-12) return false;
    for (size_t j = 0; j < 3; ++j)
      if (std::fabs(a.linear.m[i][j] - b.linear.m[i][j]) > 1e-12) return false;
  }
  return true;
}

// The tangent point on the circle about `c` (radius r) of a line through `p` along which the
// tool keeps `c` on its right (s > 0, G41) or left (s < 0, G42): travelling p -> T on approach,
// T -> p on retraction (details Q2). nullopt when p lies inside the circle.
std::optional<Vec2> tangentPoint(Vec2 p, Vec2 c, double r, double s, bool approach) {
  Vec2 v = p - c;
  double d = geom::length(v);
  if (d <= r + kEps) return std::nullopt;
  double phi = std::atan2(v.o, v.a), alpha = std::acos(r / d);
  for (double ang : {phi + alpha, phi - alpha}) {
    Vec2 t{c.a + r * std::cos(ang), c.o + r * std::sin(ang)};
    Vec2 dir = approach ? t - p : p - t;
    double sidedness = geom::cross(dir, c - (approach ? p : t));
    if (s * sidedness < 0) return t;
  }
  return std::nullopt;
}

}  // namespace

double RadiusCompensation::side() const {
  // G41: left of the direction of travel; a negative compensation value changes the side
  // (PM-NC p256).
  double s = settings_.mode == 41 ? 1.0 : -1.0;
  return settings_.radius < 0 ? -s : s;
}

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

MotionBlock RadiusCompensation::toBlock(const MotionBlock& like, const Element& e) const {
  PlaneAxes pa = planeAxes(like.plane);
  MotionBlock b = like;
  b.start[pa.abscissa] = e.p0.a;
  b.start[pa.ordinate] = e.p0.o;
  b.end[pa.abscissa] = e.p1.a;
  b.end[pa.ordinate] = e.p1.o;
  if (e.arc) {
    b.motion = e.ccw ? Motion::G3 : Motion::G2;
    b.centre[pa.abscissa] = e.c.a;
    b.centre[pa.ordinate] = e.c.o;
    b.centre[pa.applicate] = b.start[pa.applicate];
    b.applicate = pa.applicate;
    b.turns = e.turns;
  } else if (b.motion == Motion::G2 || b.motion == Motion::G3) {
    b.motion = Motion::G1;
  }
  return b;
}

bool RadiusCompensation::planeMotion(const MotionBlock& m) const {
  if (m.motion == Motion::G2 || m.motion == Motion::G3) return true;
  Element e = toElement(m);
  return geom::length(e.p1 - e.p0) > 1e-12;
}

RadiusCompensation::Piece RadiusCompensation::compensate(const MotionBlock& m, double r0,
                                                          double r1) const {
  Piece p;
  p.block = m;
  p.programmed = toElement(m);
  p.r0 = r0;
  p.r1 = r1;
  double r = std::fmax(r0, r1);
  auto eq = geom::equidistant(p.programmed, side() * r);
  if (!eq)
    raise(10751, fmt::format("danger of collision due to tool radius compensation: the arc radius "
                             "{} is not larger than the compensation value {} on its inside",
                             p.programmed.radius(), r));
  p.compensated = *eq;
  if (r0 != r1) {
    // Only lines get here: from start + R_old n to end + R_new n.
    Vec2 n = side() * geom::leftNormal(p.programmed.startTangent());
    p.compensated.p0 = p.programmed.p0 + r0 * n;
    p.compensated.p1 = p.programmed.p1 + r1 * n;
  }
  return p;
}

Element RadiusCompensation::cornerEquidistant(const Piece& p, bool at_end) const {
  double r = at_end ? p.r1 : p.r0;
  if (p.r0 == p.r1) return p.compensated;
  Element e = *geom::equidistant(p.programmed, side() * r);  // a line: always exists
  return e;
}

RadiusCompensation::Piece RadiusCompensation::compensateWithChange(const MotionBlock& m) {
  const double old_r = std::fabs(settings_.radius), new_r = std::fabs(m.trc.radius);
  if (std::fabs(old_r - new_r) < 1e-12) return compensate(m);
  if ((m.trc.radius < 0) != (settings_.radius < 0))
    notModelled("a change of the compensation value that changes its sign (side) while active");
  if (m.motion == Motion::G2 || m.motion == Motion::G3)
    notModelled("a change of the compensation value in a circle block (a spiral, details Q8)");
  settings_.radius = m.trc.radius;
  return compensate(m, old_r, new_r);
}

void RadiusCompensation::emitPiece(const Piece& p) { emit(toBlock(p.block, p.compensated)); }

void RadiusCompensation::emitWaiting(Vec2 at) {
  // Blocks without plane motion (infeed, other axes) run at the intermediate point (PM-F 8-40).
  for (MotionBlock w : waiting_) {
    PlaneAxes pa = planeAxes(w.plane);
    w.start[pa.abscissa] = w.end[pa.abscissa] = at.a;
    w.start[pa.ordinate] = w.end[pa.ordinate] = at.o;
    emit(w);
  }
  waiting_.clear();
}

void RadiusCompensation::checkSameSettings(const MotionBlock& m) const {
  if (m.trc.mode != settings_.mode)
    notModelled(fmt::format("changing from G{} to G{} while compensation is active", settings_.mode,
                            m.trc.mode));
  if (m.trc.collision == CollisionCheck::Cdon) notModelled("CDON bottleneck detection");
  if (m.plane != selection_.plane)
    raise(10757, "change of compensation plane not possible while tool radius compensation is active");
  if (!sameAffine(m.frame, selection_.frame))
    notModelled("a frame change while compensation is active");
}

void RadiusCompensation::blockWithoutMotion() {
  if (state_ == State::Off) return;
  if (++dummy_blocks_ > settings_.max_dummy_blocks)
    raise(10762, fmt::format("too many empty blocks between two traversing blocks with active tool "
                             "radius compensation (MD20250 = {})",
                             settings_.max_dummy_blocks));
}

void RadiusCompensation::motion(const MotionBlock& m) {
  out_.programmed(m);
  switch (state_) {
    case State::Off: {
      const bool wants = m.trc.mode != 40 && std::fabs(m.trc.radius) > 1e-12;
      if (!wants || !planeMotion(m)) {
        emit(m);  // no compensation, or no plane axis in the block: no selection yet (W1 2-41)
        return;
      }
      if (m.motion != Motion::G0 && m.motion != Motion::G1)
        raise(10753, "activation of tool radius compensation only possible in linear block");
      if (m.trc.approach == Approach::KontC || m.trc.approach == Approach::KontT)
        notModelled(m.trc.approach == Approach::KontC ? "KONTC" : "KONTT");
      if (m.trc.collision == CollisionCheck::Cdon) notModelled("CDON bottleneck detection");
      if (m.trc.strategy != 460) notModelled(fmt::format("G{}", m.trc.strategy));
      settings_ = m.trc;
      selection_ = m;
      state_ = State::Selecting;
      dummy_blocks_ = 0;
      return;
    }
    case State::Selecting: {
      if (m.trc.mode == 40) {
        // G40 in the block after the selection block: no selection takes place (W1 2-41).
        emit(selection_);
        for (const auto& w : waiting_) emit(w);
        waiting_.clear();
        emit(m);
        state_ = State::Off;
        return;
      }
      checkSameSettings(m);
      if (!planeMotion(m)) {
        waiting_.push_back(m);
        blockWithoutMotion();
        return;
      }
      Piece first = compensate(m);
      Element approach;
      approach.p0 = toElement(selection_).p0;
      approach.p1 = first.compensated.p0;
      const Vec2 p1 = first.programmed.p0;
      const Vec2 n1 = side() * geom::leftNormal(first.programmed.startTangent());
      if (settings_.approach == Approach::Kont && geom::dot(approach.p0 - p1, n1) < -kEps) {
        kontApproach(first);
        return;
      }
      // NORM: one straight line to the normal point of the first element (details Q1); if it
      // cuts the first equidistant earlier, the intersection replaces that point (G460).
      if (geom::length(approach.p1 - approach.p0) > kEps) {
        double best = 2;
        for (const auto& x : geom::intersect(approach, first.compensated))
          if (x.u1 > kEps && x.u1 < 1 - 1e-9 && x.u2 > -kEps && x.u2 < 1 + kEps && x.u1 < best) {
            best = x.u1;
            approach.p1 = x.p;
          }
        if (best < 2) first.compensated.p0 = approach.p1;
      }
      emit(toBlock(selection_, approach));
      emitWaiting(approach.p1);
      pending_ = first;
      dummy_blocks_ = 0;
      state_ = State::On;
      return;
    }
    case State::On: {
      if (m.trc.mode == 40) {
        // Deselection with G40 (NORM): the last element ends on its normal at its end point,
        // then a straight line to the programmed end point (details Q1).
        if (m.motion != Motion::G0 && m.motion != Motion::G1)
          raise(10754, "deactivation of tool radius compensation only possible in linear block");
        if (m.trc.strategy != 460) notModelled(fmt::format("G{}", m.trc.strategy));
        const Piece& last = *pending_;
        const Vec2 pe = last.programmed.p1;
        const Vec2 ne = side() * geom::leftNormal(last.programmed.endTangent());
        Element retract = toElement(m);
        if (m.trc.approach == Approach::Kont && geom::dot(retract.p1 - pe, ne) < -kEps) {
          kontRetraction(m);
          return;
        }
        if (m.trc.approach == Approach::KontC || m.trc.approach == Approach::KontT)
          notModelled(m.trc.approach == Approach::KontC ? "KONTC" : "KONTT");
        // G460: if the retraction line cuts the last equidistant before its end, that
        // intersection replaces the normal point (details Q1).
        Piece fin = last;
        retract.p0 = fin.compensated.p1;
        if (geom::length(retract.p1 - retract.p0) > kEps) {
          double best = -1;
          for (const auto& x : geom::intersect(fin.compensated, retract))
            if (x.u1 > -kEps && x.u1 < 1 - 1e-9 && x.u2 > 1e-9 && x.u2 < 1 + kEps && x.u1 > best) {
              best = x.u1;
              fin.compensated.p1 = x.p;
            }
          retract.p0 = fin.compensated.p1;
        }
        emitPiece(fin);
        emitWaiting(fin.compensated.p1);
        MotionBlock b = toBlock(m, retract);
        emit(b);
        pending_.reset();
        state_ = State::Off;
        return;
      }
      checkSameSettings(m);
      settings_.corner = m.trc.corner;
      settings_.disc = m.trc.disc;
      if (!planeMotion(m)) {
        waiting_.push_back(m);
        blockWithoutMotion();
        return;
      }
      Piece next = compensateWithChange(m);
      corner(next);
      dummy_blocks_ = 0;
      return;
    }
  }
}

void RadiusCompensation::joinAt(Piece& cur, Piece& next, Vec2 x) {
  cur.compensated.p1 = x;
  next.compensated.p0 = x;
  emitPiece(cur);
  emitWaiting(x);
  pending_ = next;
}

void RadiusCompensation::corner(Piece& next) {
  Piece& cur = *pending_;
  const Vec2 a = cur.compensated.p1, b = next.compensated.p0;
  const Vec2 p = cur.programmed.p1;  // the corner point
  if (geom::length(a - b) < kEps) {  // tangent transition: nothing inserted
    joinAt(cur, next, a);
    return;
  }
  const Vec2 t1 = cur.programmed.endTangent(), t2 = next.programmed.startTangent();
  const double c = geom::cross(t1, t2), d = geom::dot(t1, t2);
  const double s = side();
  const bool reversal = std::fabs(c) < 1e-12 && d < 0;
  const bool inside = !reversal && s * c > 0;
  if (inside) {
    // Inside corner: both elements end at the intersection of their equidistants; of several,
    // the one nearest the start of the next block (W1 2.4.3).
    std::optional<geom::Crossing> best;
    for (const auto& x : geom::intersect(cornerEquidistant(cur, true), cornerEquidistant(next, false)))
      if (x.u1 > -kEps && x.u1 < 1 + kEps && x.u2 > -kEps && x.u2 < 1 + kEps &&
          (!best || x.u2 < best->u2))
        best = x;
    if (!best)
      notModelled("an inside corner whose equidistants do not meet within the two blocks (the "
                  "look-ahead over MD20240 blocks)");
    joinAt(cur, next, best->p);
    return;
  }
  // Outside corner (details Q3/Q4): G450 circle unless flatter than MD20230; G451 intersection
  // unless the contour angle reaches MD20210.
  const double angle = reversal ? 180.0 : std::acos(std::fmax(-1.0, std::fmin(1.0, d))) * kDeg;
  bool circle = settings_.corner == CornerMode::TransitionCircle
                    ? !(angle < settings_.curve_insert_limit)
                    : angle >= settings_.corner_limit;
  if (circle && settings_.corner == CornerMode::TransitionCircle && settings_.disc > 0)
    notModelled(fmt::format("DISC={} (transition curve other than a circle)", settings_.disc));
  if (!circle) {
    std::optional<geom::Crossing> best;
    for (const auto& x : geom::intersect(cornerEquidistant(cur, true), cornerEquidistant(next, false)))
      if (x.u1 > 1 - kEps && x.u2 < kEps &&
          (!best || geom::length(x.p - p) < geom::length(best->p - p)))
        best = x;
    if (best) {
      joinAt(cur, next, best->p);
      return;
    }
  }
  // Transition circle of the tool radius about the corner point; it belongs to the next block.
  emitPiece(cur);
  emitWaiting(a);
  Element arc;
  arc.arc = true;
  arc.p0 = a;
  arc.p1 = b;
  arc.c = p;
  arc.ccw = s < 0;  // around the outside: clockwise for G41, counter-clockwise for G42
  MotionBlock tb = toBlock(next.block, arc);
  PlaneAxes pa = planeAxes(tb.plane);
  tb.start[pa.applicate] = tb.end[pa.applicate] = next.block.start[pa.applicate];
  tb.centre[pa.applicate] = tb.start[pa.applicate];
  tb.turns = 0;
  emit(tb);
  pending_ = next;
}

// KONT with the start point behind the contour (details Q2): a straight line tangent to the
// circle of radius R about the contour start point, then (G450) an arc on that circle to the
// normal point of the first element, or (G451, below MD20210) the line extended to the first
// equidistant. Both belong to the selection block.
void RadiusCompensation::kontApproach(Piece& first) {
  const Vec2 p0 = toElement(selection_).p0;
  const Vec2 p1 = first.programmed.p0;
  const double r = std::fabs(settings_.radius), s = side();
  std::optional<Vec2> t = tangentPoint(p0, p1, r, s, true);
  if (!t)
    throw AlarmError(10755,
                     "activation of tool radius compensation via KONT not possible in current start point",
                     selection_.line);  // the selection block is the one to change
  Element line;
  line.p0 = p0;
  line.p1 = *t;
  const Vec2 dir = geom::length(*t - p0) > 0 ? (1.0 / geom::length(*t - p0)) * (*t - p0) : Vec2{1, 0};
  const double angle = std::acos(std::fmax(-1.0, std::fmin(1.0, geom::dot(dir, first.programmed.startTangent())))) * kDeg;
  if (settings_.corner == CornerMode::Intersection && angle < settings_.corner_limit) {
    std::optional<geom::Crossing> best;
    for (const auto& x : geom::intersect(line, first.compensated))
      if (x.u1 > kEps && x.u2 < kEps && (!best || geom::length(x.p - p1) < geom::length(best->p - p1)))
        best = x;
    if (best) {
      line.p1 = best->p;
      first.compensated.p0 = best->p;
      emit(toBlock(selection_, line));
      emitWaiting(best->p);
      pending_ = first;
      dummy_blocks_ = 0;
      state_ = State::On;
      return;
    }
  }
  if (settings_.corner == CornerMode::TransitionCircle && settings_.disc > 0)
    notModelled(fmt::format("DISC={} (transition curve other than a circle)", settings_.disc));
  MotionBlock lb = toBlock(selection_, line);
  PlaneAxes pa = planeAxes(lb.plane);
  lb.end[pa.applicate] = lb.start[pa.applicate];  // the applicate moves with the circle
  emit(lb);
  Element arc;
  arc.arc = true;
  arc.p0 = *t;
  arc.p1 = first.compensated.p0;
  arc.c = p1;
  arc.ccw = s < 0;
  MotionBlock ab = toBlock(selection_, arc);
  ab.start[pa.applicate] = lb.end[pa.applicate];
  ab.centre[pa.applicate] = ab.start[pa.applicate];
  emit(ab);
  emitWaiting(arc.p1);
  pending_ = first;
  dummy_blocks_ = 0;
  state_ = State::On;
}

// KONT retraction with the end point behind the contour (details Q2): from the normal point of
// the last element, an arc about its end point to the tangent point of the line through the
// programmed end point (G450), or the last equidistant extended to that line (G451); then the
// straight line to the programmed end point. Both belong to the G40 block.
void RadiusCompensation::kontRetraction(const MotionBlock& m) {
  Piece last = *pending_;
  const Vec2 pe = last.programmed.p1;
  const Vec2 p2 = toElement(m).p1;
  const double r = std::fabs(settings_.radius), s = side();
  std::optional<Vec2> t = tangentPoint(p2, pe, r, s, false);
  if (!t)
    raise(10756, "deactivation of tool radius compensation via KONT not possible at programmed end point");
  Element line;
  line.p0 = *t;
  line.p1 = p2;
  PlaneAxes pa = planeAxes(m.plane);
  const Vec2 dir = (1.0 / geom::length(p2 - *t)) * (p2 - *t);
  const double angle = std::acos(std::fmax(-1.0, std::fmin(1.0, geom::dot(last.programmed.endTangent(), dir)))) * kDeg;
  if (m.trc.corner == CornerMode::Intersection && angle < settings_.corner_limit) {
    std::optional<geom::Crossing> best;
    for (const auto& x : geom::intersect(last.compensated, line))
      if (x.u1 > 1 - kEps && x.u2 < 1 - kEps && (!best || geom::length(x.p - pe) < geom::length(best->p - pe)))
        best = x;
    if (best) {
      last.compensated.p1 = best->p;
      emitPiece(last);
      emitWaiting(best->p);
      line.p0 = best->p;
      emit(toBlock(m, line));
      pending_.reset();
      state_ = State::Off;
      return;
    }
  }
  if (m.trc.corner == CornerMode::TransitionCircle && m.trc.disc > 0)
    notModelled(fmt::format("DISC={} (transition curve other than a circle)", m.trc.disc));
  emitPiece(last);
  emitWaiting(last.compensated.p1);
  Element arc;
  arc.arc = true;
  arc.p0 = last.compensated.p1;
  arc.p1 = *t;
  arc.c = pe;
  arc.ccw = s < 0;
  MotionBlock ab = toBlock(m, arc);
  ab.start[pa.applicate] = ab.end[pa.applicate] = m.start[pa.applicate];
  ab.centre[pa.applicate] = ab.start[pa.applicate];
  emit(ab);
  emit(toBlock(m, line));
  pending_.reset();
  state_ = State::Off;
}

void RadiusCompensation::finish() {
  if (state_ == State::Selecting) {
    // No contour element follows the selection block: it ends on its own normal.
    Piece only = compensate(selection_);
    Element approach;
    approach.p0 = only.programmed.p0;
    approach.p1 = only.compensated.p1;
    emit(toBlock(selection_, approach));
    emitWaiting(approach.p1);
  } else if (state_ == State::On && pending_) {
    emitPiece(*pending_);
    emitWaiting(pending_->compensated.p1);
  }
  waiting_.clear();
  pending_.reset();
  state_ = State::Off;
}

}  // namespace ncoffset::trc
