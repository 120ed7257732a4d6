// The dwells of the built-in CYCLE83 (src/cycles/drilling_cycles.cpp, docs/cycles.md): DTB
// after each stroke, DTS after each chip-removal return, the newer versions' _DTD at the final
// depth (> 0 seconds, < 0 revolutions, 0: DTB there too). The golden cases (tests/programs/
// cycles/deep_hole_*) check the path; the CSV has no dwells, so their order is checked here:
// every segment as "G1 -8" (motion and drilling-axis end), every dwell as "s0.5" or "r4".
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ncoffset/channel.hpp"

namespace ncoffset {
namespace {

class Sequence final : public PathSink {
 public:
  std::vector<std::string> items;
  bool wantsEvents() const override { return true; }
  void segment(const Segment& s) override {
    items.push_back(fmt::format("{} {}", motionName(s.motion), s.end.z));
  }
  void dwell(const DwellEvent& e) override {
    items.push_back(e.revolutions != 0 ? fmt::format("r{}", e.revolutions)
                                       : fmt::format("s{}", e.seconds));
  }
  void finish(const Alarm*) override {}
};

std::vector<std::string> run(const std::string& cycle) {
  Sequence sink;
  Channel ch;
  RunResult r = ch.runText("T.MPF", "G17 G90 G94 F100\nG0 X0 Y0 Z10\n" + cycle + "\nM30\n", sink);
  EXPECT_EQ(r.status, RunResult::Status::Ok);
  return sink.items;
}

using V = std::vector<std::string>;

TEST(Cycle83, DtdInRevolutionsAtTheFinalDepthDtbAndDtsBetween) {
  // Chip removal, depth 20 (anticipation 0.6), FDPR 8, DAM 0: strokes to -8, -16, -20. After
  // the first two DTB 0.5 s, G0 Z1, DTS 0.3 s, G0 back 0.6 above; after the last _DTD -4:
  // 4 revolutions instead of DTB.
  EXPECT_EQ(run("CYCLE83(10,0,1,0,20,0,8,0,0.5,0.3,1,1,0,0,0,-4)"),
            (V{"G0 10", "G0 1", "G1 -8", "s0.5", "G0 1", "s0.3", "G0 -7.4", "G1 -16", "s0.5",
               "G0 1", "s0.3", "G0 -15.4", "G1 -20", "r4", "G0 10"}));
}

TEST(Cycle83, DtdZeroDwellsDtbAtTheFinalDepthToo) {
  // Chip breaking, the same strokes: DTB 0.5 s after each, the G1 retraction of 1 mm between.
  EXPECT_EQ(run("CYCLE83(10,0,1,0,20,0,8,0,0.5,0,1,0)"),
            (V{"G0 10", "G0 1", "G1 -8", "s0.5", "G1 -7", "G1 -16", "s0.5", "G1 -15", "G1 -20",
               "s0.5", "G0 10"}));
}

TEST(Cycle83, DtbAndDtsInRevolutionsDtdInSeconds) {
  // DTB -2: 2 revolutions after the stroke to -8; DTS -3: 3 revolutions at RFP + SDIS;
  // _DTD 1.5: 1.5 s at the final depth -16.
  EXPECT_EQ(
      run("CYCLE83(10,0,1,-16,0,-8,0,0,-2,-3,1,1,0,0,0,1.5)"),
      (V{"G0 10", "G0 1", "G1 -8", "r2", "G0 1", "r3", "G0 -7.4", "G1 -16", "s1.5", "G0 10"}));
}

}  // namespace
}  // namespace ncoffset
