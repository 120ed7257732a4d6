// Output sinks (src/out/writers.hpp): the CSV contract of design.md and JSON Lines.
#include "out/writers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::File;
using test::makeAlarm;
using test::readAll;

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream is(s);
  std::string l;
  while (std::getline(is, l)) out.push_back(l);
  return out;
}

Segment line(int no, Motion m, Vec3 end, double feed = 0, bool has_feed = false) {
  Segment s;
  s.line = no;
  s.motion = m;
  s.end = end;
  s.feed = feed;
  s.has_feed = has_feed;
  return s;
}

Segment arc(int no, Motion m, Vec3 end, Vec3 centre, double feed) {
  Segment s = line(no, m, end, feed, true);
  s.centre = centre;
  return s;
}

const std::string kHeader = "line,motion,x,y,z,cx,cy,cz,feed";

TEST(CsvWriter, HeaderOnlyForAnEmptyPath) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    CsvWriter w(f.get());
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(f.get()), kHeader + "\n");
}

TEST(CsvWriter, RowsForLinesAndArcs) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    CsvWriter w(f.get());
    w.segment(line(3, Motion::G0, {0, 0, 5}));
    w.segment(line(4, Motion::G1, {10, -2.5, 5}, 100, true));
    w.segment(arc(5, Motion::G2, {20, -2.5, 5}, {15, -2.5, 5}, 100));
    w.segment(arc(6, Motion::G3, {10, -2.5, 5}, {15, -2.5, 5}, 250.5));
    w.finish(nullptr);
  }
  auto l = lines(readAll(f.get()));
  ASSERT_EQ(l.size(), 5u);
  EXPECT_EQ(l[0], kHeader);
  EXPECT_EQ(l[1], "3,G0,0,0,5,,,,");         // no centre, no feed for G0
  EXPECT_EQ(l[2], "4,G1,10,-2.5,5,,,,100");  // empty centre for lines
  EXPECT_EQ(l[3], "5,G2,20,-2.5,5,15,-2.5,5,100");
  EXPECT_EQ(l[4], "6,G3,10,-2.5,5,15,-2.5,5,250.5");
}

TEST(CsvWriter, ShortestRoundTripNumbers) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  const double third = 1.0 / 3.0;
  const double big = 123456789.123;
  const double tiny = 0.1 + 0.2;  // 0.30000000000000004
  {
    CsvWriter w(f.get());
    w.segment(line(1, Motion::G1, {0.1, third, -0.0}, 0.1, true));
    w.segment(line(2, Motion::G1, {big, tiny, 1e-3}, 1000, true));
    w.finish(nullptr);
  }
  auto l = lines(readAll(f.get()));
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l[1], "1,G1,0.1,0.3333333333333333,0,,,,0.1");  // -0 prints as 0
  EXPECT_EQ(l[2], "2,G1,123456789.123,0.30000000000000004,0.001,,,,1000");
  // Every number reads back to the same double.
  std::string y = l[1].substr(l[1].find(",0.3") + 1);
  EXPECT_EQ(std::strtod(y.c_str(), nullptr), third);
  std::string t = l[2].substr(l[2].find(",0.3") + 1);
  EXPECT_EQ(std::strtod(t.c_str(), nullptr), tiny);
}

TEST(CsvWriter, AlarmDoesNotTearTheOutput) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    CsvWriter w(f.get());
    w.segment(line(1, Motion::G1, {1, 2, 3}, 10, true));
    Alarm a = makeAlarm(14051, "T.MPF", 2, "arithmetic error");
    w.finish(&a);
    // Everything is on disk once finish returns, even before the writer goes away.
    std::string s = readAll(f.get());
    EXPECT_EQ(s, kHeader + "\n1,G1,1,2,3,,,,10\n");  // alarms go to stderr, not into the CSV
  }
}

