// Data-driven check of the length-component assignment (spec §2.2-2.4, seed 003, PM-NC p750):
// every row of both SD42940 tables in all three planes, the default tables of both tool
// classes, invalid and negative values, the hundreds digit, and SD42950 0/1/2/other. Each row
// checks the offset vector of L1 = 1, L2 = 10, L3 = 100 numerically.
#include <gtest/gtest.h>

#include "ncoffset/tool.hpp"

namespace ncoffset {
namespace {

struct Row {
  int type;
  long sd42940;
  long sd42950;
  Plane plane;
  Vec3 expected;  // offset of L1=1, L2=10, L3=100 on X, Y, Z
};

// Helpers: which axis gets L1, L2, L3.
constexpr int X = 0, Y = 1, Z = 2;
Vec3 place(int a1, int a2, int a3, double s2 = 1) {
  Vec3 v;
  v[a1] += 1;
  v[a2] += 10 * s2;
  v[a3] += 100;
  return v;
}

std::vector<Row> rows() {
  std::vector<Row> r;
  const Plane planes[] = {Plane::G17, Plane::G18, Plane::G19};
  // Default tables (SD42940 = 0): milling L1 applicate, L2 ordinate, L3 abscissa.
  r.push_back({120, 0, 0, Plane::G17, place(Z, Y, X)});
  r.push_back({120, 0, 0, Plane::G18, place(Y, X, Z)});
  r.push_back({120, 0, 0, Plane::G19, place(X, Z, Y)});
  // Turning/grinding: L1 ordinate, L2 abscissa, L3 applicate.
  for (int type : {400, 500, 599}) {
    r.push_back({type, 0, 0, Plane::G17, place(Y, X, Z)});
    r.push_back({type, 0, 0, Plane::G18, place(X, Z, Y)});
    r.push_back({type, 0, 0, Plane::G19, place(Z, Y, X)});
  }
  // Boundaries of the tool classes: 399 and 600 are "other tools".
  r.push_back({399, 0, 0, Plane::G18, place(Y, X, Z)});
  r.push_back({600, 0, 0, Plane::G18, place(Y, X, Z)});
  for (Plane p : planes) {
    // Turning table.
    r.push_back({500, 17, 0, p, place(Y, X, Z)});
    r.push_back({500, 18, 0, p, place(X, Z, Y)});
    r.push_back({500, 19, 0, p, place(Z, Y, X)});
    r.push_back({500, -17, 0, p, place(X, Y, Z)});
    r.push_back({500, -18, 0, p, place(Z, X, Y)});
    r.push_back({500, -19, 0, p, place(Y, Z, X)});
    r.push_back({500, 5, 0, p, place(X, Z, Y)});  // any other value -> 18
    r.push_back({500, -5, 0, p, place(X, Z, Y)});
    r.push_back({500, 20, 0, p, place(X, Z, Y)});
    // Other tools.
    r.push_back({120, 17, 0, p, place(Z, Y, X)});
    r.push_back({120, 18, 0, p, place(Y, X, Z)});
    r.push_back({120, 19, 0, p, place(X, Z, Y)});
    r.push_back({120, -17, 0, p, place(Z, X, Y)});
    r.push_back({120, -18, 0, p, place(Y, Z, X)});
    r.push_back({120, -19, 0, p, place(X, Y, Z)});
    r.push_back({120, 5, 0, p, place(Z, Y, X)});  // any other value -> 17
    r.push_back({120, 99, 0, p, place(Z, Y, X)});
    // Hundreds digit 1: the sign of L2 is inverted (details §3 decoding).
    r.push_back({120, 117, 0, p, place(Z, Y, X, -1)});
    r.push_back({120, -118, 0, p, place(Y, Z, X, -1)});
    r.push_back({500, 119, 0, p, place(Z, Y, X, -1)});
    r.push_back({120, 105, 0, p, place(Z, Y, X, -1)});
    r.push_back({120, 1117, 0, p, place(Z, Y, X, -1)});
    r.push_back({120, 1017, 0, p, place(Z, Y, X)});  // thousands digit: orientation only
  }
  // SD42950: 1 = always milling, 2 = always turning, other values = 0 (by type).
  r.push_back({500, 0, 1, Plane::G17, place(Z, Y, X)});
  r.push_back({120, 0, 2, Plane::G17, place(Y, X, Z)});  // 808D PM p83: G17 L1 Y, L2 X
  r.push_back({120, 0, 2, Plane::G18, place(X, Z, Y)});  // G18 L1 X, L2 Z
  r.push_back({120, 0, 2, Plane::G19, place(Z, Y, X)});  // G19 L1 Z, L2 Y
  r.push_back({120, 0, 3, Plane::G17, place(Z, Y, X)});
  r.push_back({500, 0, -1, Plane::G18, place(X, Z, Y)});
  r.push_back({120, 18, 2, Plane::G17, place(X, Z, Y)});  // SD42950 decides the table
  return r;
}

TEST(LengthAssignment, EveryTableRow) {
  for (const Row& row : rows()) {
    EdgeData e;
    e.dp[1] = row.type;
    e.dp[3] = 1;
    e.dp[4] = 10;
    e.dp[5] = 100;
    ToolSettings s;
    s.length_const = row.sd42940;
    s.length_type = row.sd42950;
    Vec3 v = lengthVector(e, s, row.plane, {false, false, false});
    SCOPED_TRACE(testing::Message()
                 << "type " << row.type << " SD42940 " << row.sd42940 << " SD42950 " << row.sd42950
                 << " plane G" << 17 + static_cast<int>(row.plane));
    EXPECT_NEAR(v.x, row.expected.x, 1e-9);
    EXPECT_NEAR(v.y, row.expected.y, 1e-9);
    EXPECT_NEAR(v.z, row.expected.z, 1e-9);
  }
}

TEST(LengthAssignment, SeedExampleMillingG17) {
  // Seed 000: milling tool with G17: L1 in Z (applicate), L2 in Y, L3 in X.
  LengthAssignment a = assignLengths(120, Plane::G17, 0, 0);
  EXPECT_EQ(a.axis[0], Z);
  EXPECT_EQ(a.axis[1], Y);
  EXPECT_EQ(a.axis[2], X);
}

// Spec §2.7 worked numbers A-O.
TEST(EffectiveLengths, WorkedCasesAtoN) {
  EdgeData a;
  a.dp[1] = 120;
  a.dp[3] = 100;
  a.dp[12] = 0.5;
  a.dp[21] = 10;
  ToolSettings s;
  const std::array<bool, 3> none{false, false, false};
  auto expectVec = [](Vec3 v, Vec3 w) {
    EXPECT_NEAR(v.x, w.x, 1e-9);
    EXPECT_NEAR(v.y, w.y, 1e-9);
    EXPECT_NEAR(v.z, w.z, 1e-9);
  };
  expectVec(lengthVector(a, s, Plane::G17, none), {0, 0, 110.5});  // A
  expectVec(lengthVector(a, s, Plane::G18, none), {0, 110.5, 0});  // B
  expectVec(lengthVector(a, s, Plane::G19, none), {110.5, 0, 0});  // C
  EdgeData d;
  d.dp[1] = 120;
  d.dp[3] = 100;
  d.dp[4] = 20;
  d.dp[5] = 5;
  expectVec(lengthVector(d, s, Plane::G17, none), {5, 20, 100});  // D
  expectVec(lengthVector(d, s, Plane::G18, none), {20, 100, 5});  // E
  expectVec(lengthVector(d, s, Plane::G19, none), {100, 5, 20});  // F
  EdgeData g;
  g.dp[1] = 500;
  g.dp[3] = 30;
  g.dp[4] = 50;
  expectVec(lengthVector(g, s, Plane::G18, none), {30, 0, 50});  // G
  expectVec(lengthVector(g, s, Plane::G17, none), {50, 30, 0});  // H
  expectVec(lengthVector(g, s, Plane::G19, none), {0, 50, 30});  // I
  ToolSettings j;
  j.length_const = 18;
  expectVec(lengthVector(g, j, Plane::G17, none), {30, 0, 50});  // J
  ToolSettings k;
  k.length_const = -17;
  expectVec(lengthVector(d, k, Plane::G18, none), {20, 5, 100});  // K
  ToolSettings l;
  l.length_type = 2;
  expectVec(lengthVector(d, l, Plane::G17, none), {20, 100, 5});  // L
  EdgeData m = g;
  m.dp[2] = 3;
  m.dp[12] = 0.2;
  m.dp[13] = 0.1;
  ToolSettings ms;
  ms.wear_sign_cutpos = true;
  expectVec(lengthVector(m, ms, Plane::G18, none), {29.8, 0, 49.9});  // M
  ToolSettings n;
  n.wear_sign = true;
  expectVec(lengthVector(a, n, Plane::G17, none), {0, 0, 109.5});  // N
  ToolSettings o;
  o.mirror_length = true;
  expectVec(lengthVector(a, o, Plane::G17, {false, false, true}), {0, 0, -109.5});  // O
}

TEST(EffectiveLengths, WearSignByCuttingEdgePosition) {
  // SD42920 table (FM 828D p1547): wear L1 inverted for SL 3, 4, 8; wear L2 for SL 2, 3, 7.
  const int l1_inverted[10] = {0, 0, 0, 1, 1, 0, 0, 0, 1, 0};
  const int l2_inverted[10] = {0, 0, 1, 1, 0, 0, 0, 1, 0, 0};
  for (int sl = 1; sl <= 9; ++sl) {
    EdgeData e;
    e.dp[1] = 500;
    e.dp[2] = sl;
    e.dp[12] = 1;
    e.dp[13] = 1;
    ToolSettings s;
    s.wear_sign_cutpos = true;
    EffectiveLengths l = effectiveLengths(e, s);
    EXPECT_EQ(l.wear[0], l1_inverted[sl] ? -1 : 1) << "SL " << sl;
    EXPECT_EQ(l.wear[1], l2_inverted[sl] ? -1 : 1) << "SL " << sl;
    // SD42900 with a mirrored axis cancels an SD42920 inversion only for geometry: wear
    // needs SD42910 (T-WEAR-3: SD42910 and SD42920 together cancel).
    s.mirror_wear = true;
    Vec3 v = lengthVector(e, s, Plane::G18, {true, false, true});
    EXPECT_EQ(v.x, l1_inverted[sl] ? 1 : -1) << "SL " << sl;
    EXPECT_EQ(v.z, l2_inverted[sl] ? 1 : -1) << "SL " << sl;
  }
  // Milling tools are not affected by SD42920.
  EdgeData mill;
  mill.dp[1] = 120;
  mill.dp[2] = 3;
  mill.dp[12] = 1;
  ToolSettings s;
  s.wear_sign_cutpos = true;
  EXPECT_EQ(effectiveLengths(mill, s).wear[0], 1);
}

TEST(EffectiveLengths, RadiusAndWearSign) {
  EdgeData e;
  e.dp[6] = 5;
  e.dp[15] = 0.2;
  EXPECT_NEAR(effectiveLengths(e, {}).radius, 5.2, 1e-12);
  ToolSettings s;
  s.wear_sign = true;
  EXPECT_NEAR(effectiveLengths(e, s).radius, 4.8, 1e-12);
}

}  // namespace
}  // namespace ncoffset

