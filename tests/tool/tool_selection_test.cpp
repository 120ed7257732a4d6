// The tool selection alone (src/tool/tool_selection.hpp): T/D/M6 per MD22550 and MD20270, the
// offset memory written as $TC_DP.., and what the active edge gives the path.
#include "tool/tool_selection.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "ncoffset/alarm.hpp"
#include "support/alarm_of.hpp"

namespace ncoffset::tool {
namespace {

using lang::Value;

void setEdge(ToolSelection& s, int t, int d, int n, double x) {
  std::vector<Value> idx{Value::integer(t), Value::integer(d)};
  ASSERT_TRUE(s.write("$TC_DP" + std::to_string(n), idx, true, Value::real(x)));
}

// T1 D1: a milling tool (type 120) of length 100 and radius 5; D2 radius 3.
ToolSelection millingTool() {
  ToolSelection s(32000);
  setEdge(s, 1, 1, 1, 120);
  setEdge(s, 1, 1, 3, 100);
  setEdge(s, 1, 1, 6, 5);
  setEdge(s, 1, 2, 1, 120);
  setEdge(s, 1, 2, 6, 3);
  return s;
}

using test::alarmOf;

TEST(ToolSelection, TChangesTheToolAndTheDefaultEdgeIsSelected) {
  ToolSelection s = millingTool();
  SelectionContext ctx;  // MD20270 = 1
  s.execute({1, std::nullopt, false}, true, ctx);
  EXPECT_EQ(s.activeTool(), 1);
  EXPECT_EQ(s.activeEdge(), 1);
  EXPECT_EQ(s.radius(), 5);
  // G17: L1 acts in Z (spec §2.2).
  Vec3 l = s.lengthVector(Plane::G17);
  EXPECT_EQ(l.z, 100);
  EXPECT_EQ(l.x, 0);
  s.execute({std::nullopt, 2, false}, true, ctx);
  EXPECT_EQ(s.radius(), 3);
}

TEST(ToolSelection, WithMd22550TPreselectsAndM6Changes) {
  ToolSelection s = millingTool();
  SelectionContext ctx;
  s.execute({1, std::nullopt, false}, false, ctx);
  EXPECT_EQ(s.activeTool(), 0);
  Value p;
  ASSERT_TRUE(s.read("$P_TOOLP", {}, false, Plane::G17, p));
  EXPECT_EQ(p.num, 1);
  s.execute({std::nullopt, std::nullopt, true}, false, ctx);
  EXPECT_EQ(s.activeTool(), 1);
  EXPECT_EQ(s.activeEdge(), 1);
}

TEST(ToolSelection, DataActFromTheNextSelection) {
  ToolSelection s = millingTool();
  SelectionContext ctx;
  s.execute({1, 1, false}, true, ctx);
  setEdge(s, 1, 1, 6, 7);  // W1 2.5: a changed radius acts with the next D
  EXPECT_EQ(s.radius(), 5);
  s.execute({std::nullopt, 1, false}, true, ctx);
  EXPECT_EQ(s.radius(), 7);
}

TEST(ToolSelection, MissingToolAndEdgeGiveTheControlsAlarms) {
  ToolSelection s = millingTool();
  SelectionContext ctx;
  EXPECT_EQ(alarmOf([&] {
              s.execute({2, std::nullopt, false}, true, ctx);
            }),
            toInt(AlarmNumber::ToolNotExisting));
  s.execute({1, std::nullopt, false}, true, ctx);
  EXPECT_EQ(alarmOf([&] {
              s.execute({std::nullopt, 3, false}, true, ctx);
            }),
            toInt(AlarmNumber::EdgeNotExisting));
}

TEST(ToolSelection, NoEdgeMeansNoOffset) {
  ToolSelection s = millingTool();
  SelectionContext ctx;
  ctx.default_edge = 0;  // MD20270 = 0
  s.execute({1, std::nullopt, false}, true, ctx);
  EXPECT_FALSE(s.hasEdge());
  EXPECT_EQ(s.radius(), 0);
  EXPECT_EQ(s.lengthVector(Plane::G17).z, 0);
  EXPECT_EQ(s.orientation(Plane::G18).y, 1);  // without an edge: the plane's applicate
}

TEST(ToolSelection, TurningEdgeGivesPMinusSPerPlane) {
  // docs/cutting-edge-positions.md: type 500, SL3, R 0.8 -> (-0.8 along L1, -0.8 along L2).
  ToolSelection s(32000);
  setEdge(s, 1, 1, 1, 500);
  setEdge(s, 1, 1, 2, 3);
  setEdge(s, 1, 1, 3, 100);
  setEdge(s, 1, 1, 4, 50);
  setEdge(s, 1, 1, 6, 0.8);
  setEdge(s, 1, 2, 1, 500);  // D2: SL 9, P = S
  setEdge(s, 1, 2, 2, 9);
  setEdge(s, 1, 2, 6, 0.8);
  SelectionContext ctx;
  s.execute({1, 1, false}, true, ctx);
  ASSERT_TRUE(s.hasTip());
  Vec3 g18 = s.tipVector(Plane::G18);  // L1 -> X, L2 -> Z
  EXPECT_DOUBLE_EQ(g18.x, -0.8);
  EXPECT_DOUBLE_EQ(g18.z, -0.8);
  EXPECT_EQ(s.lengthVector(Plane::G18).x, 100);
  Vec3 g17 = s.tipVector(Plane::G17);  // L1 -> Y, L2 -> X: the cache follows the plane
  EXPECT_DOUBLE_EQ(g17.x, -0.8);
  EXPECT_DOUBLE_EQ(g17.y, -0.8);
  EXPECT_EQ(g17.z, 0);
  EXPECT_EQ(s.lengthVector(Plane::G17).y, 100);
  s.execute({std::nullopt, 2, false}, true, ctx);
  EXPECT_FALSE(s.hasTip());
  EXPECT_EQ(s.tipVector(Plane::G18).x, 0);
  s.execute({std::nullopt, 0, false}, true, ctx);  // D0: no edge
  EXPECT_FALSE(s.hasTip());
}

TEST(ToolSelection, MillingEdgeHasNoTip) {
  ToolSelection s = millingTool();
  setEdge(s, 1, 1, 2, 3);  // a cutting edge position on an end mill means nothing
  s.execute({1, std::nullopt, false}, true, SelectionContext{});
  EXPECT_FALSE(s.hasTip());
}

}  // namespace
}  // namespace ncoffset::tool
