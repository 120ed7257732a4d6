// Approach and retraction of radius compensation (spec §5.2/§5.3, W1 2.4.10, details
// Q1/Q2/Q7): NORM runs straight to / from the normal point of the first / last element, KONT
// with the start / end point behind the contour goes around the contour point, and at the
// retraction G461/G462 extend the last element to find an intersection with an earlier one
// (their extension of the approach line is part of bottleneck detection, bottleneck.cpp).
#include <cmath>

#include "trc/compensation_internal.hpp"
#include "trc/radius_compensation.hpp"
#include "trc/usual_element.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
using core::TrcStrategy;
namespace tol = geom::tol;
using geom::Element;
using geom::Vec2;

namespace {
// The retraction's fraction tests (filteredCrossings: asked before an arc's angles).
bool onBeforeEnd(double u, double len) {
  return tol::onElement(u, len) && tol::beforeEnd(u, len);
}
bool afterStartOn(double u, double len) {
  return tol::afterStart(u, len) && tol::onElement(u, len);
}
}  // namespace

void RadiusCompensation::approachLine(Piece& approach, Piece& first) {
  // Every field is set: `approach` is a reused slot of the window (its vectors keep their memory);
  // its block is the selection block already (startSelection).
  approach.r0 = approach.r1 = 0;
  approach.index = 0;
  approach.valid = true;
  approach.open_before = approach.restart = approach.emitted = false;
  approach.approach = true;
  approach.strategy = approach.block.trc.strategy;
  approach.transition.clear();
  approach.waiting.clear();
  approach.side = first.side;
  // The first element's start tangent: asked only by G462 (bottleneck.cpp, approachExtension)
  // and KONT, so not computed for every approach (docs/performance.md §36).
  if (approach.strategy == TrcStrategy::G462)
    approach.first_tangent = first.programmed.startTangent();
  approach.programmed = toElement(approach.block);
  approach.compensated = Element{};
  approach.compensated.p0 = approach.programmed.p0;
  approach.compensated.p1 = first.compensated.p0;
  const Vec2 p1 = first.programmed.p0;
  if (approach.block.trc.approach == Approach::Kont &&
      geom::dot(approach.programmed.p0 - p1,
                first.side * geom::leftNormal(first.programmed.startTangent())) < -tol::kPoint) {
    approach.strategy =
        TrcStrategy::G460;  // the point behind the contour: G461/G462 have no effect (Q7)
    kontApproach(approach, first);
  } else if (geom::length(approach.compensated.p1 - approach.compensated.p0) > tol::kPoint) {
    // NORM: one straight line to the normal point of the first element (details Q1); if it
    // cuts the first equidistant earlier, the intersection nearest the start of the line
    // replaces that point (G460).
    // (The two fraction tests first: the arc's angles only for a crossing inside the line. A
    // line running into the first arc's circle at its start has none: not searched, §42.)
    if (!general_paths_ && geom::joinedLineArcMiss(approach.compensated, first.compensated, true))
      return keepRaw(approach);
    auto best = geom::nearestCrossing(approach.compensated, first.compensated, tol::insideElement,
                                      tol::onElement, [](const geom::Crossing& x) { return x.u1; });
    if (best) approach.compensated.p1 = first.compensated.p0 = best->p;
  }
  keepRaw(approach);
}

// KONT with the start point behind the contour (details Q2): a straight line tangent to the
// circle of radius R about the contour start point, then (G450) an arc on that circle to the
// normal point of the first element, or (G451, below MD20210) the line extended to the first
// equidistant. Both belong to the selection block.
void RadiusCompensation::kontApproach(Piece& approach, Piece& first) {
  const Vec2 p0 = approach.programmed.p0;
  const Vec2 p1 = first.programmed.p0;
  const double r = first.r0, s = first.side;  // the value at the contour's start
  std::optional<Vec2> t = geom::tangentPoint(p0, p1, r, s, true);
  if (!t)
    throw AlarmError(
        AlarmNumber::TrcKontSelection,
        "activation of tool radius compensation via KONT not possible in current start point",
        approach.block.line);  // the selection block is the one to change
  Element line;
  line.p0 = p0;
  line.p1 = *t;
  const Vec2 dir = geom::unit(*t - p0);
  const double angle = geom::angleDeg(dir, first.programmed.startTangent());
  if (settings_.corner == CornerMode::Intersection && angle < settings_.corner_limit) {
    // The line extended meets the first equidistant extended backwards: nearest the contour
    // start point.
    auto best = geom::nearestCrossing(
        line, first.compensated,
        [](const geom::Crossing& x) {
          return tol::afterStart(x.u1, x.len1) && tol::beforeStart(x.u2, x.len2);
        },
        [&p1](const geom::Crossing& x) { return geom::length(x.p - p1); });
    if (best) {
      approach.compensated.p1 = best->p;
      first.compensated.p0 = best->p;
      return;
    }
  }
  MotionBlock& selection = approach.block;  // (the selection block, §36)
  PlaneAxes pa = planeAxes(selection.plane);
  approach.compensated.p1 = *t;
  first.transition.clear();
  // The circle runs from the height where the line ends to the selection block's end (before
  // the line's end is moved: it is that block).
  transition(first.transition, selection, *t, dir, first.compensated.p0,
             first.programmed.startTangent(), p1, s,
             settings_.corner == CornerMode::TransitionCircle ? settings_.disc : 0,
             selection.start[pa.applicate], selection.end[pa.applicate]);
  selection.end[pa.applicate] = selection.start[pa.applicate];  // moves with the circle
}

