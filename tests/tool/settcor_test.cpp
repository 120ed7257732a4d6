// SETTCOR's parameter checks (src/tool/settcor.cpp) and its writing against GETTCOR's reading
// (src/tool/tool_environment_write.cpp, tool_environment.cpp): docs/tool-offsets.md 14a.
#include "tool/settcor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/alarm_of.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {
namespace {

using lang::Value;
using test::alarmOf;

TEST(Settcor, ComponentsOneOrTwoLettersAnyCaseWithBlanks) {
  SettcorComponents c;
  ASSERT_EQ(parseSettcorComponents("G", c), 0);
  EXPECT_EQ(c.count, 1);
  EXPECT_EQ(c.val1, ToolComponent::Geometry);
  EXPECT_FALSE(c.tool_coords);
  ASSERT_EQ(parseSettcorComponents(" w\tg ", c), 0);
  EXPECT_EQ(c.count, 2);
  EXPECT_EQ(c.val1, ToolComponent::Wear);
  EXPECT_EQ(c.val2, ToolComponent::Geometry);
  ASSERT_EQ(parseSettcorComponents("e:t", c), 0);  // PM-JP 12/2019: ":T" the TCS
  EXPECT_EQ(c.val1, ToolComponent::Setup);
  EXPECT_TRUE(c.tool_coords);
  ASSERT_EQ(parseSettcorComponents("S:W", c), 0);
  EXPECT_FALSE(c.tool_coords);
  ASSERT_EQ(parseSettcorComponents("C:", c), 0);  // an empty second substring is the WCS
  EXPECT_EQ(c.val1, ToolComponent::Base);
}

TEST(Settcor, BadComponentStringsAreStatusMinus3) {
  SettcorComponents c;
  for (const char* bad : {"", " ", ":", ":W", "GX", "GG", "gG", "GWS", "G:Q", "G:WT", "G:M", "1"})
    EXPECT_EQ(parseSettcorComponents(bad, c), -3) << '"' << bad << '"';
}

TEST(Settcor, CorcompAndCormodeRanges) {
  for (int cc = 0; cc <= 11; ++cc) EXPECT_EQ(checkSettcorModes(cc, 0), 0) << cc;
  EXPECT_EQ(checkSettcorModes(-1, 0), -9);
  EXPECT_EQ(checkSettcorModes(12, 0), -9);
  EXPECT_EQ(checkSettcorModes(0, -1), -10);
  EXPECT_EQ(checkSettcorModes(0, 100), -10);
  EXPECT_EQ(checkSettcorModes(0, 99), 0);
  SettcorComponents one, two;
  ASSERT_EQ(parseSettcorComponents("G", one), 0);
  ASSERT_EQ(parseSettcorComponents("GW", two), 0);
  EXPECT_TRUE(settcorModelled(one, 0));
  EXPECT_TRUE(settcorModelled(one, 1));
  EXPECT_FALSE(settcorModelled(one, 2));
  EXPECT_FALSE(settcorModelled(one, 10));
  EXPECT_FALSE(settcorModelled(two, 0));
}

void setEdge(ToolSelection& s, int t, int d, int n, double x) {
  std::vector<Value> idx{Value::integer(t), Value::integer(d)};
  ASSERT_TRUE(s.write("$TC_DP" + std::to_string(n), idx, true, Value::real(x)));
}

double edgeParam(const ToolSelection& s, int t, int d, int n) {
  return s.store().edge(t, d)->dp[static_cast<size_t>(n)];
}

// One SETTCOR call's parameters (built whole: GCC 12 warns wrongly on assigning the string).
SettcorRequest req(const char* comp, int corcomp, int cormode, std::array<double, 3> v,
                   int geoax = -1) {
  return SettcorRequest{v, comp, corcomp, cormode, geoax};
}

// A rotated and mirrored environment: what SETTCOR writes as a WCS vector GETTCOR reads back.
TEST(Settcor, WcsVectorRoundTripsThroughGettcor) {
  ToolSelection s(100);
  setEdge(s, 1, 1, 1, 500);  // turning tool: G18 L1 on X, L2 on Z
  setEdge(s, 1, 1, 2, 3);
  setEdge(s, 1, 1, 3, 30);
  setEdge(s, 1, 1, 12, 0.4);
  ToolEnvironment env;
  env.plane = Plane::G18;
  env.settings.mirror_length = true;
  env.settings.mirror_wear = true;
  env.settings.wear_sign = true;
  env.mirrored = {true, false, false};
  const double c = std::cos(0.5), sn = std::sin(0.5);
  env.orientation.m = {{{c, -sn, 0}, {sn, c, 0}, {0, 0, -1}}};  // a rotation and a mirror
  env.t = 1, env.d = 1;
  struct Case {
    const char* comp;
    const char* read;  // GETTCOR's _COMP: the same component in the WCS
  };
  for (const Case& k : {Case{"G", "G:W"}, Case{"W", "W:W"}}) {
    ASSERT_EQ(s.setToolCorrection(req(k.comp, 1, 0, {1.5, -2.25, 7}), env), 0) << k.comp;
    std::vector<Value> len(11);
    ASSERT_EQ(s.toolCorrection(len, k.read, env), 0);
    EXPECT_NEAR(len[2].num, 1.5, 1e-12) << k.comp;  // abscissa, ordinate, applicate of G18
    EXPECT_NEAR(len[3].num, -2.25, 1e-12) << k.comp;
    EXPECT_NEAR(len[4].num, 7, 1e-12) << k.comp;
    // Add 0.5 along Z, the abscissa of G18.
    ASSERT_EQ(s.setToolCorrection(req(k.comp, 0, 1, {0.5, 0, 0}, 2), env), 0);
    ASSERT_EQ(s.toolCorrection(len, k.read, env), 0);
    EXPECT_NEAR(len[2].num, 2.0, 1e-12) << k.comp;
    EXPECT_NEAR(len[3].num, -2.25, 1e-12) << k.comp;
  }
}

TEST(Settcor, ToolComponentsIgnoreTheFrameAndTheSignRules) {
  ToolSelection s(100);
  setEdge(s, 1, 1, 1, 120);
  setEdge(s, 1, 1, 3, 100);
  ToolEnvironment env;
  env.settings.wear_sign = true;
  env.orientation.m = {{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}};
  env.t = 1, env.d = 1;
  ASSERT_EQ(s.setToolCorrection(req("W", 2, 0, {0.1, 0.2, 0.3}), env), 0);
  EXPECT_EQ(edgeParam(s, 1, 1, 12), 0.1);
  EXPECT_EQ(edgeParam(s, 1, 1, 13), 0.2);
  EXPECT_EQ(edgeParam(s, 1, 1, 14), 0.3);
  // _CORCOMP 9: $TC_DP18 (the wear of $TC_DP9), added twice.
  ASSERT_EQ(s.setToolCorrection(req("W", 9, 1, {2, 0, 0}), env), 0);
  ASSERT_EQ(s.setToolCorrection(req("W", 9, 1, {2, 0, 0}), env), 0);
  EXPECT_EQ(edgeParam(s, 1, 1, 18), 4);
  // The base dimension has L1..L3 only.
  ASSERT_EQ(s.setToolCorrection(req("C", 5, 0, {2, 0, 0}), env), 0);
  EXPECT_EQ(edgeParam(s, 1, 1, 23), 2);
  EXPECT_EQ(s.setToolCorrection(req("C", 6, 0, {2, 0, 0}), env), -3);
}

TEST(Settcor, StatusOfTheEdgeAndTheAlarms) {
  ToolSelection s(100);
  setEdge(s, 1, 1, 1, 120);
  ToolEnvironment env;
  env.t = 1, env.d = 1;
  EXPECT_EQ(s.setToolCorrection(req("G", 0, 0, {1, 0, 0}), env), -13);  // no _GEOAX
  const SettcorRequest l1 = req("G", 3, 0, {1, 0, 0});
  env.t = 2;
  EXPECT_EQ(s.setToolCorrection(l1, env), -4);
  env.t = 1, env.d = 0;
  EXPECT_EQ(s.setToolCorrection(l1, env), -5);
  env.d = 10;  // above MD18105
  EXPECT_EQ(s.setToolCorrection(l1, env), -5);
  env.d = 1, env.dl = 7;  // above MD18110
  EXPECT_EQ(s.setToolCorrection(l1, env), -6);
  env.dl = 0;
  EXPECT_EQ(s.setToolCorrection(req("E", 3, 0, {1, 0, 0}), env), -14);
  EXPECT_EQ(s.setToolCorrection(req("S", 3, 0, {1, 0, 0}), env), -6);
  EXPECT_EQ(alarmOf([&] { s.setToolCorrection(req("G", 3, 0, {2e9, 0, 0}), env); }), 12160);
  EXPECT_EQ(edgeParam(s, 1, 1, 3), 0);  // nothing written
  EXPECT_EQ(alarmOf([&] { s.setToolCorrection(req("G", 3, 2, {1, 0, 0}), env); }), 99010);
  EXPECT_EQ(alarmOf([&] { s.setToolCorrection(req("GW", 3, 0, {1, 0, 0}), env); }), 99010);
}

// Flat D numbers (MD18102 = 1): the edge is $TC_DPx[d], the T does not matter.
TEST(Settcor, FlatDNumbersWriteTheOneTable) {
  ToolSelection s(100);
  DNumberConfig flat;
  flat.flat = true;
  s.configure(flat);
  std::vector<Value> idx{Value::integer(3)};
  ASSERT_TRUE(s.write("$TC_DP1", idx, true, Value::real(120)));
  ToolEnvironment env;
  env.t = 7, env.d = 3;
  ASSERT_EQ(s.setToolCorrection(req("G", 3, 1, {12.5, 0, 0}), env), 0);
  Value out;
  ASSERT_TRUE(s.read("$TC_DP3", idx, true, Plane::G17, out));
  EXPECT_EQ(out.num, 12.5);
  env.d = 4;
  EXPECT_EQ(s.setToolCorrection(req("G", 3, 1, {12.5, 0, 0}), env), -5);
}

}  // namespace
}  // namespace ncoffset::tool
