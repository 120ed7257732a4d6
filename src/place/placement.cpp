#include "place/placement.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/inline_step.hpp"

namespace ncoffset::place {

using core::Geometry;
using core::MotionBlock;

// (Inlined into its callers, one a segment: the Segment is built in place, 10 % of the
// placement's instructions, docs/performance.md §26. Its fields are computed first and the
// Segment initialised from them at once, one object returned on every path: `Segment s;` zeroed
// all of it before the fields were written, §28. A template: motion() hands the block itself
// as its geometry, no copy of its points, §37.)
template <typename G>
NCOFFSET_INLINE_STEP Segment Placement::toSegment(const MotionBlock& m, const G& g) const {
  Vec3 normal;
  normal[g.applicate] = 1;
  Vec3 start, end, centre;
  Motion motion = g.motion;
  if (coords_ == CoordSystem::WCS) {
    start = g.start;
    end = g.end;
    centre = g.centre;
  } else if (m.frame.isIdentity()) {  // no frame: only the tool offset
    start = g.start + m.tool_offset;
    end = g.end + m.tool_offset;
    if (g.motion == Motion::G2 || g.motion == Motion::G3) centre = g.centre + m.tool_offset;
  } else [[unlikely]] {
    framedPoints(m, {g.motion, g.tip_at, g.start, g.end, g.centre, g.applicate, g.turns}, start,
                 end, centre, normal, motion);
  }
  Segment s{m.line, m.file,  motion, start,       end,        centre,
            normal, g.turns, m.feed, m.feed_unit, m.has_feed, m.lead_change};
  if (g.tip_at != core::kTipNone) addTip(s, m, g.tip_at, g.motion);  // turning tools with TRC
  return s;
}

// The unit vector of axis `applicate`: G17's Z as constants, without the vector built in memory
// to set one of its coordinates (docs/performance.md §40).
namespace {
NCOFFSET_INLINE_STEP Vec3 unitNormal(int applicate) {
  if (applicate == 2) [[likely]]
    return {0, 0, 1};
  Vec3 normal;
  normal[applicate] = 1;
  return normal;
}
}  // namespace

// toSegment of a block itself in MCS without a frame or P - S: its points with the tool offset,
// each written once (docs/performance.md §37).
NCOFFSET_INLINE_STEP Segment Placement::blockSegment(const MotionBlock& m) const {
  const Vec3& o = m.tool_offset;
  const Vec3 normal = unitNormal(m.applicate);
  const bool arc = m.motion == Motion::G2 || m.motion == Motion::G3;
  return Segment{m.line, m.file,  m.motion, m.start + o, m.end + o,  arc ? m.centre + o : Vec3{},
                 normal, m.turns, m.feed,   m.feed_unit, m.has_feed, m.lead_change};
}

// planeGeometry (core/stage.hpp) for G17 and toSegment's MCS case without a frame in one: the
// plane's points from the element, the applicate from the block, the tool offset added.
NCOFFSET_INLINE_STEP Segment Placement::planeSegment(const MotionBlock& like,
                                                     const geom::Element& e) const {
  const Vec3& o = like.tool_offset;
  const Vec3 start{e.p0.a + o.x, e.p0.o + o.y, like.start.z + o.z};
  const Vec3 end{e.p1.a + o.x, e.p1.o + o.y, like.end.z + o.z};
  if (e.arc) {
    return Segment{like.line,      like.file,     e.ccw ? Motion::G3 : Motion::G2,
                   start,          end,           {e.c.a + o.x, e.c.o + o.y, start.z},
                   {0, 0, 1},      e.turns,       like.feed,
                   like.feed_unit, like.has_feed, like.lead_change};
  }
  const Vec3 normal = unitNormal(like.applicate);
  const Motion line =
      like.motion == Motion::G2 || like.motion == Motion::G3 ? Motion::G1 : like.motion;
  return Segment{like.line, like.file,  line,      start,          end,           Vec3{},
                 normal,    like.turns, like.feed, like.feed_unit, like.has_feed, like.lead_change};
}

void Placement::framedPoints(const MotionBlock& m, const Geometry& g, Vec3& start, Vec3& end,
                             Vec3& centre, Vec3& normal, Motion& motion) const {
  start = m.frame.map().apply(g.start) + m.tool_offset;
  end = m.frame.map().apply(g.end) + m.tool_offset;
  if (g.motion != Motion::G2 && g.motion != Motion::G3) return;
  centre = m.frame.map().apply(g.centre) + m.tool_offset;
  // The arc turns about frame * normal; a mirrored frame (det < 0) reverses its sense.
  const Vec3 n = m.frame.linear() * normal;
  const double len = norm(n);
  if (len > 0) normal = (1.0 / len) * n;
  bool flip = m.frame.linear().determinant() < 0;
  // Report the sense as seen from the positive end of the dominant machine axis.
  int dom = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(normal[i]) > std::fabs(normal[dom])) dom = i;
  if (normal[dom] < 0) {
    normal = -1.0 * normal;
    flip = !flip;
  }
  if (flip) motion = g.motion == Motion::G2 ? Motion::G3 : Motion::G2;
}