namespace ncoffset {
namespace {

TEST(CuttingEdgePosition, TipFromCentreTable) {
  // Spec §7 table, r = 0.8.
  const double want[10][2] = {{0, 0},  {.8, .8}, {.8, -.8}, {-.8, -.8}, {-.8, .8},
                              {0, .8}, {.8, 0},  {0, -.8},  {-.8, 0},   {0, 0}};
  for (int sl = 0; sl <= 9; ++sl) {
    auto p = tipFromEdgeCentre(sl, 0.8);
    EXPECT_DOUBLE_EQ(p[0], want[sl][0]) << "SL " << sl;
    EXPECT_DOUBLE_EQ(p[1], want[sl][1]) << "SL " << sl;
  }
  // Consistent with SD42920: wear L1 inverted exactly where P-S is negative along L1.
  for (int sl = 1; sl <= 9; ++sl) {
    EdgeData e;
    e.dp[1] = 500;
    e.dp[2] = sl;
    e.dp[12] = 1;
    e.dp[13] = 1;
    ToolSettings s;
    s.wear_sign_cutpos = true;
    EffectiveLengths l = effectiveLengths(e, s);
    auto p = tipFromEdgeCentre(sl, 1);
    EXPECT_EQ(l.wear[0] < 0, p[0] < 0) << "SL " << sl;
    EXPECT_EQ(l.wear[1] < 0, p[1] < 0) << "SL " << sl;
  }
}

TEST(CuttingEdgePosition, TipVectorOnTheAxesOfL1AndL2) {
  // docs/cutting-edge-positions.md: P - S along the axes of L1 and L2 in the plane.
  EdgeData e;
  e.dp[1] = 500;
  e.dp[2] = 3;  // (-R along L1, -R along L2)
  const ToolSettings s;
  const Vec3 g18 = tipVector(e, s, Plane::G18, 0.8);  // L1 -> X, L2 -> Z
  EXPECT_DOUBLE_EQ(g18.x, -0.8);
  EXPECT_DOUBLE_EQ(g18.y, 0);
  EXPECT_DOUBLE_EQ(g18.z, -0.8);
  e.dp[2] = 1;
  const Vec3 g17 = tipVector(e, s, Plane::G17, 0.8);  // L1 -> Y, L2 -> X
  EXPECT_DOUBLE_EQ(g17.x, 0.8);
  EXPECT_DOUBLE_EQ(g17.y, 0.8);
  EXPECT_DOUBLE_EQ(g17.z, 0);
  e.dp[2] = 6;
  const Vec3 g19 = tipVector(e, s, Plane::G19, 0.8);  // L1 -> Z, L2 -> Y
  EXPECT_DOUBLE_EQ(g19.x, 0);
  EXPECT_DOUBLE_EQ(g19.y, 0);
  EXPECT_DOUBLE_EQ(g19.z, 0.8);
}

TEST(CuttingEdgePosition, NoTipForSl9Sl0OrMillingTools) {
  EdgeData e;
  e.dp[1] = 500;
  for (int sl : {0, 9}) {
    e.dp[2] = sl;
    const Vec3 v = tipVector(e, {}, Plane::G18, 0.8);
    EXPECT_EQ(v.x, 0);
    EXPECT_EQ(v.z, 0);
  }
  e.dp[1] = 120;  // an end mill: $TC_DP2 has no meaning
  e.dp[2] = 3;
  const Vec3 v = tipVector(e, {}, Plane::G18, 5);
  EXPECT_EQ(v.x, 0);
  EXPECT_EQ(v.y, 0);
  EXPECT_EQ(v.z, 0);
  e.dp[1] = 400;  // grinding tools have positions too (W1: types 400..599)
  EXPECT_DOUBLE_EQ(tipVector(e, {}, Plane::G18, 1).x, -1);
}

}  // namespace
}  // namespace ncoffset