TEST(CsvWriter, ManyRowsAreAllWritten) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  const int n = 20000;  // more than one buffer's worth
  {
    CsvWriter w(f.get());
    for (int i = 1; i <= n; ++i) w.segment(line(i, Motion::G1, {double(i), 0, 0}, 1, true));
    w.finish(nullptr);
  }
  auto l = lines(readAll(f.get()));
  ASSERT_EQ(l.size(), static_cast<size_t>(n + 1));
  EXPECT_EQ(l[1], "1,G1,1,0,0,,,,1");
  EXPECT_EQ(l[n], std::to_string(n) + ",G1," + std::to_string(n) + ",0,0,,,,1");
}

// The row as the general path writes it: every number by {fmt}'s "{}" (-0 as 0).
std::string generalRow(const Segment& s) {
  auto num = [](double v) { return fmt::format("{}", v + 0.0); };
  const bool arc = s.motion == Motion::G2 || s.motion == Motion::G3;
  return fmt::format("{},{},{},{},{},{},{},{},{}\n", s.line, motionName(s.motion), num(s.end.x),
                     num(s.end.y), num(s.end.z), arc ? num(s.centre.x) : "",
                     arc ? num(s.centre.y) : "", arc ? num(s.centre.z) : "",
                     s.has_feed ? num(s.feed) : "");
}

// The columns written from the memo of the row before (z, the centre's z, the feed) against the
// general path: 300,000 random rows whose z and feed repeat, change, change sign (0 and -0)
// and become NaN, mixed with long numbers and arcs.
TEST(CsvWriter, RepeatedColumnsAsTheGeneralPath) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  std::mt19937_64 rng(32);
  const double pool[] = {0.0,    -0.0, -1.0, -2.75,      5.0,          2.7889999999999997,
                         1000.0, 1e20, 1e-7, 123456.789, std::nan(""), 600.5};
  std::uniform_int_distribution<int> pick(0, 11), motion(0, 4), keep(0, 3);
  std::uniform_real_distribution<double> any(-1e4, 1e4);
  std::string expected = kHeader + "\n";
  {
    CsvWriter w(f.get());
    Segment s = line(1, Motion::G1, {0, 0, 0}, 100, true);
    for (int i = 0; i < 300000; ++i) {
      s.line = i;
      s.motion = static_cast<Motion>(motion(rng));  // G0..G3 and G33
      s.end = {any(rng), pool[pick(rng)], keep(rng) ? s.end.z : pool[pick(rng)]};
      s.centre = {pool[pick(rng)], any(rng), keep(rng) ? s.end.z : pool[pick(rng)]};
      if (!keep(rng)) s.feed = pool[pick(rng)];
      s.has_feed = keep(rng) != 0;
      w.segment(s);
      expected += generalRow(s);
    }
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(f.get()), expected);
}

// The line number from the memo of the row before (the same line, the next one: its digits
// incremented in place) against the general path: runs of consecutive lines across every
// carry (9 -> 10, 1999 -> 2000, 99999999 -> 100000000, up to INT_MAX), repeats, jumps back
// and to negative numbers.
TEST(CsvWriter, LineNumbersAsTheGeneralPath) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  std::mt19937_64 rng(37);
  const int starts[] = {0,       1,        7,         95,         990, 1995, 99990,          999995,
                        9999990, 99999990, 999999990, 2147483640, -1,  -12,  -2147483647 - 1};
  std::uniform_int_distribution<int> pick(0, 14), step(0, 9), run(1, 40);
  std::uniform_int_distribution<int> any(std::numeric_limits<int>::min(),
                                         std::numeric_limits<int>::max());
  std::string expected = kHeader + "\n";
  {
    CsvWriter w(f.get());
    Segment s = line(1, Motion::G1, {1, 2, 3}, 100, true);
    for (int i = 0; i < 20000; ++i) {
      const int k = step(rng);
      s.line = k < 6 ? starts[pick(rng)] : k < 8 ? any(rng) : s.line;  // a start, any, the same
      for (int n = run(rng); n > 0; --n) {
        w.segment(s);
        expected += generalRow(s);
        if (s.line == std::numeric_limits<int>::max()) break;
        s.line += step(rng) < 8 ? 1 : 0;  // the next line, or the same again
      }
    }
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(f.get()), expected);
}