void Placement::addTip(Segment& s, const MotionBlock& m, std::uint8_t tip_at, Motion motion) const {
  // The lengths refer to the tool tip P; radius compensation guided the cutting edge centre S,
  // so the points it made get P - S (docs/cutting-edge-positions.md). The vector is fixed in
  // the BCS; in WCS coordinates it is the frame's inverse image.
  Vec3 tip = m.tip;
  if (coords_ == CoordSystem::WCS && !m.frame.isIdentity()) tip = m.frame.linear().inverse() * tip;
  if (tip_at & core::kTipStart) s.start = s.start + tip;
  if (tip_at & core::kTipEnd) {
    s.end = s.end + tip;
    if (motion == Motion::G2 || motion == Motion::G3) s.centre = s.centre + tip;
  }
}

namespace {

// A compensated position beyond the machine's number range (a huge OFFN or tool radius next to
// a contour near the limit): the value range alarm of the block it belongs to, as for
// programmed positions (interp/motion_builder.cpp), never a silently huge coordinate.
bool inRange(const Vec3& p) {  // false for NaN too; one branch for the three axes
  return (std::fabs(p.x) <= 1e9) & (std::fabs(p.y) <= 1e9) & (std::fabs(p.z) <= 1e9);
}

[[noreturn, gnu::cold, gnu::noinline]] void outOfRange(const Segment& s, int line) {
  const bool arc = s.motion == Motion::G2 || s.motion == Motion::G3;
  for (const Vec3* p : {&s.end, &s.centre})
    for (int i = 0; i < 3; ++i)
      if (!(std::fabs((*p)[i]) <= 1e9) && (p == &s.end || arc))
        throw AlarmError(AlarmNumber::ValueRange,
                         fmt::format("value range exceeded: compensated position {} of axis {} "
                                     "beyond 1e9 mm",
                                     (*p)[i], "XYZ"[i]),
                         line);
  throw AlarmError(AlarmNumber::ValueRange, "value range exceeded", line);
}

NCOFFSET_INLINE_STEP void checkRange(const Segment& s, int line) {
  const bool arc = s.motion == Motion::G2 || s.motion == Motion::G3;
  if (inRange(s.end) && (!arc || inRange(s.centre))) return;
  outOfRange(s, line);
}

// inRange of the end and, for an arc, the centre, a row's way: first whether the sum of their
// squares is below 1e18, which holds only if every coordinate is within 1e9 (a coordinate beyond
// it, infinite or NaN has a square, rounded, of at least 1e18 or NaN, and adding squares rounds
// upwards from it or stays NaN); a few multiplications instead of the tests of each coordinate
// (docs/performance.md §49). Else the tests of each, as inRange.
NCOFFSET_INLINE_STEP bool rowInRange(const Vec3& end, const Vec3& centre, bool arc) {
  double squares = end.x * end.x + end.y * end.y + end.z * end.z;
  if (arc) squares += centre.x * centre.x + centre.y * centre.y + centre.z * centre.z;
  if (squares < 1e18) [[likely]]
    return true;
  return inRange(end) && (!arc || inRange(centre));
}

// outOfRange of a row (Placement::placeRow): its segment built for the alarm's text. (The
// coordinates in registers: by reference, placeRow kept its points on its stack, §51.)
[[noreturn, gnu::cold, gnu::noinline]] void rowOutOfRange(Motion motion, double x, double y,
                                                          double z, double cx, double cy, double cz,
                                                          int line) {
  Segment s;
  s.motion = motion;
  s.end = {x, y, z};
  s.centre = {cx, cy, cz};
  outOfRange(s, line);
}

}  // namespace

void Placement::rejoin(Segment& s, const MotionBlock& m, Joint& j) const {
  // The frame or the tool offset changed (or this is the first segment): the previous end as a
  // machine position (MCS = frame(WCS) + offset, Segment points of turning tools included), and
  // that point expressed with this segment's frame and offset. The change of the carrier position
  // (the length take-up) is part of this motion (W1 2.1: the offset is traversed with the next
  // programmed motion of the axis), never a jump.
  if (j.placed) {
    const bool wcs = coords_ == CoordSystem::WCS;
    const Vec3 mcs = wcs ? j.frame.apply(j.at) + j.offset : j.at;
    if (!wcs)
      s.start = mcs;
    else if (m.frame.isIdentity())
      s.start = mcs - m.tool_offset;
    else
      s.start = m.frame.map().inverse().apply(mcs - m.tool_offset);
  }
  j.placed = true;
  j.offset = m.tool_offset;
  j.frame = m.frame;
}

