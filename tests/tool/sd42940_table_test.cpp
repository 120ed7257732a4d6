// Walks tests/programs/tool/sd42940_table.txt: for each tool type, SD42940, SD42950 and plane,
// the offset vector of L1 = 1, L2 = 10, L3 = 100 derived by hand from the tables of spec
// §2.2-2.4 (seed 003, PM-NC p750).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "ncoffset/tool.hpp"

namespace ncoffset {
namespace {

TEST(Sd42940Table, EveryRowOfTheTableFile) {
  std::ifstream in(std::string(NCOFFSET_PROGRAMS) + "/tool/sd42940_table.txt");
  ASSERT_TRUE(in) << "table file missing";
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    int type;
    long sd42940, sd42950;
    std::string plane;
    Vec3 want;
    if (!(ss >> type >> sd42940 >> sd42950 >> plane >> want.x >> want.y >> want.z)) continue;
    Plane p = plane == "G17" ? Plane::G17 : plane == "G18" ? Plane::G18 : Plane::G19;
    EdgeData e;
    e.dp[1] = type;
    e.dp[3] = 1;
    e.dp[4] = 10;
    e.dp[5] = 100;
    ToolSettings s;
    s.length_const = sd42940;
    s.length_type = sd42950;
    Vec3 got = lengthVector(e, s, p, {false, false, false});
    EXPECT_NEAR(got.x, want.x, 1e-9) << line;
    EXPECT_NEAR(got.y, want.y, 1e-9) << line;
    EXPECT_NEAR(got.z, want.z, 1e-9) << line;
    ++rows;
  }
  EXPECT_GE(rows, 200);
}

}  // namespace
}  // namespace ncoffset
