// D-number management, tool environments and grinding chaining of the tool selection alone
// (src/tool/d_numbers.cpp, tool_environment.cpp, grinding.cpp; docs/tool-offsets.md §10-12).
#include <gtest/gtest.h>

#include <vector>

#include "ncoffset/alarm.hpp"
#include "support/alarm_of.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {
namespace {

using lang::Value;

void set(ToolSelection& s, const std::string& name, std::vector<Value> idx, double x) {
  ASSERT_TRUE(s.write(name, idx, true, Value::real(x)));
}

double get(const ToolSelection& s, const std::string& name, std::vector<Value> idx) {
  Value out;
  EXPECT_TRUE(s.read(name, idx, true, Plane::G17, out));
  return out.num;
}

using test::alarmOf;

// Free D numbers: MD18105 = 100 > MD18106 = 3; T5 D51, D52; T7 D71.
ToolSelection freeNumbers() {
  ToolSelection s(32000);
  s.configure({false, 100, 3});
  for (auto [t, d] : {std::pair{5, 51}, {5, 52}, {7, 71}})
    set(s, "$TC_DP1", {Value::integer(t), Value::integer(d)}, 120);
  return s;
}

TEST(DNumbers, CuttingEdgeNumbersCountFromOnePerTool) {
  ToolSelection s = freeNumbers();
  EXPECT_EQ(s.cuttingEdgeNumber(5, 51), 1);
  EXPECT_EQ(s.cuttingEdgeNumber(5, 52), 2);
  EXPECT_EQ(s.cuttingEdgeNumber(7, 71), 1);
  EXPECT_EQ(s.getDNumber(5, 2), 52);
  EXPECT_EQ(s.getDNumber(5, 3), 0);
}

TEST(DNumbers, CollisionsAndRenaming) {
  ToolSelection s = freeNumbers();
  ToolSelection::DCollision c;
  EXPECT_TRUE(s.checkDNumbers(0, 0, 0, c));
  EXPECT_TRUE(s.setDNumber(7, 1, 51));
  EXPECT_FALSE(s.checkDNumbers(0, 0, 0, c));
  EXPECT_EQ(c.t1, 5);
  EXPECT_EQ(c.t2, 7);
  EXPECT_EQ(c.d, 51);
  EXPECT_TRUE(s.checkDNumbers(5, 7, 52, c));   // only D52: no collision
  EXPECT_FALSE(s.setDNumber(5, 2, 51));        // T5 has a D51 already
  EXPECT_FALSE(s.checkDNumbers(99, 0, 0, c));  // no tool 99: FALSE
  int t = 0;
  EXPECT_EQ(s.toolOfDNumber(51, t), -2);
  EXPECT_EQ(t, 5);
  EXPECT_EQ(alarmOf([&] { s.setDNumber(5, 1, 0); }), 12160);
}

TEST(DNumbers, DzeroInvalidatesUntilSetdno) {
  ToolSelection s = freeNumbers();
  s.invalidateDNumbers();
  EXPECT_EQ(s.getDNumber(5, 1), 32051);
  SelectionContext ctx;
  ctx.default_edge = 0;  // MD20270 = 0: T selects no edge
  s.execute({5, std::nullopt, false}, true, ctx);
  EXPECT_EQ(alarmOf([&] { s.execute({std::nullopt, 51, false}, true, ctx); }), 17181);
  EXPECT_TRUE(s.setDNumber(5, 1, 51));
  s.execute({std::nullopt, 51, false}, true, ctx);
  EXPECT_EQ(s.activeEdge(), 51);
}

TEST(DNumbers, EdgesPerToolLimitedByMd18106) {
  ToolSelection s = freeNumbers();
  set(s, "$TC_DP1", {Value::integer(5), Value::integer(53)}, 120);
  EXPECT_EQ(alarmOf([&] {
              set(s, "$TC_DP1", {Value::integer(5), Value::integer(54)}, 120);
            }),
            17030);
}

TEST(DNumbers, FlatNumbersHaveOneIndex) {
  ToolSelection s(32000);
  s.configure({true, 500, 9});
  set(s, "$TC_DP3", {Value::integer(101)}, 80);
  EXPECT_EQ(alarmOf([&] {
              set(s, "$TC_DP3", {Value::integer(1), Value::integer(101)}, 1);
            }),
            17020);
  SelectionContext ctx;
  s.execute({42, 101, false}, true, ctx);  // T42 exists nowhere: no alarm with flat D
  EXPECT_EQ(s.activeEdge(), 101);
  EXPECT_EQ(s.lengths().total[0], 80);
  s.execute({43, std::nullopt, false}, true, ctx);  // T keeps the offset
  EXPECT_EQ(s.activeEdge(), 101);
}

TEST(ToolEnvironments, GettcorComponentsAndStatus) {
  ToolSelection s(32000);
  const std::vector<Value> td{Value::integer(1), Value::integer(1)};
  set(s, "$TC_DP1", td, 120);
  set(s, "$TC_DP3", td, 100);
  set(s, "$TC_DP12", td, -0.5);
  set(s, "$TC_DP21", td, 2);
  SelectionContext ctx;
  s.execute({1, 1, false}, true, ctx);
  ToolEnvironment env = s.currentEnvironment({}, Plane::G17, {}, Mat3::identity());
  std::vector<Value> len(11);
  EXPECT_EQ(s.toolCorrection(len, "G", env), 0);
  EXPECT_EQ(len[4].num, 100);
  EXPECT_EQ(s.toolCorrection(len, "g w c", env), 0);
  EXPECT_EQ(len[4].num, 101.5);
  EXPECT_EQ(s.toolCorrection(len, "GCG", env), -3);
  EXPECT_EQ(s.toolCorrection(len, "G:X", env), -9);
  env.d = 3;
  EXPECT_EQ(s.toolCorrection(len, "G", env), -5);
}

TEST(Grinding, Tpg2ChainsTheWheelEdges) {
  ToolSelection s(32000);
  const std::vector<Value> d1{Value::integer(1), Value::integer(1)},
      d2{Value::integer(1), Value::integer(2)};
  set(s, "$TC_DP1", d1, 403);
  set(s, "$TC_DP1", d2, 403);
  set(s, "$TC_TPG2", {Value::integer(1)}, 1 << 11);  // $TC_DP12
  set(s, "$TC_DP12", d1, -0.4);
  set(s, "$TC_DP13", d1, 0.1);
  EXPECT_EQ(get(s, "$TC_DP12", d2), -0.4);
  EXPECT_EQ(get(s, "$TC_DP13", d2), 0);
  set(s, "$TC_DP12", d2, -0.6);
  EXPECT_EQ(get(s, "$TC_DP12", d1), -0.6);
  EXPECT_EQ(alarmOf([&] { set(s, "$TC_TPG9", {Value::integer(1)}, 7); }), 12160);
}

}  // namespace
}  // namespace ncoffset::tool