void RadiusCompensation::retract(const MotionBlock& m) {
  // Deselection with G40 (NORM): the last element ends on its normal at its end point, then a
  // straight line to the programmed end point (details Q1).
  if (m.motion != Motion::G0 && m.motion != Motion::G1)
    raise(AlarmNumber::TrcDeselectionNotLinear,
          "deactivation of tool radius compensation only possible in linear block");
  if (m.trc.approach == Approach::KontC || m.trc.approach == Approach::KontT)
    detail::notModelled(m.trc.approach == Approach::KontC ? "KONTC" : "KONTT");
  Piece& last = window_.back();
  if (!last.valid) detail::collision(last.block.line, settings_.check_blocks);
  Element retract = toElement(m);
  // (The normal at the end only for KONT.)
  if (m.trc.approach == Approach::Kont && !last.emitted &&
      geom::dot(retract.p1 - last.programmed.p1,
                last.side * geom::leftNormal(last.programmed.endTangent())) < -tol::kPoint) {
    kontRetraction(m);
    return;
  }
  if (last.open_before && !last.emitted &&
      (m.trc.strategy == TrcStrategy::G461 || m.trc.strategy == TrcStrategy::G462))
    retractionExtension(m);
  // G460: if the retraction line cuts the last equidistant before its end, that intersection
  // (the one nearest the end of the equidistant) replaces the normal point (details Q1).
  Piece& fin = window_.back();
  retract.p0 = fin.compensated.p1;
  // (A line running out of the last arc's circle at its end has no such crossing, §42.)
  if (!fin.approach && !fin.emitted && geom::length(retract.p1 - retract.p0) > tol::kPoint &&
      (general_paths_ || !geom::joinedLineArcMiss(retract, fin.compensated, false))) {
    auto best = geom::nearestCrossing(fin.compensated, retract, onBeforeEnd, afterStartOn,
                                      [](const geom::Crossing& x) { return -x.u1; });
    if (best) fin.compensated.p1 = best->p;
    retract.p0 = fin.compensated.p1;
  }
  flushAll();
  lineToEnd(line_, m, retract);
  detail::keepTipAt(line_, core::kTipStart);
  emit(line_);
  state_ = State::Off;
}

void RadiusCompensation::retractionExtension(const MotionBlock& m) {
  // G461/G462: the last element, which meets no earlier one, is extended by a circle about
  // its programmed end point (radius R) or along its end tangent; the intersection with an
  // earlier element ends that element and starts the retraction (W1 2.4.10, details Q7).
  const Piece& last = window_.back();
  Element ext;
  if (m.trc.strategy == TrcStrategy::G461) {
    ext = geom::fullCircle(last.programmed.p1, std::fabs(last.r1));
  } else {
    ext.p0 = last.raw_end;
    ext.p1 = last.raw_end + last.programmed.endTangent();
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
          return tol::afterStart(x.u1, x.len1) && tol::onElement(x.u1, x.len1) &&
                 (ext.arc || x.u2 * x.len2 > -tol::kPoint);
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
    raise(AlarmNumber::TrcKontDeselection,
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
        [](const geom::Crossing& x) {
          return tol::pastEnd(x.u1, x.len1) && tol::beforeEnd(x.u2, x.len2);
        },
        [&pe](const geom::Crossing& x) { return geom::length(x.p - pe); });
    if (best) {
      last.compensated.p1 = best->p;
      line.p0 = best->p;
      flushAll();
      MotionBlock block = toBlock(m, line);
      detail::keepTipAt(block, core::kTipStart);
      emit(block);
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
  MotionBlock block = toBlock(m, line);
  detail::keepTipAt(block, core::kTipStart);
  emit(block);
  state_ = State::Off;
}

}  // namespace ncoffset::trc
