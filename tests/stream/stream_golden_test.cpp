// Streaming (include/ncoffset/stream.hpp) against the whole text: every golden program
// (tests/programs/**/NAME.MPF, with the init files and options of its NAME.expected) is fed to a
// Stream line by line, and again in chunks of 7 characters that cut lines apart, and what the
// sink receives is compared with Channel::runText of the whole text: segment for segment, event
// for event, message, warning and alarm, every number exact.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "ncoffset/channel.hpp"
#include "ncoffset/stream.hpp"
#include "support/golden_cases.hpp"

using namespace ncoffset;

namespace {

// Every record as one exact text line (doubles in their shortest round-trip form).
class Recorder final : public PathSink {
 public:
  std::vector<std::string> records;
  void segment(const Segment& s) override {
    add(fmt::format("seg {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {}", s.line, s.file,
                    motionName(s.motion), s.start.x, s.start.y, s.start.z, s.end.x, s.end.y,
                    s.end.z, s.centre.x, s.centre.y, s.centre.z, s.normal.x, s.normal.y, s.normal.z,
                    s.turns, s.feed, s.has_feed));
  }
  void message(const SourceLoc& l, const std::string& t) override {
    add(fmt::format("msg {}:{} {}", l.file, l.line, t));
  }
  void warning(const SourceLoc& l, int n, const std::string& t) override {
    add(fmt::format("warn {}:{} {} {}", l.file, l.line, n, t));
  }
  bool wantsEvents() const override { return true; }
  void tool(const ToolEvent& e) override {
    add(fmt::format("tool {}:{} {} T{} D{} r{} l{},{},{} {}", e.file, e.line,
                    static_cast<int>(e.word), e.tool, e.edge, e.radius, e.length.x, e.length.y,
                    e.length.z, e.changed));
  }
  void mFunction(const MFunctionEvent& e) override {
    add(fmt::format("m {}:{} M{}={}", e.file, e.line, e.spindle, e.number));
  }
  void dwell(const DwellEvent& e) override {
    add(fmt::format("dwell {}:{} {} {}", e.file, e.line, e.seconds, e.revolutions));
  }
  void spindle(const SpindleEvent& e) override {
    add(fmt::format("spindle {}:{} S{}={}", e.file, e.line, e.spindle, e.speed));
  }
  void feed(const FeedEvent& e) override {
    add(fmt::format("feed {}:{} {}", e.file, e.line, e.feed));
  }
  void frame(const FrameEvent& e) override {
    const auto& l = e.map.linear.m;
    add(fmt::format("frame {}:{} {} {} {} {} {} {} {} {} {} {} {} {}", e.file, e.line,
                    e.map.offset.x, e.map.offset.y, e.map.offset.z, l[0][0], l[0][1], l[0][2],
                    l[1][0], l[1][1], l[1][2], l[2][0], l[2][1], l[2][2]));
  }
  void finish(const Alarm* a) override {
    ++finished;
    add(a ? fmt::format("alarm {} {}:{}:{} {}", a->number, a->where.file, a->where.line,
                        a->where.column, a->text)
          : std::string("end"));
  }
  int finished = 0;

 private:
  void add(std::string s) { records.push_back(std::move(s)); }
};

using golden::readAll;
using golden::runGoldenInits;
using Case = golden::GoldenCase;

// Feeds `text` in pieces of `chunk` characters (0: line by line).
std::vector<std::string> streamed(const Case& c, const std::string& text, size_t chunk) {
  Channel ch(c.options);
  Recorder rec;
  if (!runGoldenInits(ch, c)) return {"init failed"};
  Stream s(ch, rec, c.program.filename().string(), c.program.parent_path());
  size_t at = 0;
  while (at < text.size()) {
    size_t n = chunk;
    if (chunk == 0) {
      size_t nl = text.find('\n', at);
      n = nl == std::string::npos ? text.size() - at : nl + 1 - at;
    }
    s.feed(std::string_view(text).substr(at, n));
    at += n;
  }
  s.finish();
  s.finish();  // a second finish changes nothing
  EXPECT_EQ(rec.finished, 1);
  return rec.records;
}

// Alarms of the control-structure index: 12640/12641 nesting, 12080 a label defined twice.
bool isStructureAlarm(const std::string& r) {
  return r.rfind("alarm 12640 ", 0) == 0 || r.rfind("alarm 12641 ", 0) == 0 ||
         r.rfind("alarm 12080 ", 0) == 0;
}
// "alarm N file:line:column text" without the column (the block's, where the stream was).
std::string withoutColumn(const std::string& r) {
  size_t sp = r.find(' ', 12);
  size_t colon = r.rfind(':', sp);
  return sp == std::string::npos || colon == std::string::npos ? r
                                                               : r.substr(0, colon) + r.substr(sp);
}

class StreamGolden : public ::testing::TestWithParam<Case> {};

TEST_P(StreamGolden, SameAsWholeText) {
  const Case& c = GetParam();
  const std::string text = readAll(c.program);
  Channel whole_ch(c.options);
  Recorder whole;
  if (!runGoldenInits(whole_ch, c)) GTEST_SKIP() << "an init file of the case fails";
  whole_ch.runText(c.program.filename().string(), text, whole, c.program.parent_path());
  for (size_t chunk : {size_t{0}, size_t{7}}) {
    std::vector<std::string> s = streamed(c, text, chunk);
    const char* how = chunk ? "in chunks of 7 characters" : "line by line";
    if (whole.records.size() == 1 && isStructureAlarm(whole.records[0])) {
      // Found before anything runs in the whole text, when the line is fed in a stream (the
      // segments before it are written first): the same alarm at the same line.
      ASSERT_FALSE(s.empty()) << how;
      EXPECT_EQ(withoutColumn(s.back()), withoutColumn(whole.records[0])) << how;
      continue;
    }
    EXPECT_EQ(s, whole.records) << how;
  }
}

INSTANTIATE_TEST_SUITE_P(Programs, StreamGolden,
                         ::testing::ValuesIn(golden::discoverGoldenCases(NCOFFSET_PROGRAMS)),
                         [](const auto& info) { return info.param.name; });

}  // namespace

