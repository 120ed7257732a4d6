// The public API (include/ncoffset/channel.hpp): Channel::runText with a collecting PathSink.
#include "ncoffset/channel.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ncoffset {
namespace {

class CollectSink final : public PathSink {
 public:
  std::vector<Segment> segments;
  std::vector<std::pair<SourceLoc, std::string>> messages;
  int finished = 0;
  std::optional<Alarm> alarm;

  void segment(const Segment& s) override { segments.push_back(s); }
  void message(const SourceLoc& where, const std::string& text) override {
    messages.emplace_back(where, text);
  }
  void finish(const Alarm* a) override {
    ++finished;
    if (a) alarm = *a;
  }
};

struct Outcome {
  CollectSink sink;
  RunResult result;
  std::string vars;
};

Outcome run(const std::string& text, RunOptions options = {}) {
  Outcome r;
  Channel ch(options);
  r.result = ch.runText("T.MPF", text, r.sink);
  std::ostringstream os;
  ch.writeVariablesJson(os);
  r.vars = os.str();
  return r;
}

void expectVec(Vec3 v, double x, double y, double z) {
  EXPECT_NEAR(v.x, x, 1e-9);
  EXPECT_NEAR(v.y, y, 1e-9);
  EXPECT_NEAR(v.z, z, 1e-9);
}

TEST(Channel, LinesAndArcs) {
  Outcome r =
      run("G1 X10 F100\n"       // 1
          "G2 X20 Y0 CR=5\n"    // 2
          "G0 Z5\n"             // 3
          "G3 X10 Y0 I-5 J0\n"  // 4: F100 is modal across the G0
          "M30\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok);
  EXPECT_FALSE(r.result.alarm);
  EXPECT_EQ(r.sink.finished, 1);
  EXPECT_FALSE(r.sink.alarm);
  ASSERT_EQ(r.sink.segments.size(), 4u);

  const Segment& a = r.sink.segments[0];
  EXPECT_EQ(a.line, 1);
  EXPECT_EQ(a.file, 0);
  EXPECT_EQ(a.motion, Motion::G1);
  expectVec(a.start, 0, 0, 0);
  expectVec(a.end, 10, 0, 0);
  EXPECT_TRUE(a.has_feed);
  EXPECT_EQ(a.feed, 100);

  const Segment& b = r.sink.segments[1];
  EXPECT_EQ(b.line, 2);
  EXPECT_EQ(b.motion, Motion::G2);
  expectVec(b.start, 10, 0, 0);
  expectVec(b.end, 20, 0, 0);
  expectVec(b.centre, 15, 0, 0);
  expectVec(b.normal, 0, 0, 1);
  EXPECT_EQ(b.turns, 0);

  const Segment& c = r.sink.segments[2];
  EXPECT_EQ(c.line, 3);
  EXPECT_EQ(c.motion, Motion::G0);
  expectVec(c.end, 20, 0, 5);
  EXPECT_FALSE(c.has_feed);

  const Segment& d = r.sink.segments[3];
  EXPECT_EQ(d.line, 4);
  EXPECT_EQ(d.motion, Motion::G3);
  expectVec(d.end, 10, 0, 5);
  expectVec(d.centre, 15, 0, 5);
  EXPECT_TRUE(d.has_feed);
  EXPECT_EQ(d.feed, 100);
}

TEST(Channel, ZeroLengthMovesGiveNoSegment) {
  Outcome r = run("G1 X0 Y0 F100\nG1 X1\nG1 X1\nG91 X0\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok);
  ASSERT_EQ(r.sink.segments.size(), 1u);
  EXPECT_EQ(r.sink.segments[0].line, 2);
}

TEST(Channel, CrlfAndCommentsAndBlockNumbers) {
  Outcome r = run("%_N_T_MPF\r\n; header\r\nN10 g1 x5 f200 ; go\r\nN20 M30\r\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << (r.result.alarm ? r.result.alarm->text : "");
  ASSERT_EQ(r.sink.segments.size(), 1u);
  EXPECT_EQ(r.sink.segments[0].line, 3);
  expectVec(r.sink.segments[0].end, 5, 0, 0);
}

TEST(Channel, AlarmCarriesNumberFileAndLine) {
  Outcome r =
      run("G1 X10 F100\n"  // 1
          "R1=1/0\n"       // 2
          "G1 X20\n");     // 3
  ASSERT_EQ(r.result.status, RunResult::Status::Alarm);
  ASSERT_TRUE(r.result.alarm);
  EXPECT_EQ(r.result.alarm->number, 14051);
  EXPECT_EQ(r.result.alarm->where.line, 2);
  EXPECT_EQ(r.result.alarm->where.file, "T.MPF");
  EXPECT_FALSE(r.result.alarm->text.empty());
  // The path up to the alarm is kept, and the sink hears of the alarm once.
  ASSERT_EQ(r.sink.segments.size(), 1u);
  EXPECT_EQ(r.sink.finished, 1);
  ASSERT_TRUE(r.sink.alarm);
  EXPECT_EQ(r.sink.alarm->number, 14051);
  EXPECT_EQ(r.sink.alarm->where.line, 2);
}

TEST(Channel, FeedMissing10860) {
  Outcome r = run("G0 X5\nG1 X10\n");
  ASSERT_TRUE(r.result.alarm);
  EXPECT_EQ(r.result.alarm->number, 10860);
  EXPECT_EQ(r.result.alarm->where.line, 2);
  EXPECT_EQ(r.sink.segments.size(), 1u);
}

TEST(Channel, StructureAlarmFromThePreScan) {
  Outcome r = run("G1 X10 F100\nG1 X20\nWHILE R1<2\nG1 X30\n");
  ASSERT_TRUE(r.result.alarm);
  EXPECT_EQ(r.result.alarm->number, 12640);
  EXPECT_EQ(r.result.alarm->where.line, 3);
  // Found when the file is loaded: nothing was executed.
  EXPECT_TRUE(r.sink.segments.empty());
}

TEST(Channel, BlockLimit) {
  RunOptions o;
  o.limits.max_blocks = 50;
  Outcome r = run("LBL: G1 X1 F100\nR1=R1+1\nG1 X2\nIF R1>0 GOTOB LBL\n", o);
  ASSERT_TRUE(r.result.alarm);
  EXPECT_EQ(r.result.alarm->number, 99002);
}

// The automatic --max-blocks (docs/limits.md "Endless loops"): the base and 2 blocks per byte of
// program text. The loop runs 1 + 600 * 3 + 1 = 1802 blocks.
TEST(Channel, AutomaticBlockLimitGrowsWithTheProgramText) {
  const std::string loop = "R1=0\nLL: R1=R1+1\nG1 X=R1 F100\nIF R1<600 GOTOB LL\nM30\n";
  RunOptions o;
  o.limits.max_blocks_auto_base = 1000;
  Outcome small = run(loop, o);  // 1000 + 2 * 50 bytes < 1802
  ASSERT_TRUE(small.result.alarm);
  EXPECT_EQ(small.result.alarm->number, 99002);
  const long long budget = 1000 + 2 * static_cast<long long>(loop.size());
  EXPECT_NE(small.result.alarm->text.find("limit of " + std::to_string(budget) + " executed"),
            std::string::npos)
      << small.result.alarm->text;
  const std::string padded = "; " + std::string(500, '-') + "\n" + loop;  // 1000 + 2 * 553
  Outcome large = run(padded, o);
  EXPECT_FALSE(large.result.alarm) << large.result.alarm->text;
  EXPECT_EQ(large.sink.segments.size(), 600u);
}

TEST(Channel, ControlFlowAndVariables) {
  Outcome r =
      run("DEF INT II\n"
          "FOR II=1 TO 3\n"
          "  G1 X=II*10 F100\n"
          "ENDFOR\n"
          "IF (II>=3) AND (R1==0)\n"
          "  G1 Y5\n"
          "ELSE\n"
          "  G1 Y-5\n"
          "ENDIF\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << (r.result.alarm ? r.result.alarm->text : "");
  ASSERT_EQ(r.sink.segments.size(), 4u);
  expectVec(r.sink.segments[2].end, 30, 0, 0);
  EXPECT_EQ(r.sink.segments[2].line, 3);
  expectVec(r.sink.segments[3].end, 30, 5, 0);
  EXPECT_EQ(r.sink.segments[3].line, 6);
}

TEST(Channel, Messages) {
  Outcome r = run("G1 X1 F10\nMSG(\"Hello \" << 42)\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok);
  ASSERT_EQ(r.sink.messages.size(), 1u);
  EXPECT_EQ(r.sink.messages[0].first.line, 2);
  EXPECT_EQ(r.sink.messages[0].first.file, "T.MPF");
  EXPECT_EQ(r.sink.messages[0].second, "Hello 42");
}

TEST(Channel, FrameAndCoordinateSystems) {
  const std::string prog = "TRANS X10\nG1 X5 F100\n";
  Outcome mcs = run(prog);
  ASSERT_EQ(mcs.sink.segments.size(), 1u);
  expectVec(mcs.sink.segments[0].end, 15, 0, 0);
  RunOptions o;
  o.coords = CoordSystem::WCS;
  Outcome wcs = run(prog, o);
  ASSERT_EQ(wcs.sink.segments.size(), 1u);
  expectVec(wcs.sink.segments[0].end, 5, 0, 0);
}

TEST(Channel, MirrorSwapsArcSense) {
  Outcome r =
      run("MIRROR X0\n"
          "G1 X10 Y0 F100\n"
          "G2 X0 Y10 I-10 J0\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << (r.result.alarm ? r.result.alarm->text : "");
  ASSERT_EQ(r.sink.segments.size(), 2u);
  expectVec(r.sink.segments[0].end, -10, 0, 0);
  const Segment& arc = r.sink.segments[1];
  EXPECT_EQ(arc.motion, Motion::G3);
  expectVec(arc.end, 0, 10, 0);
  expectVec(arc.centre, 0, 0, 0);
  expectVec(arc.normal, 0, 0, 1);
}

// Mirroring must give the mirror image of the contour programmed inside it, also when the
// contour is rotated (spec §7: A-commands act in the already mirrored system; the frame chain
// IFRAME : PFRAME applies PFRAME inside IFRAME). Unmirrored, X10 after a rotation of 30 degrees
// ends at (8.66, 5).
TEST(Channel, RotationInsideAMirroredSystemIsMirroredToo) {
  Outcome prog = run("MIRROR X0\nAROT Z30\nG1 X10 F100\n");
  ASSERT_EQ(prog.sink.segments.size(), 1u);
  expectVec(prog.sink.segments[0].end, -5 * std::sqrt(3.0), 5, 0);

  Outcome settable = run("$P_UIFR[1]=CMIRROR(Y)\nG54\nROT Z30\nG1 X10 F100\n");
  ASSERT_EQ(settable.sink.segments.size(), 1u);
  expectVec(settable.sink.segments[0].end, 5 * std::sqrt(3.0), -5, 0);
}

TEST(Channel, VariablesJson) {
  Outcome r =
      run("DEF INT K[3]=SET(1,2,3)\n"
          "DEF REAL A=0.1\n"
          "DEF BOOL FLAG=TRUE\n"
          "DEF STRING[8] ST=\"a\\b\"\n"
          "R1=3\n"
          "R7=1/3\n"
          "M30\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << (r.result.alarm ? r.result.alarm->text : "");
  EXPECT_EQ(r.vars,
            "{\"R\": {\"1\": 3, \"7\": 0.3333333333333333}, "
            "\"$P_TOOLNO\": 0, \"$P_TOOL\": 0, \"$P_TOOLL\": [0,0,0], \"$P_TOOLR\": 0, "
            "\"$P_TOOLO\": [0,0,1], \"$TOOL_LENGTH_BCS\": [0,0,0], \"$P_AD\": "
            "[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0], "
            "\"$P_TOOLENVN\": 0, \"DL\": 0, "
            "\"$SUM_OFFSET\": [0,0,0,0], \"$SETUP_OFFSET\": [0,0,0,0], \"$P_TOFFL\": [0,0,0,0], "
            "\"$P_TOFF\": [0,0,0], \"$P_TOFFR\": 0, \"$P_APR\": [0,0,0], "
            "\"$P_AEP\": [0,0,0], \"$P_APDV\": 0, "
            "\"A\": 0.1, \"FLAG\": true, "
            "\"K\": [1,2,3], \"ST\": \"a\\\\b\"}\n");
}

TEST(Channel, VariablesJsonShowsTheActiveOffset) {
  // The D-number state (docs/tool-offsets.md section 10): $P_AD = $TC_DP1..25 of the active
  // offset and its cutting edge number (CE 2: the second edge of T3 created), $P_TOOLENVN.
  Outcome r =
      run("$MN_MM_MAX_CUTTING_EDGE_NO=40\n"
          "$TC_DP1[3,31]=120 $TC_DP1[3,32]=120 $TC_DP3[3,32]=100 $TC_DP6[3,32]=4\n"
          "T3 D32\n"
          "M30\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << (r.result.alarm ? r.result.alarm->text : "");
  EXPECT_NE(r.vars.find("\"$P_TOOLNO\": 3, \"$P_TOOL\": 32,"), std::string::npos) << r.vars;
  EXPECT_NE(r.vars.find("\"$P_AD\": [120,0,100,0,0,4,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,2], "
                        "\"$P_TOOLENVN\": 0"),
            std::string::npos)
      << r.vars;
}

TEST(Channel, VariablesJsonTwoDimensionsAndNoR) {
  Outcome r = run("DEF REAL MM[2,2]=SET(1,2,3,4.5)\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << (r.result.alarm ? r.result.alarm->text : "");
  EXPECT_EQ(r.vars,
            "{\"R\": {}, "
            "\"$P_TOOLNO\": 0, \"$P_TOOL\": 0, \"$P_TOOLL\": [0,0,0], \"$P_TOOLR\": 0, "
            "\"$P_TOOLO\": [0,0,1], \"$TOOL_LENGTH_BCS\": [0,0,0], \"$P_AD\": "
            "[0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0], "
            "\"$P_TOOLENVN\": 0, \"DL\": 0, "
            "\"$SUM_OFFSET\": [0,0,0,0], \"$SETUP_OFFSET\": [0,0,0,0], \"$P_TOFFL\": [0,0,0,0], "
            "\"$P_TOFF\": [0,0,0], \"$P_TOFFR\": 0, \"$P_APR\": [0,0,0], "
            "\"$P_AEP\": [0,0,0], \"$P_APDV\": 0, "
            "\"MM\": [[1,2],[3,4.5]]}\n");
}

TEST(Channel, FileNameOfMainProgram) {
  Channel ch;
  CollectSink sink;
  ch.runText("MAIN.MPF", "G0 X1\n", sink);
  EXPECT_EQ(ch.fileName(0), "MAIN.MPF");
}

// A fresh directory for subprogram files, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::temp_directory_path() /
            ("ncoffset_channel_test_" +
             std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

TEST(Channel, SubprogramsBesideTheProgram) {
  TempDir dir;
  dir.write("SUB1.SPF", "G1 X=R1 F100\nM17\n");
  dir.write("L100.SPF", "G1 Y7 F100\nRET\n");
  dir.write("STEP.SPF", "R2=R2+1\nG1 Z=R2 F100\n");  // ends at the end of the file
  Channel ch;
  CollectSink sink;
  RunResult r = ch.runText("MAIN.MPF", "R1=5\nSUB1\nL100\nSTEP P3\nG1 X0\n", sink, dir.path());
  ASSERT_EQ(r.status, RunResult::Status::Ok) << (r.alarm ? r.alarm->text : "");
  ASSERT_EQ(sink.segments.size(), 6u);
  const Segment& sub = sink.segments[0];
  EXPECT_EQ(sub.line, 1);
  EXPECT_NE(sub.file, 0);
  expectVec(sub.end, 5, 0, 0);
  EXPECT_NE(ch.fileName(sub.file).find("SUB1.SPF"), std::string::npos) << ch.fileName(sub.file);
  expectVec(sink.segments[1].end, 5, 7, 0);
  expectVec(sink.segments[2].end, 5, 7, 1);
  expectVec(sink.segments[4].end, 5, 7, 3);
  EXPECT_EQ(sink.segments[5].line, 5);
  EXPECT_EQ(sink.segments[5].file, 0);
  expectVec(sink.segments[5].end, 0, 7, 3);
}

TEST(Channel, SubprogramNotFound) {
  TempDir dir;
  Outcome r;
  Channel ch;
  r.result = ch.runText("MAIN.MPF", "G0 X1\nNOSUCHSUB\n", r.sink, dir.path());
  ASSERT_TRUE(r.result.alarm);
  EXPECT_EQ(r.result.alarm->number, 14011);
  EXPECT_EQ(r.result.alarm->where.line, 2);
  EXPECT_EQ(r.result.alarm->where.file, "MAIN.MPF");
}

TEST(Channel, MissingFileIsAFileError) {
  Channel ch;
  CollectSink sink;
  RunResult r = ch.runProgram("/nonexistent/dir/NOPE.MPF", sink);
  EXPECT_EQ(r.status, RunResult::Status::FileError);
  EXPECT_FALSE(r.file_error.empty());
  EXPECT_TRUE(sink.segments.empty());
}

}  // namespace
}  // namespace ncoffset