// A random row after `s` for UsualRowsAsTheGeneralPath: numbers around the usual row's limits
// (|v| < 10000, six decimals), -0 and NaN; z, the centre's z and the feed mostly repeated.
Segment nextUsualRow(const Segment& s, std::mt19937_64& rng) {
  static const double pool[] = {0.0,     -0.0,         1.0,          -4.0,      9999.0,
                                -9999.0, 10000.0,      -10000.0,     9999.5,    49.25,
                                1.23e-4, 9999.999999,  -9999.999999, 1.0000001, 2.7889999999999997,
                                1e-5,    std::nan(""), 600.5};
  auto any = [&rng] { return pool[rng() % std::size(pool)]; };
  auto often = [&rng] { return rng() % 8 != 0; };
  Segment r = s;
  r.line = rng() % 100 == 0 ? static_cast<int>(rng() % 100000) : s.line + (often() ? 1 : 0);
  r.motion = static_cast<Motion>(rng() % 5);  // G0..G3 and G33
  r.end = {any(), any(), often() ? s.end.z : any()};
  r.centre = {any(), any(), often() ? r.end.z : any()};
  r.feed = often() ? s.feed : any();
  r.has_feed = often();
  return r;
}

// segment()'s usual row (no call, §43) against the general path, and its hand-over to
// generalRow in the middle of a row: consecutive lines (carries included), jumps of the
// line, arcs and G33 (nextUsualRow).
TEST(CsvWriter, UsualRowsAsTheGeneralPath) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  std::mt19937_64 rng(43);
  std::string expected = kHeader + "\n";
  {
    CsvWriter w(f.get());
    Segment s = line(1, Motion::G1, {0, 0, 0}, 100, true);
    for (int i = 0; i < 200000; ++i) {
      s = nextUsualRow(s, rng);
      w.segment(s);
      expected += generalRow(s);
    }
  }
  EXPECT_EQ(readAll(f.get()), expected);
}

// The rows' own buffer (§40): the additional axes' columns join the header while no row was
// written (none pending either), the header stays once a row is pending; rows and header in
// order, nothing lost at the end without finish().
TEST(CsvWriter, AxisColumnsOnlyBeforeTheFirstRow) {
  File f(std::tmpfile()), g(std::tmpfile());
  ASSERT_TRUE(f && g);
  {
    CsvWriter w(f.get());
    w.axisNames({"A"});
    w.axes({1, 0, {90}});
    w.segment(line(1, Motion::G1, {1, 2, 3}, 100, true));
    w.segment(line(2, Motion::G1, {1, 2, 4}, 100, true));  // (consecutive, repeated: §49)
    w.segment(line(2, Motion::G0, {1, 2, 4}));
  }
  EXPECT_EQ(readAll(f.get()),
            kHeader + ",a\n1,G1,1,2,3,,,,100,90\n2,G1,1,2,4,,,,100,90\n2,G0,1,2,4,,,,,90\n");
  {
    CsvWriter w(g.get());
    w.segment(line(1, Motion::G0, {1, 2, 3}));
    w.axisNames({"A"});
    w.segment(line(2, Motion::G0, {4, 5, 6}));
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(g.get()), kHeader + "\n1,G0,1,2,3,,,,\n2,G0,4,5,6,,,,\n");
}

// ---- JSON Lines ------------------------------------------------------------------------------

FileNames names() {
  static const std::vector<std::string> kNames = {"MAIN.MPF", "dir\\SUB \"1\".SPF"};
  return [](int i) -> const std::string& { return kNames.at(static_cast<size_t>(i)); };
}

