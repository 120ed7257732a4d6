// Basic tool orientation (spec §4, seed 004) and LENTOAX (seed 000, spec §3, details §1).
#include <gtest/gtest.h>

#include "ncoffset/frame.hpp"
#include "ncoffset/tool.hpp"

namespace ncoffset {
namespace {

const std::array<bool, 3> kNone{false, false, false};

void expectVec(Vec3 v, Vec3 w) {
  EXPECT_NEAR(v.x, w.x, 1e-9);
  EXPECT_NEAR(v.y, w.y, 1e-9);
  EXPECT_NEAR(v.z, w.z, 1e-9);
}

TEST(Orientation, CodedValuesFollowTheTable) {
  // Milling G17: 1=+Z 2=+Y 3=+X 4=-Z 5=-Y 6=-X; turning G18: 1=+Y 2=+Z 3=+X 4=-Y 5=-Z 6=-X.
  const Vec3 milling[] = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0, -1, 0}, {-1, 0, 0}};
  const Vec3 turning[] = {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {-1, 0, 0}};
  for (int v = 1; v <= 6; ++v) {
    EdgeData m;
    m.dp[1] = 120;
    m.dpv = v;
    expectVec(toolOrientation(m, {}, Plane::G17, kNone), milling[v - 1]);
    EdgeData t;
    t.dp[1] = 500;
    t.dpv = v;
    expectVec(toolOrientation(t, {}, Plane::G18, kNone), turning[v - 1]);
  }
}

TEST(Orientation, VectorFromDpv3To5) {
  // T-ORI-2: DPV3=1, DPV5=1 (L1 and L3), milling G17 -> (1,0,1)/sqrt 2.
  EdgeData e;
  e.dp[1] = 120;
  e.dpv3 = 1;
  e.dpv5 = 1;
  double h = 1 / std::sqrt(2.0);
  expectVec(toolOrientation(e, {}, Plane::G17, kNone), {h, 0, h});
}

TEST(Orientation, PlaneChangeRotatesUnlessSd42940) {
  // Seed 004: G17 -> G18 is the cyclic permutation (x,y,z) -> new X = old Y, Y = Z, Z = X.
  EdgeData e;
  e.dp[1] = 120;
  e.dpv = 2;  // +Y in G17
  expectVec(toolOrientation(e, {}, Plane::G18, kNone), {1, 0, 0});
  expectVec(toolOrientation(e, {}, Plane::G19, kNone), {0, 0, 1});
  ToolSettings s;
  s.length_const = 17;
  expectVec(toolOrientation(e, s, Plane::G18, kNone), {0, 1, 0});
  // Without orientation data: the applicate of the plane.
  EdgeData plain;
  plain.dp[1] = 120;
  expectVec(toolOrientation(plain, {}, Plane::G18, kNone), {0, 1, 0});
  // Thousands digit: orientation from the table's plane (17: milling along Z).
  ToolSettings th;
  th.length_const = 1017;
  expectVec(toolOrientation(plain, th, Plane::G18, kNone), {0, 0, 1});
  // SD42950 = 2 treats a milling tool as a turning tool (home plane G18).
  EdgeData coded;
  coded.dp[1] = 120;
  coded.dpv = 1;
  ToolSettings turn;
  turn.length_type = 2;
  expectVec(toolOrientation(coded, turn, Plane::G18, kNone), {0, 1, 0});
  // SD42900 mirrors like lengths.
  ToolSettings mir;
  mir.mirror_length = true;
  expectVec(toolOrientation(coded, mir, Plane::G17, {false, false, true}), {0, 0, -1});
}

LentoaxResult run(const EdgeData& e, ToolSettings s, Plane p, const Frame& f,
                  const std::string& coord = "WCS") {
  return lentoax(e, s, p, f.mirror, f.affine().linear, coord);
}

EdgeData mill() {
  EdgeData e;
  e.dp[1] = 120;
  e.dp[3] = 100;
  return e;
}

