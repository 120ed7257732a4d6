// The placement's row hand-over (core/row_sink.hpp, docs/architecture.md "The row hand-over")
// against its twin, the Segment to PathSink::segment: the same fields bit for bit, the same CSV
// byte for byte.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/row_sink.hpp"
#include "ncoffset/frame.hpp"
#include "out/writer_test_support.hpp"
#include "out/writers.hpp"
#include "place/placement.hpp"

namespace ncoffset::place {
namespace {

using core::MotionBlock;

// What a RowSink reads of a segment (the centre of arcs only).
struct Row {
  int line;
  Motion motion;
  bool has_feed;
  Vec3 end, centre;
  double feed;
  bool operator==(const Row& r) const {
    const bool arc = motion == Motion::G2 || motion == Motion::G3;
    return line == r.line && motion == r.motion && has_feed == r.has_feed &&
           std::memcmp(&end, &r.end, sizeof end) == 0 &&
           (!arc || std::memcmp(&centre, &r.centre, sizeof centre) == 0) &&
           std::memcmp(&feed, &r.feed, sizeof feed) == 0;
  }
};

Row rowOf(const Segment& s) {
  return {s.line, s.motion, s.has_feed, s.end, s.centre, s.feed};
}

// Segments only (the twin's way).
class Segments final : public PathSink {
 public:
  std::vector<Row> rows;
  void segment(const Segment& s) override { rows.push_back(rowOf(s)); }
  void finish(const Alarm*) override {}
};

// A RowSink: rows (counted) and segments in one sequence.
class Rows final : public core::RowSink, public PathSink {
 public:
  std::vector<Row> rows;
  size_t by_row = 0;
  void segment(const Segment& s) final { rows.push_back(rowOf(s)); }
  void row(int line, Motion motion, bool has_feed, double x, double y, double z, double cx,
           double cy, double cz, double feed) final {
    rows.push_back({line, motion, has_feed, {x, y, z}, {cx, cy, cz}, feed});
    ++by_row;
  }
  void finish(const Alarm*) override {}
};

// Passes segments on: hides the CSV writer's RowSink from the placement.
class Forward final : public PathSink {
 public:
  explicit Forward(PathSink& next) : next_(next) {}
  void segment(const Segment& s) override { next_.segment(s); }
  void finish(const Alarm* a) override { next_.finish(a); }