NCOFFSET_INLINE_STEP void Placement::place(Segment& s, const MotionBlock& m, bool check) {
  join(s, m, path_);
  if (check) checkRange(s, m.line);
  seq_ = m.seq;
  emit(s);
}

// place() for a row: the same join (none needed: toRows), range check and sequence number.
NCOFFSET_INLINE_STEP void Placement::placeRow(const MotionBlock& m, Motion motion, const Vec3& end,
                                              const Vec3& centre, bool check) {
  const int line = m.line;  // (read before the stores, which may alias the block)
  const long long seq = m.seq;
  const bool has_feed = m.has_feed;
  const double feed = m.feed;
  path_.at = end;
  const bool arc = motion == Motion::G2 || motion == Motion::G3;
  if (check && !rowInRange(end, centre, arc)) [[unlikely]]
    rowOutOfRange(motion, end.x, end.y, end.z, centre.x, centre.y, centre.z, line);
  seq_ = seq;
  row_->row(line, motion, has_feed, end.x, end.y, end.z, centre.x, centre.y, centre.z, feed);
}

// The usual motion (MCS, no frame, no P - S) to a RowSink (toRows) as a row, else as a segment.
// (Both inline: the segment's way out of line cost a plain sink 23 instructions a block in
// BM_PlainG1, §49; element() keeps its segment out of line.)
core::Feedback Placement::motion(const MotionBlock& m) {
  // Blocks that radius compensation made or moved (corner circles, approach and retraction
  // lines) carry its settings; programmed positions were checked by the interpreter.
  const bool check = m.trc.mode != core::TrcMode::Off;
  if (!usualMotion(m)) [[unlikely]] {
    generalMotion(m, check);
    return {};
  }
  if (toRows(m)) [[likely]] {  // blockSegment's end and centre
    const Vec3& o = m.tool_offset;
    const bool arc = m.motion == Motion::G2 || m.motion == Motion::G3;
    placeRow(m, m.motion, m.end + o, arc ? m.centre + o : Vec3{}, check);
    return {};
  }
  Segment s = blockSegment(m);
  place(s, m, check);
  return {};
}

void Placement::generalMotion(const MotionBlock& m, bool check) {
  Segment s = toSegment(m, m);
  place(s, m, check);
}

// planeSegment's end, centre and motion, as a row.
NCOFFSET_INLINE_STEP void Placement::rowElement(const MotionBlock& like, const geom::Element& e) {
  const Vec3& o = like.tool_offset;
  const Vec3 end{e.p1.a + o.x, e.p1.o + o.y, like.end.z + o.z};
  if (e.arc) {
    const Vec3 centre{e.c.a + o.x, e.c.o + o.y, like.start.z + o.z};
    return placeRow(like, e.ccw ? Motion::G3 : Motion::G2, end, centre, true);
  }
  const Motion line =
      like.motion == Motion::G2 || like.motion == Motion::G3 ? Motion::G1 : like.motion;
  placeRow(like, line, end, Vec3{}, true);
}

// As motion(): the usual element to a RowSink inline, every other one out of line.
void Placement::element(const MotionBlock& like, const geom::Element& e, std::uint8_t tip_at) {
  // (toRows implies MCS, usualElement's coords_.)
  const bool row = toRows(like) && like.plane == Plane::G17 && like.frame.isIdentity() &&
                   tip_at == core::kTipNone;
  if (!row) [[unlikely]]
    return segmentElement(like, e, tip_at);
  rowElement(like, e);
}

void Placement::segmentElement(const MotionBlock& like, const geom::Element& e,
                               std::uint8_t tip_at) {
  if (!usualElement(like, tip_at)) [[unlikely]]
    return generalElement(like, e, tip_at);
  Segment s = planeSegment(like, e);
  place(s, like, true);
}

void Placement::generalElement(const MotionBlock& like, const geom::Element& e,
                               std::uint8_t tip_at) {
  // The element as a geometry of the block (core::planeGeometry), as Stage::element has it.
  Segment s = toSegment(like, core::planeGeometry(like, e, tip_at));
  place(s, like, true);
}

void Placement::warning(const MotionBlock& m, int number, const std::string& text) {
  static const std::string kUnknown = "?";
  sink_.warning({file_name_ ? file_name_(m.file) : kUnknown, m.line}, number, text);
}

void Placement::programmedSegment(const MotionBlock& m) {
  Segment s = toSegment(m, m);
  join(s, m, programmed_);
  sink_.programmed(s);
}

}  // namespace ncoffset::place