TEST(JsonLinesWriter, SegmentsMessagesAndAlarmRecord) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    JsonLinesWriter w(f.get(), names());
    w.segment(line(1, Motion::G0, {0, 0, 5}));
    Segment a = arc(2, Motion::G2, {20, 0, 5}, {15, 0, 5}, 100);
    a.file = 1;
    a.turns = 2;
    a.normal = {0, 0, 1};
    w.segment(a);
    w.message({"MAIN.MPF", 3}, "tab\there \"quoted\"");
    Alarm al = makeAlarm(14040, "MAIN.MPF", 4, "error in end point of circle");
    w.finish(&al);
  }
  auto l = lines(readAll(f.get()));
  ASSERT_EQ(l.size(), 4u);
  EXPECT_EQ(l[0], R"({"line":1,"file":"MAIN.MPF","motion":"G0","x":0,"y":0,"z":5})");
  EXPECT_EQ(l[1],
            R"({"line":2,"file":"dir\\SUB \"1\".SPF","motion":"G2","x":20,"y":0,"z":5,)"
            R"("cx":15,"cy":0,"cz":5,"normal":[0,0,1],"turns":2,"feed":100,"feed_unit":"mm/min"})");
  EXPECT_EQ(l[2], R"({"message":"tab\u0009here \"quoted\"","file":"MAIN.MPF","line":3})");
  EXPECT_EQ(
      l[3],
      R"({"alarm":14040,"file":"MAIN.MPF","line":4,"column":0,"text":"error in end point of circle"})");
}

TEST(JsonLinesWriter, NoAlarmRecordOnNormalEnd) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    JsonLinesWriter w(f.get(), names());
    w.segment(line(1, Motion::G1, {0.1, 1.0 / 3.0, 0}, 5, true));
    w.finish(nullptr);
  }
  auto l = lines(readAll(f.get()));
  ASSERT_EQ(l.size(), 1u);
  EXPECT_EQ(
      l[0],
      R"({"line":1,"file":"MAIN.MPF","motion":"G1","x":0.1,"y":0.3333333333333333,"z":0,"feed":5,"feed_unit":"mm/min"})");
}

// The feed's unit from G group 15 (docs/turning.md): mm/rev under G95/G96/G97, 1/min (G93).
TEST(JsonLinesWriter, FeedUnit) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    JsonLinesWriter w(f.get(), names());
    Segment a = line(1, Motion::G1, {1, 0, 0}, 0.2, true);
    a.feed_unit = FeedUnit::MmPerRev;
    w.segment(a);
    a.feed_unit = FeedUnit::InverseTime;
    w.segment(a);
    w.finish(nullptr);
  }
  auto l = lines(readAll(f.get()));
  ASSERT_EQ(l.size(), 2u);
  EXPECT_NE(l[0].find(R"("feed":0.2,"feed_unit":"mm/rev"})"), std::string::npos) << l[0];
  EXPECT_NE(l[1].find(R"("feed":0.2,"feed_unit":"1/min"})"), std::string::npos) << l[1];
}

TEST(JsonString, Escaping) {
  auto json = [](std::string_view s) {
    fmt::memory_buffer b;
    appendJsonString(b, s);
    return fmt::to_string(b);
  };
  EXPECT_EQ(json("plain"), "\"plain\"");
  EXPECT_EQ(json("a\"b"), "\"a\\\"b\"");
  EXPECT_EQ(json("a\\b"), "\"a\\\\b\"");
  EXPECT_EQ(json("line\nbreak"), "\"line\\u000abreak\"");
  EXPECT_EQ(json(std::string_view("\0\x1f", 2)), "\"\\u0000\\u001f\"");
  EXPECT_EQ(json("\x7f"), "\"\\u007f\"");
  EXPECT_EQ(json(""), "\"\"");
  // Output is plain ASCII whatever the input.
  std::string s = json("\xC3\xA4\xFF");
  for (char c : s) EXPECT_LT(static_cast<unsigned char>(c), 0x80u);
}

TEST(MotionName, Names) {
  EXPECT_STREQ(motionName(Motion::G0), "G0");
  EXPECT_STREQ(motionName(Motion::G1), "G1");
  EXPECT_STREQ(motionName(Motion::G2), "G2");
  EXPECT_STREQ(motionName(Motion::G3), "G3");
}

}  // namespace
}  // namespace ncoffset::out
