// The interpreter alone (src/interp/interpreter.hpp), without Channel: it hands motion blocks to
// the stage it is given and takes back what that stage feeds back; MSG texts go to the sink.
#include "interp/interpreter.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace ncoffset::interp {
namespace {

// The first stage: keeps the blocks and counts what else arrives.
class CollectStage final : public core::Stage {
 public:
  std::vector<core::MotionBlock> blocks;
  int without_motion = 0, stops = 0, flushes = 0;
  core::Feedback next;
  core::Feedback motion(const core::MotionBlock& m) override {
    blocks.push_back(m);
    return std::exchange(next, {});
  }
  void warning(const core::MotionBlock&, int, const std::string&) override {}
  void blockWithoutMotion() override { ++without_motion; }
  std::optional<Vec3> preprocessorStop(bool) override {
    ++stops;
    return std::nullopt;
  }
  void flush() override { ++flushes; }
};

class MessageSink final : public PathSink {
 public:
  std::vector<std::string> messages;
  void segment(const Segment&) override {}
  void message(const SourceLoc&, const std::string& t) override { messages.push_back(t); }
  void finish(const Alarm*) override {}
};

struct Fixture {
  MessageSink sink;
  CollectStage stage;
  Interpreter interp{RunOptions{}, sink, stage};
  void run(const std::string& text) {
    interp.run(interp.load(lang::SourceFile::fromString("T.MPF", text)), false);
  }
};

TEST(Interpreter, HandsEachMotionToTheFirstStage) {
  Fixture f;
  f.run("G90 G1 X10 Y5 F200\nG41 X20\nM30\n");
  ASSERT_EQ(f.stage.blocks.size(), 2u);
  EXPECT_EQ(f.stage.blocks[0].line, 1);
  EXPECT_EQ(f.stage.blocks[0].end.x, 10);
  EXPECT_EQ(f.stage.blocks[0].feed, 200);
  EXPECT_EQ(f.stage.blocks[1].trc.mode, core::TrcMode::Left);
  EXPECT_EQ(f.stage.flushes, 1);  // the program end flushes the chain
}

TEST(Interpreter, BlocksWithoutMotionAndStopreReachTheStage) {
  Fixture f;
  f.run("G1 X1 F100\nM8\nSTOPRE\nS100\n");
  EXPECT_EQ(f.stage.without_motion, 2);  // M8 and S100 (STOPRE is a stop of its own)
  EXPECT_EQ(f.stage.stops, 1);
}

TEST(Interpreter, TheFedBackEndPointIsWhereTheNextBlockStarts) {
  Fixture f;
  f.stage.next.end_point = Vec3{3, 4, 0};  // e.g. a retraction whose end point is implicit
  f.run("G1 X10 F100\nG1 X20\n");
  ASSERT_EQ(f.stage.blocks.size(), 2u);
  EXPECT_EQ(f.stage.blocks[1].start.x, 3);
  EXPECT_EQ(f.stage.blocks[1].start.y, 4);
}

TEST(Interpreter, ApproachPointsFedBackAreReadable) {
  Fixture f;
  f.stage.next.approach = core::ApproachPoints{{1, 2, 3}, {4, 5, 6}, true};
  f.run("G1 X10 F100\nR1=$P_APR[X] R2=$P_AEP[Z] R3=$P_APDV\n");
  std::ostringstream vars;
  f.interp.writeVariablesJson(vars);
  EXPECT_NE(vars.str().find(R"("R": {"1": 1, "2": 6, "3": 1})"), std::string::npos) << vars.str();
}

}  // namespace
}  // namespace ncoffset::interp