 private:
  PathSink& next_;
};

const std::string& noName(int) {
  static const std::string kName = "T.MPF";
  return kName;
}

// Random elements and motions through two placements, `a` (its target a RowSink, the bypass of
// the sink switch waiting now and then) and `b` (segments only): G17 and other planes, lines of
// any motion and arcs, tool offsets that change (rejoined), frames, WCS, turning tools, range
// checks, -0, numbers the CSV writer's usual row takes and ones it does not.
void placeRandom(Placement& a, Placement& b, bool& waiting, int seed, int n) {
  std::mt19937_64 rng(static_cast<unsigned long long>(seed));
  std::uniform_real_distribution<double> any(-500, 500);
  std::uniform_int_distribution<int> pick(0, 9);
  const double pool[] = {0.0, -0.0, 1.5, -20, 2.7889999999999997, 9999, 12345.5, 0.125};
  const auto value = [&] { return pick(rng) < 6 ? pool[pick(rng) % 8] : any(rng); };
  const auto point = [&] { return Vec3{value(), value(), value()}; };
  Frame f;
  f.coarse = {100, 0, 0};
  f.rotation = {0, 30, 90};
  MotionBlock like;
  for (int i = 0; i < n; ++i) {
    like.line = pick(rng) < 8 ? like.line + 1 : pick(rng) * 1000;
    like.seq = i;
    like.plane = static_cast<Plane>(pick(rng) < 8 ? 0 : pick(rng) % 3);
    like.motion = static_cast<Motion>(pick(rng) % 5);  // G0..G3, G33
    like.start = point(), like.end = point(), like.centre = point();
    like.applicate = pick(rng) < 8 ? 2 : pick(rng) % 3;
    like.turns = pick(rng) % 3;
    like.trc.mode = pick(rng) < 5 ? core::TrcMode::Off : core::TrcMode::Left;
    if (pick(rng) == 0) like.tool_offset = point();
    like.frame = pick(rng) < 9 ? core::BlockFrame() : core::BlockFrame(f.affine(), 1, false);
    like.tip_at = pick(rng) < 9 ? core::kTipNone : core::kTipBoth;
    like.tip = point();
    like.feed = value(), like.has_feed = pick(rng) < 7;
    waiting = pick(rng) == 0;
    if (pick(rng) < 5) {
      a.motion(like);
      b.motion(like);
      continue;
    }
    geom::Element e;
    e.arc = pick(rng) < 4;
    e.p0 = {value(), value()}, e.p1 = {value(), value()}, e.c = {value(), value()};
    e.ccw = pick(rng) < 5;
    const auto tip = static_cast<std::uint8_t>(pick(rng) < 9 ? core::kTipNone : core::kTipEnd);
    a.element(like, e, tip);
    b.element(like, e, tip);
  }
}

// The fields a RowSink reads, by row() and by segment() (the bypass waiting, a rejoin, the
// placement's general paths), against the segments of the twin: the same to the bit, in order.
TEST(PlacementRows, RowsAsTheSegments) {
  for (CoordSystem cs : {CoordSystem::MCS, CoordSystem::WCS}) {
    Rows rows;
    Segments segments;
    Placement a(rows, cs, Vec3{1, 2, 3}), b(segments, cs, Vec3{1, 2, 3});
    PathSink* target = &rows;  // the sink switch's bypass: waiting, segments go through it
    bool waiting = false;
    a.bypass(&target, &waiting);
    a.beginRun(noName);
    b.beginRun(noName);
    placeRandom(a, b, waiting, cs == CoordSystem::MCS ? 49 : 50, 40000);
    ASSERT_EQ(rows.rows.size(), segments.rows.size());
    if (cs == CoordSystem::MCS) {
      EXPECT_GT(rows.by_row, 20000u);
    }
    EXPECT_GT(rows.rows.size() - rows.by_row, 4000u);
    for (size_t i = 0; i < rows.rows.size(); ++i) {
      ASSERT_TRUE(rows.rows[i] == segments.rows[i]) << i;
    }
  }
}

// The range check of a row (the sum of the squares first) against a segment's: for coordinates
// at and beyond 1e9, infinite and NaN, in the end point and an arc's centre, the same alarm or
// none, and the same rows.
TEST(PlacementRows, RangeAlarmsAsTheSegments) {
  const double edge[] = {0,
                         -1e9,
                         1e9,
                         std::nextafter(1e9, 2e9),
                         -std::nextafter(1e9, 2e9),
                         7e8,
                         5.8e8,
                         1e18,
                         std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN()};
  std::mt19937_64 rng(53);
  std::uniform_int_distribution<int> pick(0, 9);
  Rows rows;
  Segments segments;
  Placement a(rows, CoordSystem::MCS), b(segments, CoordSystem::MCS);
  a.beginRun(noName);
  b.beginRun(noName);
  MotionBlock like;
  like.trc.mode = core::TrcMode::Left;
  int alarms = 0;
  for (int i = 0; i < 20000; ++i) {
    like.line = i;
    geom::Element e;
    e.arc = pick(rng) < 5;
    e.p1 = {edge[pick(rng)], edge[pick(rng)]};
    e.c = {edge[pick(rng)], edge[pick(rng)]};
    like.start.z = edge[pick(rng)];
    like.end.z = edge[pick(rng)];
    std::string alarm_a, alarm_b;
    try {
      a.element(like, e, core::kTipNone);
    } catch (const AlarmError& x) {
      alarm_a = x.text();
    }
    try {
      b.element(like, e, core::kTipNone);
    } catch (const AlarmError& x) {
      alarm_b = x.text();
    }
    ASSERT_EQ(alarm_a, alarm_b) << i;
    alarms += !alarm_a.empty();
  }
  EXPECT_GT(alarms, 5000);
  EXPECT_GT(rows.by_row, 1000u);
  ASSERT_EQ(rows.rows.size(), segments.rows.size());
  for (size_t i = 0; i < rows.rows.size(); ++i) {
    ASSERT_TRUE(rows.rows[i] == segments.rows[i]) << i;
  }
}

// The CSV writer given rows by the placement against the same writer given its segments (its
// RowSink hidden behind a forwarding sink): the same file, byte for byte.
TEST(PlacementRows, CsvAsFromTheSegments) {
  out::test::File f(std::tmpfile()), g(std::tmpfile());
  ASSERT_TRUE(f && g);
  {
    out::CsvWriter rows(f.get()), segments(g.get());
    Forward forward(segments);
    Placement a(rows, CoordSystem::MCS), b(forward, CoordSystem::MCS);
    PathSink* target = &rows;
    bool waiting = false;
    a.bypass(&target, &waiting);
    a.beginRun(noName);
    b.beginRun(noName);
    placeRandom(a, b, waiting, 51, 100000);
  }
  const std::string csv = out::test::readAll(f.get());
  EXPECT_GT(csv.size(), 1000000u);
  EXPECT_TRUE(csv ==
              out::test::readAll(g.get()));  // (not EXPECT_EQ: no megabytes of text on a failure)
}

}  // namespace
}  // namespace ncoffset::place
