// Sum/setup offset names and how a DL adds to the wear (src/tool/sum_offsets.cpp), and the
// programmed offsets per component (src/tool/programmable_offsets.cpp).
#include "tool/sum_offsets.hpp"

#include <gtest/gtest.h>

#include "tool/programmable_offsets.hpp"

namespace ncoffset::tool {
namespace {

TEST(SumOffsets, NameIsTenTimesDlPlusParameter) {
  SumOffsetName n;
  ASSERT_TRUE(parseSumOffsetName("$TC_SCP13", n));
  EXPECT_FALSE(n.setup);
  EXPECT_EQ(n.dl, 1);
  EXPECT_EQ(n.param, 3);
  ASSERT_TRUE(parseSumOffsetName("$TC_SCP21", n));  // DL1, parameter 11
  EXPECT_EQ(n.dl, 1);
  EXPECT_EQ(n.param, 11);
  ASSERT_TRUE(parseSumOffsetName("$TC_ECP66", n));  // DL6 radius
  EXPECT_TRUE(n.setup);
  EXPECT_EQ(n.dl, 6);
  EXPECT_EQ(n.param, 6);
  for (const char* bad : {"$TC_SCP12", "$TC_SCP22", "$TC_SCP72", "$TC_SCP013", "$TC_SCP",
                          "$TC_SCPX", "$TC_DP13", "$TC_SCP1a"})
    EXPECT_FALSE(parseSumOffsetName(bad, n)) << bad;
}

TEST(SumOffsets, AddToTheWearParameters) {
  SumOffsetMemory m;
  m.forWrite(false, 1, 1, 2)[0] = 0.1;  // $TC_SCP23: L1
  m.forWrite(false, 1, 1, 2)[3] = 0.2;  // $TC_SCP26: R
  m.forWrite(true, 1, 1, 2)[0] = 0.4;   // $TC_ECP23
  EdgeData e;
  e.dp[12] = 1;
  addSumOffsets(e, m, 1, 1, 2, {6, false});
  EXPECT_DOUBLE_EQ(e.dp[12], 1.1);  // setup offsets off (MD18112 bit 4 = 0)
  EXPECT_DOUBLE_EQ(e.dp[15], 0.2);
  addSumOffsets(e, m, 1, 1, 2, {6, true});
  EXPECT_DOUBLE_EQ(e.dp[12], 1.1 + 0.1 + 0.4);
  EXPECT_TRUE(m.exists(1, 1, 2));
  EXPECT_FALSE(m.exists(1, 1, 1));
}

TEST(ProgrammableOffsets, ToffActsOnTheComponentOfItsAxis) {
  ProgrammedOffsets p;
  p.length = {1, 2, 3, 4};  // TOFFL, TOFFL[1..3]
  p.axis = {10, 20, 30};    // TOFF[X], TOFF[Y], TOFF[Z]
  LengthAssignment g17;     // milling G17: L1 Z, L2 Y, L3 X
  const std::array<double, 3> c = programmedComponents(p, g17);
  EXPECT_DOUBLE_EQ(c[0], 1 + 2 + 30);
  EXPECT_DOUBLE_EQ(c[1], 3 + 20);
  EXPECT_DOUBLE_EQ(c[2], 4 + 10);
  const Vec3 v = programmedVector(p, 120, ToolSettings{}, Plane::G17, {false, false, false});
  EXPECT_DOUBLE_EQ(v.z, 33);
  EXPECT_DOUBLE_EQ(v.y, 23);
  EXPECT_DOUBLE_EQ(v.x, 14);
}

}  // namespace
}  // namespace ncoffset::tool
