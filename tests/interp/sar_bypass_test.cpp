// The usual block past the SAR stage (MotionBuilder::handOn, docs/performance.md §38) against its
// general twin: with the stage itself in front (the channel's chain) the motion building notes a
// block without SAR word at the idle stage and hands it to the stage behind; with any other
// stage in front, here one that forwards to the same kind of SAR stage, every block goes through
// SmoothApproach::motion. Every SAR program of the golden cases must give the same blocks behind
// the stage, bit for bit, and the same alarm both ways.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"
#include "trc/smooth_approach.hpp"

namespace ncoffset::interp {
namespace {

class CollectStage final : public core::Stage {
 public:
  std::vector<core::MotionBlock> blocks;
  core::Feedback motion(const core::MotionBlock& m) override {
    blocks.push_back(m);
    return {};
  }
  void warning(const core::MotionBlock&, int, const std::string&) override {}
};

// In front of the SAR stage: the motion building does not know it, so it calls motion().
class Forward final : public core::Stage {
 public:
  explicit Forward(core::Stage& next) : next_(next) {}
  core::Feedback motion(const core::MotionBlock& m) override { return next_.motion(m); }
  void warning(const core::MotionBlock& at, int n, const std::string& t) override {
    next_.warning(at, n, t);
  }
  void blockWithoutMotion() override { next_.blockWithoutMotion(); }
  std::optional<Vec3> preprocessorStop(bool alarm) override {
    return next_.preprocessorStop(alarm);
  }
  void flush() override { next_.flush(); }

 private:
  core::Stage& next_;
};

class NoSink final : public PathSink {
 public:
  void segment(const Segment&) override {}
  void finish(const Alarm*) override {}
};

struct Outcome {
  std::vector<core::MotionBlock> blocks;
  std::string alarm;
};

Outcome run(const std::string& text, bool past) {
  Outcome r;
  CollectStage out;
  trc::SmoothApproach sar(out);
  Forward front(sar);
  NoSink sink;
  Interpreter interp(RunOptions{}, sink, past ? static_cast<core::Stage&>(sar) : front);
  try {
    interp.run(interp.load(lang::SourceFile::fromString("T.MPF", text)), false);
  } catch (const AlarmError& e) {
    r.alarm = std::to_string(e.number()) + " " + e.what();
  }
  r.blocks = out.blocks;
  return r;
}

void expectSameVec(const Vec3& a, const Vec3& b) {
  EXPECT_EQ(a.x, b.x);  // bit for bit
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
}

TEST(SarBypass, SameBlocksAsThroughTheStage) {
  int programs = 0, clean = 0;
  for (const auto& e : std::filesystem::directory_iterator(NCOFFSET_PROGRAMS "/sar")) {
    if (e.path().extension() != ".MPF") continue;
    SCOPED_TRACE(e.path().filename().string());
    std::ifstream in(e.path());
    std::stringstream text;
    text << in.rdbuf();
    const Outcome past = run(text.str(), true), through = run(text.str(), false);
    EXPECT_EQ(past.alarm, through.alarm);
    ASSERT_EQ(past.blocks.size(), through.blocks.size());
    for (size_t i = 0; i < past.blocks.size(); ++i) {
      const core::MotionBlock &a = past.blocks[i], &b = through.blocks[i];
      EXPECT_EQ(a.line, b.line);
      EXPECT_EQ(a.motion, b.motion);
      expectSameVec(a.start, b.start);
      expectSameVec(a.end, b.end);
      expectSameVec(a.centre, b.centre);
      EXPECT_EQ(a.trc.mode, b.trc.mode);
      EXPECT_EQ(a.trc.radius, b.trc.radius);
      EXPECT_EQ(a.feed, b.feed);
    }
    ++programs;
    clean += past.alarm.empty() && past.blocks.size() > 2 ? 1 : 0;
  }
  EXPECT_GT(programs, 100);
  EXPECT_GT(clean, 100);  // most run to their end, with the sub-blocks of their SAR
}

}  // namespace
}  // namespace ncoffset::interp
