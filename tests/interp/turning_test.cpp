// Turning through the public API (docs/turning.md): reads under diameter programming in the
// --vars JSON, the --diameter output option, the feed unit of each segment and the machine
// data of the transverse axis and the reset values. Values derived by hand in the comments.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "ncoffset/channel.hpp"

namespace ncoffset {
namespace {

class Collect final : public PathSink {
 public:
  std::vector<Segment> segments;
  std::optional<Alarm> alarm;
  void segment(const Segment& s) override { segments.push_back(s); }
  void finish(const Alarm* a) override {
    if (a) alarm = *a;
  }
};

const char* kLathe = "$MC_DIAMETER_AX_DEF=\"X\"\n$MC_GCODE_RESET_VALUES[5]=2\nM17\n";

struct Outcome {
  Collect sink;
  RunResult result;
  std::string vars;
};

Outcome run(const std::string& program, const std::string& init = kLathe, RunOptions o = {}) {
  Outcome r;
  Channel ch(o);
  Collect init_sink;
  if (!init.empty()) {
    RunResult ir = ch.runInitText("LATHE.INI", init, init_sink);
    EXPECT_EQ(ir.status, RunResult::Status::Ok) << (ir.alarm ? ir.alarm->text : "");
  }
  r.result = ch.runText("T.MPF", program, r.sink);
  std::ostringstream os;
  ch.writeVariablesJson(os);
  r.vars = os.str();
  return r;
}

std::string alarmText(const Outcome& r) {
  return r.result.alarm ? r.result.alarm->text : "";
}

// $P_EP and $AA_IW under DIAMON are diameters, under DIAMOF radii; Z is never a diameter.
// G0 X50 Z-4 under DIAMON: WCS X 25. R1 = $P_EP[X] = 50, R2 = $AA_IW[X] = 50, R3 = $P_EP[Z] =
// -4; after DIAMOF R4 = $P_EP[X] = 25; DIAM90 R5 = $AA_IW[X] = 50.
TEST(Turning, ReadsUnderDiameterProgrammingInTheVariablesJson) {
  Outcome r =
      run("DIAMON\nG0 X50 Z-4\nR1=$P_EP[X] R2=$AA_IW[X] R3=$P_EP[Z]\nDIAMOF\nR4=$P_EP[X]\n"
          "DIAM90\nR5=$AA_IW[X]\nM30\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << alarmText(r);
  EXPECT_EQ(r.vars.rfind("{\"R\": {\"1\": 50, \"2\": 50, \"3\": -4, \"4\": 25, \"5\": 50}", 0), 0u)
      << r.vars;
}

// The transverse axis is read back as its name.
TEST(Turning, TransverseAxisReadsAsItsName) {
  Outcome r = run("DEF STRING[4] A\nA=$MC_DIAMETER_AX_DEF\nM30\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << alarmText(r);
  EXPECT_NE(r.vars.find("\"A\": \"X\""), std::string::npos) << r.vars;
}

// --diameter: X of start, end and centre times 2. G18 arc (from LATHE: reset G18) under DIAMON:
// G0 X40 Z0 -> radius (20, 0); G3 X60 Z-10 I0 K-10 -> end radius 30, centre (20, -10): written
// as end X 60, centre X 40, start X 40. Feed 0.2 per revolution (G95).
TEST(Turning, DiameterOutputDoublesTheTransverseAxis) {
  RunOptions o;
  o.diameter_output = true;
  Outcome r = run("DIAMON G95\nG0 X40 Z0\nG3 X60 Z-10 I0 K-10 F0.2\nM30\n", kLathe, o);
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << alarmText(r);
  ASSERT_EQ(r.sink.segments.size(), 2u);
  const Segment& a = r.sink.segments[1];
  EXPECT_DOUBLE_EQ(a.start.x, 40);
  EXPECT_DOUBLE_EQ(a.end.x, 60);
  EXPECT_DOUBLE_EQ(a.end.z, -10);
  EXPECT_DOUBLE_EQ(a.centre.x, 40);
  EXPECT_DOUBLE_EQ(a.centre.z, -10);
  EXPECT_EQ(a.feed_unit, FeedUnit::MmPerRev);
  EXPECT_DOUBLE_EQ(a.feed, 0.2);
  // Without the option: radius values.
  Outcome plain = run("DIAMON G95\nG0 X40 Z0\nG3 X60 Z-10 I0 K-10 F0.2\nM30\n");
  ASSERT_EQ(plain.sink.segments.size(), 2u);
  EXPECT_DOUBLE_EQ(plain.sink.segments[1].end.x, 30);
  EXPECT_DOUBLE_EQ(plain.sink.segments[1].centre.x, 20);
}

TEST(Turning, DiameterOutputNeedsATransverseAxis) {
  RunOptions o;
  o.diameter_output = true;
  Outcome r = run("G0 X40 Z0\nM30\n", "", o);
  ASSERT_EQ(r.result.status, RunResult::Status::Alarm);
  EXPECT_EQ(r.result.alarm->number, 16510);
}

// Feed units by G group 15: G94 mm/min, G95/G96/G97 mm/rev, G961/G971 mm/min, G93 1/min.
TEST(Turning, FeedUnitOfEachSegment) {
  Outcome r =
      run("G94 G1 X1 F100\nG95 X2 F0.1\nG96 S100 LIMS=2000 X3\nG97 S500 X4\nG961 S90 X5 F80\n"
          "G971 X6\nG93 X7 F2\nM30\n");
  ASSERT_EQ(r.result.status, RunResult::Status::Ok) << alarmText(r);
  const FeedUnit want[] = {FeedUnit::MmPerMin,   FeedUnit::MmPerRev, FeedUnit::MmPerRev,
                           FeedUnit::MmPerRev,   FeedUnit::MmPerMin, FeedUnit::MmPerMin,
                           FeedUnit::InverseTime};
  ASSERT_EQ(r.sink.segments.size(), 7u);
  for (size_t i = 0; i < 7; ++i) EXPECT_EQ(r.sink.segments[i].feed_unit, want[i]) << i;
}

// MD30460 models bit 2 only; MD20150 values outside the group are 12160; MD20100 takes an
// axis name.
TEST(Turning, MachineDataChecks) {
  Outcome mask = run("$MA_BASE_FUNCTION_MASK[Z]=1\nM30\n");
  ASSERT_TRUE(mask.result.alarm);
  EXPECT_EQ(mask.result.alarm->number, 99013);
  Outcome range = run("$MC_GCODE_RESET_VALUES[28]=5\nM30\n");
  ASSERT_TRUE(range.result.alarm);
  EXPECT_EQ(range.result.alarm->number, 12160);
  Outcome axis = run("$MC_DIAMETER_AX_DEF=\"A\"\nM30\n");
  ASSERT_TRUE(axis.result.alarm);
  EXPECT_EQ(axis.result.alarm->number, 99010);
  Outcome none = run("$MC_DIAMETER_AX_DEF=\"\"\nDIAMON\nM30\n");
  ASSERT_TRUE(none.result.alarm);
  EXPECT_EQ(none.result.alarm->number, 16510);
}

// DAC/DIC/RAC/RIC only on axes (not on I, CR=).
TEST(Turning, DiameterWordsOnlyOnAxes) {
  Outcome r = run("G2 X10 Z0 I=DAC(5) F1\nM30\n");
  ASSERT_TRUE(r.result.alarm);
  EXPECT_EQ(r.result.alarm->number, 12080);
}

}  // namespace
}  // namespace ncoffset