namespace {

// The stream's own behaviour, beside the golden comparison.
TEST(Stream, WaitsAtAForwardJumpUntilItsDestinationIsFed) {
  Channel ch;
  Recorder rec;
  Stream s(ch, rec, "J.MPF");
  s.feed("G1 X1 F100\nGOTOF END\nG1 X2\n");
  // X1 is written (G40: nothing held back); the jump waits for END, X2 is not executed.
  EXPECT_EQ(rec.records.size(), 2u);  // feed event, X1
  s.feed("G1 X3\nEND:\nG1 X4\n");
  s.finish();
  ASSERT_EQ(rec.records.size(), 4u);
  EXPECT_EQ(rec.records[2].substr(0, 6), "seg 6 ");  // X4 on line 6: X2 and X3 skipped
  EXPECT_EQ(rec.records.back(), "end");
}

TEST(Stream, BackwardJumpsRunInTheKeptText) {
  Channel ch;
  Recorder rec;
  Stream s(ch, rec, "L.MPF");
  s.feed("R1=0\nG1 F100\nLOOP1: R1=R1+1\nG1 X=R1\n");
  s.feed("IF R1<3 GOTOB LOOP1\nM30\n");
  EXPECT_TRUE(s.ended());
  EXPECT_FALSE(s.feed("G1 X99\n"));  // after M30: ignored
  s.finish();
  int segs = 0;
  for (const auto& r : rec.records) segs += r.rfind("seg ", 0) == 0;
  EXPECT_EQ(segs, 3);
}

TEST(Stream, ManySegmentsInOneFeedComeInBatches) {
  std::string text = "G1 F100\n";
  for (int i = 0; i < 3 * static_cast<int>(Stream::kBatch); ++i)
    text += fmt::format("X{} Y{}\n", i % 50 + 1, i % 7);
  Channel ch;
  Recorder rec;
  Stream s(ch, rec, "B.MPF");
  s.feed(text);
  EXPECT_EQ(rec.records.size(), 3 * Stream::kBatch + 1);  // the feed event and every segment
  EXPECT_FALSE(s.finish().alarm);
}

TEST(Stream, DestroyedUnfinishedWritesNothingMore) {
  Channel ch;
  Recorder rec;
  {
    Stream s(ch, rec, "U.MPF");
    s.feed("G1 X1 F100\nWHILE TRUE\n");
  }
  EXPECT_EQ(rec.finished, 0);
  // The channel runs again afterwards.
  Recorder again;
  EXPECT_EQ(ch.runText("A.MPF", "G1 X5 F10\n", again).status, RunResult::Status::Ok);
  EXPECT_EQ(again.records.back(), "end");
}

TEST(Stream, AnAlarmEndsTheStreamAndFinishesTheSinkOnce) {
  Channel ch;
  Recorder rec;
  Stream s(ch, rec, "A.MPF");
  EXPECT_FALSE(s.feed("G1 X1 F100\nR1=1/0\n"));
  EXPECT_EQ(rec.finished, 1);
  RunResult r = s.finish();
  ASSERT_TRUE(r.alarm);
  EXPECT_EQ(r.alarm->number, 14051);
  EXPECT_EQ(rec.finished, 1);
}

}  // namespace

namespace {

TEST(Events, MsgBetweenCompensatedBlocksComesAfterTheSegmentsBeforeIt) {
  Channel ch;
  Recorder rec;
  Recorder ignored;
  ASSERT_EQ(ch.runInitText("T.INI", "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\nM17\n", ignored).status,
            RunResult::Status::Ok);
  ch.runText("M.MPF",
             "T1 D1\nG1 F200 X0 Y0\nG41 X10 Y0\nMSG(\"corner\")\nX10 Y20\nX0 Y20\nG40 X-10 Y30\n",
             rec);
  std::vector<std::string> kinds;
  for (const auto& r : rec.records) kinds.push_back(r.substr(0, r.find(' ')));
  // The selection block (line 3) is written once line 5 is known; the MSG of line 4 follows it.
  const std::vector<std::string> expected = {"tool", "tool", "feed", "seg", "msg",
                                             "seg",  "seg",  "seg",  "end"};
  EXPECT_EQ(kinds, expected);
}

}  // namespace
