// Placement stage (src/place/placement.hpp): WCS motions become MCS segments through the
// block's frame; a mirroring frame reverses the arc sense; `--coords wcs` leaves points alone.
#include "place/placement.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "ncoffset/frame.hpp"

namespace ncoffset::place {
namespace {

using core::MotionBlock;

class Collect final : public PathSink {
 public:
  std::vector<Segment> segments;
  void segment(const Segment& s) override { segments.push_back(s); }
  void finish(const Alarm*) override {}
};

void expectVec(Vec3 v, double x, double y, double z) {
  EXPECT_NEAR(v.x, x, 1e-12);
  EXPECT_NEAR(v.y, y, 1e-12);
  EXPECT_NEAR(v.z, z, 1e-12);
}

// A quarter circle in G17, clockwise from (10,0) to (0,-10) about the origin.
MotionBlock quarterArc(Motion m = Motion::G2) {
  MotionBlock b;
  b.motion = m;
  b.start = {10, 0, 0};
  b.end = {0, -10, 0};
  b.centre = {0, 0, 0};
  b.applicate = 2;
  b.feed = 200;
  b.has_feed = true;
  b.line = 12;
  b.file = 1;
  return b;
}

// The frame as a block carries it (a frame state of its own: applied, not taken for none).
core::BlockFrame affineOf(const Frame& f) {
  return core::BlockFrame(f.affine(), 1, false);
}

Segment place(const MotionBlock& b, CoordSystem cs) {
  Collect sink;
  Placement p(sink, cs);
  p.motion(b);
  EXPECT_EQ(sink.segments.size(), 1u);
  return sink.segments.empty() ? Segment{} : sink.segments[0];
}

TEST(Placement, IdentityFrameCopiesTheBlock) {
  Segment s = place(quarterArc(), CoordSystem::MCS);
  EXPECT_EQ(s.motion, Motion::G2);
  EXPECT_EQ(s.line, 12);
  EXPECT_EQ(s.file, 1);
  EXPECT_EQ(s.feed, 200);
  EXPECT_TRUE(s.has_feed);
  expectVec(s.start, 10, 0, 0);
  expectVec(s.end, 0, -10, 0);
  expectVec(s.centre, 0, 0, 0);
  expectVec(s.normal, 0, 0, 1);
}

TEST(Placement, TranslationAndToolOffset) {
  MotionBlock b = quarterArc();
  Frame f;
  f.coarse = {100, 50, 0};
  b.frame = affineOf(f);
  b.tool_offset = {0, 0, 30};
  Segment s = place(b, CoordSystem::MCS);
  expectVec(s.start, 110, 50, 30);
  expectVec(s.end, 100, 40, 30);
  expectVec(s.centre, 100, 50, 30);
  EXPECT_EQ(s.motion, Motion::G2);
}

TEST(Placement, MirrorOfOnePlaneAxisSwapsG2AndG3) {
  Frame f;
  f.mirror = {true, false, false};
  for (Motion m : {Motion::G2, Motion::G3}) {
    MotionBlock b = quarterArc(m);
    b.frame = affineOf(f);
    Segment s = place(b, CoordSystem::MCS);
    EXPECT_EQ(s.motion, m == Motion::G2 ? Motion::G3 : Motion::G2);
    expectVec(s.start, -10, 0, 0);
    expectVec(s.end, 0, -10, 0);
    expectVec(s.centre, 0, 0, 0);
    expectVec(s.normal, 0, 0, 1);
  }
  f.mirror = {false, true, false};
  MotionBlock b = quarterArc();
  b.frame = affineOf(f);
  EXPECT_EQ(place(b, CoordSystem::MCS).motion, Motion::G3);
}

TEST(Placement, MirrorOfTheApplicateKeepsTheSense) {
  // Mirroring Z does not change an arc in the X/Y plane seen from +Z.
  Frame f;
  f.mirror = {false, false, true};
  MotionBlock b = quarterArc();
  b.start.z = b.end.z = b.centre.z = 5;
  b.frame = affineOf(f);
  Segment s = place(b, CoordSystem::MCS);
  EXPECT_EQ(s.motion, Motion::G2);
  expectVec(s.end, 0, -10, -5);
  expectVec(s.normal, 0, 0, 1);
}

TEST(Placement, MirrorOfTwoAxesKeepsTheSense) {
  Frame f;
  f.mirror = {true, true, false};
  MotionBlock b = quarterArc();
  b.frame = affineOf(f);
  Segment s = place(b, CoordSystem::MCS);
  EXPECT_EQ(s.motion, Motion::G2);
  expectVec(s.end, 0, 10, 0);
}

TEST(Placement, RotationKeepsTheSenseAndTurnsTheNormal) {
  Frame f;
  f.rotation = {0, 0, 90};
  MotionBlock b = quarterArc();
  b.frame = affineOf(f);
  Segment s = place(b, CoordSystem::MCS);
  EXPECT_EQ(s.motion, Motion::G2);
  expectVec(s.start, 0, 10, 0);
  expectVec(s.end, 10, 0, 0);

  // G18 arc (about Y) tipped by ROT X-90 turns about -Z: seen from +Z it is reversed.
  MotionBlock g18;
  g18.motion = Motion::G2;
  g18.start = {10, 0, 0};
  g18.end = {0, 0, 10};
  g18.centre = {0, 0, 0};
  g18.applicate = 1;
  Frame tip;
  tip.rotation = {-90, 0, 0};
  g18.frame = affineOf(tip);
  Segment t = place(g18, CoordSystem::MCS);
  expectVec(t.normal, 0, 0, 1);
  EXPECT_EQ(t.motion, Motion::G3);
  expectVec(t.end, 0, 10, 0);

  tip.rotation = {90, 0, 0};  // about +Z: same sense
  g18.frame = affineOf(tip);
  Segment u = place(g18, CoordSystem::MCS);
  expectVec(u.normal, 0, 0, 1);
  EXPECT_EQ(u.motion, Motion::G2);
}

TEST(Placement, LinesAreNeverSwapped) {
  Frame f;
  f.mirror = {true, false, false};
  MotionBlock b;
  b.motion = Motion::G1;
  b.start = {0, 0, 0};
  b.end = {5, 5, 0};
  b.frame = affineOf(f);
  Segment s = place(b, CoordSystem::MCS);
  EXPECT_EQ(s.motion, Motion::G1);
  expectVec(s.end, -5, 5, 0);
  b.motion = Motion::G0;
  EXPECT_EQ(place(b, CoordSystem::MCS).motion, Motion::G0);
}

TEST(Placement, WcsModeLeavesPointsAndSense) {
  Frame f;
  f.coarse = {100, 0, 0};
  f.mirror = {true, false, false};
  MotionBlock b = quarterArc();
  b.frame = affineOf(f);
  b.tool_offset = {0, 0, 30};
  Segment s = place(b, CoordSystem::WCS);
  EXPECT_EQ(s.motion, Motion::G2);
  expectVec(s.start, 10, 0, 0);
  expectVec(s.end, 0, -10, 0);
  expectVec(s.centre, 0, 0, 0);
  expectVec(s.normal, 0, 0, 1);
  EXPECT_EQ(s.line, 12);
  EXPECT_EQ(s.feed, 200);
}

TEST(Placement, TurnsArePassedOn) {
  MotionBlock b = quarterArc(Motion::G3);
  b.turns = 3;
  EXPECT_EQ(place(b, CoordSystem::MCS).turns, 3);
  EXPECT_EQ(place(b, CoordSystem::WCS).turns, 3);
}

// Two lines: G0 Z50 without a tool, then (T1 D1, L1 = 100 along Z) G0 X10 Z5 under ROT Z90
// (X of the WCS along Y of the BCS) and TRANS X100. By hand: the first ends at MCS (0, 0, 50);
// the second is placed with the frame and the offset (0, 0, 100): it ends at
// ROT(10, 0, 5) + (100, 0, 0) + (0, 0, 100) = (100, 10, 105) and starts at (0, 0, 50), where
// the carrier stands (the take-up is part of this motion, docs/tool-offsets.md section 5). In
// WCS it starts at that point in the new frame and tool: ROT^-1((0, 0, 50) - (100, 0, 0) -
// (0, 0, 100)) = ROT^-1(-100, 0, -50) = (0, 100, -50).
TEST(Placement, ASegmentAfterAFrameAndToolChangeStartsWhereThePreviousEnded) {
  MotionBlock first;
  first.motion = Motion::G0;
  first.end = {0, 0, 50};
  MotionBlock second;
  second.motion = Motion::G0;
  second.start = {0, 0, 50};  // the interpreter's WCS start: no use after the change
  second.end = {10, 0, 5};
  Frame f;
  f.coarse = {100, 0, 0};
  f.rotation = {0, 0, 90};
  second.frame = affineOf(f);
  second.tool_offset = {0, 0, 100};
  for (CoordSystem cs : {CoordSystem::MCS, CoordSystem::WCS}) {
    Collect sink;
    Placement p(sink, cs, Vec3{0, 0, 0});
    p.motion(first);
    p.motion(second);
    ASSERT_EQ(sink.segments.size(), 2u);
    const Segment& s = sink.segments[1];
    if (cs == CoordSystem::MCS) {
      expectVec(sink.segments[0].start, 0, 0, 0);
      expectVec(s.start, 0, 0, 50);
      expectVec(s.end, 100, 10, 105);
    } else {
      expectVec(s.start, 0, 100, -50);
      expectVec(s.end, 10, 0, 5);
    }
  }
}

// The bypass (Placement::bypass, the channel's sink switch): while nothing waits, segments go
// to the target directly; while something waits, through the sink. Either way the same
// segments in the same order as without a bypass (the general path).
TEST(Placement, BypassGivesTheSegmentsOfTheGeneralPath) {
  Collect general, through, direct;
  Placement plain(general, CoordSystem::MCS);
  Placement bypassed(through, CoordSystem::MCS);
  PathSink* target = &direct;
  bool waiting = false;
  bypassed.bypass(&target, &waiting);
  std::vector<bool> went_direct;
  for (int i = 0; i < 40; ++i) {
    waiting = i % 3 == 1;
    MotionBlock b = quarterArc(i % 2 ? Motion::G2 : Motion::G3);
    b.line = i;
    plain.motion(b);
    bypassed.motion(b);
    went_direct.push_back(!waiting);
  }
  ASSERT_EQ(general.segments.size(), 40u);
  ASSERT_EQ(through.segments.size() + direct.segments.size(), 40u);
  size_t d = 0, t = 0;
  for (size_t i = 0; i < 40; ++i) {
    const Segment& s = went_direct[i] ? direct.segments[d++] : through.segments[t++];
    EXPECT_EQ(s.line, general.segments[i].line);
    EXPECT_EQ(s.motion, general.segments[i].motion);
    expectVec(s.start, general.segments[i].start.x, general.segments[i].start.y,
              general.segments[i].start.z);
    expectVec(s.end, general.segments[i].end.x, general.segments[i].end.y,
              general.segments[i].end.z);
  }
}

// Two segments the same to the bit (a -0 is no 0 here).
void expectSame(const Segment& a, const Segment& b) {
  const auto same = [](const Vec3& u, const Vec3& v) { return std::memcmp(&u, &v, sizeof u) == 0; };
  EXPECT_EQ(a.line, b.line);
  EXPECT_EQ(a.file, b.file);
  EXPECT_EQ(a.motion, b.motion);
  EXPECT_TRUE(same(a.start, b.start));
  EXPECT_TRUE(same(a.end, b.end));
  EXPECT_TRUE(same(a.centre, b.centre));
  EXPECT_TRUE(same(a.normal, b.normal));
  EXPECT_EQ(a.turns, b.turns);
  EXPECT_EQ(std::memcmp(&a.feed, &b.feed, sizeof a.feed), 0);
  EXPECT_EQ(a.feed_unit, b.feed_unit);
  EXPECT_EQ(a.has_feed, b.has_feed);
  EXPECT_EQ(std::memcmp(&a.lead_change, &b.lead_change, sizeof a.lead_change), 0);
}

// The block with a P - S of -0 at both ends where it has none: the same segment (x + -0 is x,
// also for x = -0) from the placement's general path (Placement::toSegment), never its fast
// paths, which take only blocks without P - S. (Not under a frame in WCS: there the vector is
// the frame's inverse image, maybe +0.)
MotionBlock generalOnly(MotionBlock m) {
  if (m.tip_at != core::kTipNone || !m.frame.isIdentity()) return m;
  m.tip_at = core::kTipBoth;
  m.tip = {-0.0, -0.0, -0.0};
  return m;
}

// element() (its fast path for G17 in MCS without a frame or P - S, and the general one) against
// the general definition, Stage::element: the block with core::planeGeometry to motion() (its
// general path).
// 20,000 random elements in random blocks: the three planes, lines of any motion and arcs, tool
// offsets that change (rejoined), frames, WCS, turning tools, -0.
TEST(Placement, ElementAsItsGeometryInTheBlock) {
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> any(-500, 500);
  std::uniform_int_distribution<int> pick(0, 9);
  const double pool[] = {0.0, -0.0, 1.5, -20, 2.7889999999999997};
  const auto value = [&] { return pick(rng) < 3 ? pool[pick(rng) % 5] : any(rng); };
  const auto point = [&] { return Vec3{value(), value(), value()}; };
  Frame f;
  f.coarse = {100, 0, 0};
  f.rotation = {0, 30, 90};
  for (CoordSystem cs : {CoordSystem::MCS, CoordSystem::WCS}) {
    Collect fast, general;
    Placement element(fast, cs, Vec3{1, 2, 3});
    Placement motion(general, cs, Vec3{1, 2, 3});
    MotionBlock like;
    like.trc.mode = core::TrcMode::Left;  // range checked on both paths
    for (int i = 0; i < 20000; ++i) {
      like.line = i;
      like.plane = static_cast<Plane>(pick(rng) < 6 ? 0 : pick(rng) % 3);
      like.motion = static_cast<Motion>(pick(rng) % 5);  // G0..G3, G33
      like.start = point(), like.end = point(), like.centre = point();
      like.applicate = pick(rng) % 3;
      like.turns = pick(rng) % 3;
      if (pick(rng) == 0) like.tool_offset = point();
      like.frame = pick(rng) < 8 ? core::BlockFrame() : affineOf(f);
      like.has_tip = pick(rng) == 0;
      like.tip = point();
      like.feed = value(), like.has_feed = pick(rng) < 7, like.lead_change = value();
      geom::Element e;
      e.arc = pick(rng) < 4;
      e.p0 = {value(), value()}, e.p1 = {value(), value()}, e.c = {value(), value()};
      e.ccw = pick(rng) < 5;
      e.turns = pick(rng) % 2;
      const auto tip = static_cast<std::uint8_t>(like.has_tip ? pick(rng) % 4 : core::kTipNone);
      element.element(like, e, tip);
      motion.motion(generalOnly(core::withGeometry(like, core::planeGeometry(like, e, tip))));
    }
    ASSERT_EQ(fast.segments.size(), general.segments.size());
    for (size_t i = 0; i < fast.segments.size(); ++i)
      expectSame(fast.segments[i], general.segments[i]);
  }
}

// motion()'s fast path (MCS, no frame, no P - S) against its general path, Placement::toSegment:
// 20,000 random blocks, lines and arcs, tool offsets that change, frames, WCS, -0.
TEST(Placement, MotionAsTheGeneralPath) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> any(-500, 500);
  std::uniform_int_distribution<int> pick(0, 9);
  const auto value = [&] { return pick(rng) < 2 ? (pick(rng) < 5 ? 0.0 : -0.0) : any(rng); };
  const auto point = [&] { return Vec3{value(), value(), value()}; };
  Frame f;
  f.fine = {0, -5, 7};
  f.rotation = {45, 0, 0};
  for (CoordSystem cs : {CoordSystem::MCS, CoordSystem::WCS}) {
    Collect fast, general;
    Placement a(fast, cs), b(general, cs);
    MotionBlock m;
    for (int i = 0; i < 20000; ++i) {
      m.line = i;
      m.motion = static_cast<Motion>(pick(rng) % 5);  // G0..G3, G33
      m.start = point(), m.end = point(), m.centre = point();
      m.applicate = pick(rng) % 3;
      m.turns = pick(rng) % 3;
      m.trc.mode = pick(rng) < 5 ? core::TrcMode::Off : core::TrcMode::Right;
      if (pick(rng) == 0) m.tool_offset = point();
      m.frame = pick(rng) < 8 ? core::BlockFrame() : affineOf(f);
      m.feed = value(), m.has_feed = pick(rng) < 7, m.lead_change = value();
      a.motion(m);
      b.motion(generalOnly(m));
    }
    ASSERT_EQ(fast.segments.size(), general.segments.size());
    for (size_t i = 0; i < fast.segments.size(); ++i)
      expectSame(fast.segments[i], general.segments[i]);
  }
}

}  // namespace
}  // namespace ncoffset::place
