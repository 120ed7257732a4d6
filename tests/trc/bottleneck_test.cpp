// Bottleneck detection of radius compensation alone (src/trc/bottleneck.cpp, W1 2.4.8, spec
// §5.5, details Q5): the groove of tests/programs/trc/cdon_bottleneck.MPF and its variants, fed
// as motion blocks into a trc::RadiusCompensation with a collecting Stage behind it.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "ncoffset/alarm.hpp"
#include "stage_test_support.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {
namespace {

using test::Collect;
using test::expectRow;
using test::expectVec;
using test::Program;

// R = 5, G41, a groove 4 wide and 4 deep beside a wall (cdon_bottleneck.MPF):
//   N10 (0,0)->(40,0): y = 5;  N20 ->(40,-4): x = 45;  N30 ->(44,-4): y = 1;
//   N40 ->(44,20): x = 39;  N50 G40 ->(30,30).
// N20/N30 and N30/N40 do not meet; only N10 and N40 do, at (39,5), three blocks apart.
// The block numbers are the lines.
void runGroove(RadiusCompensation& trc, CollisionCheck check, int check_blocks) {
  Program p;
  p.trc = test::g41(5);
  p.trc.collision = check;
  p.trc.check_blocks = check_blocks;
  p.at = {-10, 10, 0};
  trc.motion(p.line(5, 0, 0));  // selection
  trc.motion(p.line(10, 40, 0));
  trc.motion(p.line(20, 40, -4));
  trc.motion(p.line(30, 44, -4));
  trc.motion(p.line(40, 44, 20));
  p.trc.mode = core::TrcMode::Off;
  trc.motion(p.line(50, 30, 30));
  trc.flush();
}

void expectGrooveBridged(const Collect& out) {
  // Rows: sel (0,5) | N10 (39,5) | N40 (39,20) | N50 (30,30); N20, N30 omitted with 10763.
  ASSERT_EQ(out.blocks.size(), 4u);
  expectRow(out.blocks[0], 5, Motion::G1, 0, 5);
  expectRow(out.blocks[1], 10, Motion::G1, 39, 5);
  expectRow(out.blocks[2], 40, Motion::G1, 39, 20);
  expectVec(out.blocks[2].start, 39, 5, 0);
  expectRow(out.blocks[3], 50, Motion::G1, 30, 30);
  const std::vector<std::pair<int, int>> omitted{{20, 10763}, {30, 10763}};
  EXPECT_EQ(out.warnings, omitted);
}

TEST(Bottleneck, CdonOmitsTheBlocksOfANarrowStep) {
  // cdon_bottleneck: MD20240 = 3 reaches from N40 back to N10.
  Collect out;
  RadiusCompensation trc(out);
  runGroove(trc, CollisionCheck::Cdon, 3);
  expectGrooveBridged(out);
  EXPECT_FALSE(trc.active());
}

TEST(Bottleneck, CdofSearchesBackWhenAJunctionIsOpen) {
  // cdof_bottleneck: with CDOF the open N20/N30 junction makes N40 search back too: the same
  // result, no alarm.
  Collect out;
  RadiusCompensation trc(out);
  runGroove(trc, CollisionCheck::Cdof, 3);
  expectGrooveBridged(out);
}

TEST(Bottleneck, NoIntersectionWithinMd20240IsAlarm10751) {
  // cdon_bottleneck_check_blocks_2: MD20240 = 2 does not reach from N40 to N10: alarm 10751
  // naming N20 (whose end has no valid intersection); written before it: sel (0,5) and N10 to
  // A = (40,5), the N10/N20 outside corner (its circle belongs to N20 and is not written).
  Collect out;
  RadiusCompensation trc(out);
  try {
    runGroove(trc, CollisionCheck::Cdon, 2);
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.number(), 10751);
    EXPECT_EQ(e.line(), 20);
  }
  ASSERT_EQ(out.blocks.size(), 2u);
  expectRow(out.blocks[0], 5, Motion::G1, 0, 5);
  expectRow(out.blocks[1], 10, Motion::G1, 40, 5);
  EXPECT_TRUE(out.warnings.empty());
}

TEST(Bottleneck, OmittedBlocksKeepTheirApplicateMotion) {
  // cdon_omitted_applicate_g18 in G17 terms: N20 and N30 also move the applicate (to -2, -3);
  // their plane motion is dropped, their applicate motion runs at the intersection (39,5) as
  // rows of their own, in program order (details Q5/Q9).
  Collect out;
  RadiusCompensation trc(out);
  Program p;
  p.trc = test::g41(5);
  p.trc.collision = CollisionCheck::Cdon;
  p.at = {-10, 10, 0};
  trc.motion(p.line(5, 0, 0));
  trc.motion(p.line(10, 40, 0));
  trc.motion(p.line(20, 40, -4, -2));
  trc.motion(p.line(30, 44, -4, -3));
  trc.motion(p.line(40, 44, 20));
  p.trc.mode = core::TrcMode::Off;
  trc.motion(p.line(50, 30, 30));
  trc.flush();
  ASSERT_EQ(out.blocks.size(), 6u);
  expectRow(out.blocks[1], 10, Motion::G1, 39, 5, 0);
  expectRow(out.blocks[2], 20, Motion::G1, 39, 5, -2);
  expectVec(out.blocks[2].start, 39, 5, 0);
  expectRow(out.blocks[3], 30, Motion::G1, 39, 5, -3);
  expectRow(out.blocks[4], 40, Motion::G1, 39, 20, -3);
  expectRow(out.blocks[5], 50, Motion::G1, 30, 30, -3);
  const std::vector<std::pair<int, int>> omitted{{20, 10763}, {30, 10763}};
  EXPECT_EQ(out.warnings, omitted);
}

}  // namespace
}  // namespace ncoffset::trc