TEST(Lentoax, StandardMillingG17) {
  LentoaxResult r = run(mill(), {}, Plane::G17, Frame{});
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.axind, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(r.matrix[0][2], 1);
  EXPECT_EQ(r.matrix[1][1], 1);
  EXPECT_EQ(r.matrix[2][0], 1);
}

TEST(Lentoax, PlaneChangeKeepsResult) {
  EXPECT_EQ(run(mill(), {}, Plane::G18, Frame{}).axind, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(run(mill(), {}, Plane::G19, Frame{}).axind, (std::array<int, 3>{3, 2, 1}));
}

TEST(Lentoax, RotZ60) {
  Frame f;
  f.rotation = {0, 0, 60};
  LentoaxResult r = run(mill(), {}, Plane::G17, f);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.axind, (std::array<int, 3>{2, -3, 1}));
  EXPECT_NEAR(r.matrix[0][1], std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(r.matrix[0][2], 0.5, 1e-12);
  EXPECT_NEAR(r.matrix[1][2], -std::sqrt(3.0) / 2, 1e-12);
  // BCS ignores the frame (L-15).
  EXPECT_EQ(run(mill(), {}, Plane::G17, f, "bcs").axind, (std::array<int, 3>{3, 2, 1}));
}

TEST(Lentoax, DerivedCases) {
  EdgeData turn = mill();
  turn.dp[1] = 500;
  for (Plane p : {Plane::G17, Plane::G18, Plane::G19})
    EXPECT_EQ(run(turn, {}, p, Frame{}).axind, (std::array<int, 3>{2, 1, 3}));  // L-4, L-5
  ToolSettings sd17;
  sd17.length_const = 17;
  EXPECT_EQ(run(mill(), sd17, Plane::G18, Frame{}).axind, (std::array<int, 3>{1, 3, 2}));  // L-6
  ToolSettings t2;
  t2.length_type = 2;
  EXPECT_EQ(run(mill(), t2, Plane::G17, Frame{}).axind, (std::array<int, 3>{2, 1, 3}));  // L-7
  EXPECT_EQ(run(mill(), {}, Plane::G17, Frame{}, "XYZ").status, -1);                     // L-9
  Frame z90;
  z90.rotation = {0, 0, 90};
  LentoaxResult r10 = run(mill(), {}, Plane::G17, z90);
  EXPECT_EQ(r10.status, 0);
  EXPECT_EQ(r10.axind, (std::array<int, 3>{2, -3, 1}));  // L-10
  Frame z180;
  z180.rotation = {0, 0, 180};
  EXPECT_EQ(run(mill(), {}, Plane::G17, z180).axind, (std::array<int, 3>{-3, -2, 1}));  // L-11
  Frame x90;
  x90.rotation = {90, 0, 0};
  EXPECT_EQ(run(mill(), {}, Plane::G17, x90).axind, (std::array<int, 3>{3, 1, -2}));  // L-12
  for (const char* c : {"w", "Wcs", "T", "kcs", "M", "b"})
    EXPECT_GE(run(mill(), {}, Plane::G17, Frame{}, c).status, 0) << c;  // T-AX-E3
}

TEST(Lentoax, MirrorWcsAndTcs) {
  // Details §1.4: MIRROR X0, milling G17.
  Frame f;
  f.mirror = {true, false, false};
  ToolSettings off, on;
  on.mirror_length = true;
  EXPECT_EQ(run(mill(), off, Plane::G17, f, "WCS").axind, (std::array<int, 3>{-3, 2, 1}));
  EXPECT_EQ(run(mill(), on, Plane::G17, f, "WCS").axind, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(run(mill(), off, Plane::G17, f, "TCS").axind, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(run(mill(), on, Plane::G17, f, "TCS").axind, (std::array<int, 3>{-3, 2, 1}));
}

}  // namespace
}  // namespace ncoffset
