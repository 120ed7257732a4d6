// Corners of radius compensation (W1 2.4.3, 2.4.5, spec §5.4, details Q3/Q4): how each new
// element is joined to the previous one. Tangent: nothing inserted; inside corner: the
// intersection of the equidistants; outside corner: the G450 transition circle (or the DISC
// curve) about the corner point, or with G451 the intersection; a change of side: a straight
// line between the two normal points.
#include <cmath>

#include "geom/disc_curve.hpp"
#include "trc/compensation_internal.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
namespace tol = geom::tol;
using geom::Element;
using geom::Vec2;

// One junction: where the two equidistants end and start, the corner point and the tangents
// of the programmed contour there.
struct RadiusCompensation::Corner {
  Vec2 a, b;    // end of the first equidistant, start of the second
  Vec2 p;       // the corner point (the programmed contour)
  Vec2 t1, t2;  // the end tangent of the first element, the start tangent of the second
  double s;     // the side of the second element
  bool reversal;
  Element e1, e2;  // the equidistants at the values the corner uses (Q8)
};

void RadiusCompensation::connect(Piece& cur, Piece& next) {
  if (joinTangent(cur, next)) return;  // tangent transition: nothing inserted
  if (!cur.valid || !next.valid) {
    next.open_before = true;
    return;
  }
  const Vec2 a = cur.compensated.p1, b = next.compensated.p0;
  if (next.restart) {
    restartLine(next, a);
    return;
  }
  const Vec2 t1 = cur.programmed.endTangent(), t2 = next.programmed.startTangent();
  const double c = geom::cross(t1, t2), d = geom::dot(t1, t2);
  const double s = next.side;
  const bool reversal = std::fabs(c) < tol::kParallel && d < 0;
  const bool inside = !reversal && s * c > 0;
  const Corner k{a,
                 b,
                 cur.programmed.p1,
                 t1,
                 t2,
                 s,
                 reversal,
                 cornerEquidistant(cur, true),
                 cornerEquidistant(next, false)};
  if (inside)
    insideCorner(cur, next, k);
  else
    outsideCorner(cur, next, k);
}

void RadiusCompensation::restartLine(Piece& next, Vec2 from) const {
  // A new side: no corner; a straight line from the old normal point to the new one, part of
  // the new block.
  const Vec2 b = next.compensated.p0;
  if (geom::length(from - b) < tol::kPoint) {
    next.compensated.p0 = from;
  } else {
    Element line;
    line.p0 = from;
    line.p1 = b;
    MotionBlock lb = toBlock(next.block, line);
    PlaneAxes pa = planeAxes(lb.plane);
    lb.end[pa.applicate] = lb.start[pa.applicate];
    next.transition.assign(1, lb);
  }
}

void RadiusCompensation::insideCorner(Piece& cur, Piece& next, const Corner& k) const {
  // Both elements end at the intersection of their equidistants; of several, the one nearest
  // the start of the next block (W1 2.4.3). None: the look-ahead decides.
  auto best = geom::nearestCrossing(
      k.e1, k.e2,
      [](const geom::Crossing& x) {
        return tol::onElement(x.u1, x.len1) && tol::onElement(x.u2, x.len2);
      },
      [](const geom::Crossing& x) { return x.u2; });
  if (best) {
    cur.compensated.p1 = next.compensated.p0 = best->p;
  } else if (geom::length(k.a - k.b) < tol::kInsert) {
    // Tangent within half an increment, where the crossing of two nearly parallel curves is
    // lost in its own error (a spiral's radius moves it far along them): joined at the first
    // one's end; the second starts at most (half an increment)^2 / 2R nearer than R.
    next.compensated.p0 = k.a;
  } else {
    next.open_before = true;
  }
}

void RadiusCompensation::outsideCorner(Piece& cur, Piece& next, const Corner& k) const {
  // An outside corner by its tangents whose curved equidistants still cross within both
  // elements (an arc bending back over its neighbour): the tool cannot pass the crossing
  // without cutting into the other element, so it is treated like an inside corner [D].
  if (cur.programmed.arc || next.programmed.arc) {
    auto best = geom::nearestCrossing(
        k.e1, k.e2,
        [](const geom::Crossing& x) {
          return tol::insideElement(x.u1, x.len1) && tol::insideElement(x.u2, x.len2);
        },
        [](const geom::Crossing& x) { return x.u2; });
    if (best) {
      cur.compensated.p1 = next.compensated.p0 = best->p;
      return;
    }
  }
  // Details Q3/Q4: G450 circle unless flatter than MD20230; G451 intersection unless the
  // contour angle reaches MD20210.
  const double angle = k.reversal ? 180.0 : geom::angleDeg(k.t1, k.t2);
  const core::TrcSettings& t = next.block.trc;
  bool circle = t.corner == CornerMode::TransitionCircle ? !(angle < t.curve_insert_limit)
                                                         : angle >= t.corner_limit;
  // A circle shorter than half an increment is no motion on the control: intersect instead.
  const bool microscopic = geom::length(k.a - k.b) < tol::kInsert;
  if (!circle || microscopic) {
    // The intersection of the extended equidistants nearest the corner point.
    auto best = geom::nearestCrossing(
        k.e1, k.e2,
        [](const geom::Crossing& x) {
          return tol::pastEnd(x.u1, x.len1) && tol::beforeStart(x.u2, x.len2);
        },
        [&k](const geom::Crossing& x) { return geom::length(x.p - k.p); });
    if (best) {
      cur.compensated.p1 = next.compensated.p0 = best->p;
      return;
    }
    if (microscopic) {  // the two equidistants end within half an increment: joined there
      next.compensated.p0 = k.a;
      return;
    }
  }
  // Transition circle of the tool radius about the corner point (or the DISC curve); it
  // belongs to the next block.
  const double app = next.block.start[planeAxes(next.block.plane).applicate];
  next.transition.clear();
  transition(next.transition, next.block, k.a, k.t1, k.b, k.t2, k.p, k.s,
             t.corner == CornerMode::TransitionCircle ? t.disc : 0, app, app);
}

void RadiusCompensation::transition(std::vector<MotionBlock>& out, const MotionBlock& like, Vec2 a,
                                    Vec2 ta, Vec2 b, Vec2 tb, Vec2 p, double s, double disc,
                                    double app0, double app1) const {
  PlaneAxes pa = planeAxes(like.plane);
  if (disc > 0) {
    if (auto curve = geom::discCurve(a, ta, b, tb, p, disc)) {
      // DISC: the curve as straight chords within tol::kChord (the applicate, if it moves, is
      // spread over them).
      const std::vector<Vec2> pts = geom::chords(*curve, tol::kChord);
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

}  // namespace ncoffset::trc
