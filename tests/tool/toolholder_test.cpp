// The orientable toolholder alone (src/tool/toolholder*.cpp, docs/toolholders.md): rotations,
// the TCOFR angle solution and the pose of each kinematic type.
#include "tool/toolholder.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "ncoffset/alarm.hpp"

namespace ncoffset::tool {
namespace {

using lang::Value;

void expectNear(Vec3 a, Vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(a.z, b.z, 1e-9);
}

void set(ToolCarriers& c, int n, int m, const Value& v) {
  const Value idx[] = {Value::integer(m)};
  ASSERT_TRUE(c.write("$TC_CARR" + std::to_string(n), idx, true, v));
}

TEST(Toolholder, RotationIsRightHanded) {
  // R_y(30) (12, 0, 1) = (10.8923, 0, -5.1340): the 828D example (type M).
  expectNear(
      rotationAboutVector({0, 2, 0}, 30) * Vec3{12, 0, 1},
      {12 * std::cos(kPi / 6) + std::sin(kPi / 6), 0, -12 * std::sin(kPi / 6) + std::cos(kPi / 6)});
  expectNear(rotationAboutVector({0, 0, 0}, 30) * Vec3{1, 2, 3}, {1, 2, 3});  // no axis
}

TEST(Toolholder, TwoAxesHaveTwoSolutions) {
  // C (Z) then A (X) to (0, -0.5, 0.866): (0, 30) and (180, -30).
  const Vec3 f{0, -0.5, std::sqrt(0.75)};
  AngleSolutions s = solveTwoAxes({0, 0, 1}, {1, 0, 0}, {0, 0, 1}, f, {0, 0});
  ASSERT_EQ(s.count, 2);
  for (int i = 0; i < 2; ++i) {
    const auto& b = s.b[static_cast<size_t>(i)];
    expectNear(rotationAboutVector({0, 0, 1}, b[0]) *
                   (rotationAboutVector({1, 0, 0}, b[1]) * Vec3{0, 0, 1}),
               f);
  }
  // One axis about Y cannot reach a Y component.
  EXPECT_EQ(solveTwoAxes({0, 1, 0}, {}, {0, 0, 1}, f, {0, 0}).count, 0);
  // Parallel axes act as one.
  EXPECT_EQ(solveTwoAxes({0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, {0, 0}).count, 1);
}

TEST(Toolholder, PoseOfEachType) {
  ToolCarriers c(3);
  set(c, 8, 1, Value::real(1));  // v1 = +Y
  set(c, 13, 1, Value::real(90));
  set(c, 17, 1, Value::real(10));  // l3
  CarrierPose t = c.pose(1, CarrierAngles::Absolute, Mat3{}, false);
  expectNear(t.tool_rotation * Vec3{0, 0, 1}, {1, 0, 0});
  expectNear(t.tool_offset, {10, 0, 0});  // R1 l3
  set(c, 23, 1, Value::string("p"));
  CarrierPose p = c.pose(1, CarrierAngles::Absolute, Mat3{}, false);
  expectNear(p.tool_rotation * Vec3{0, 0, 1}, {0, 0, 1});
  expectNear(p.part_offset, {10, 0, 0});  // l2 + R1 (l3 + R2 l4) = R1 l3
  set(c, 23, 1, Value::string("Q"));
  EXPECT_THROW(c.pose(1, CarrierAngles::Absolute, Mat3{}, false), AlarmError);
  EXPECT_THROW(c.pose(4, CarrierAngles::Absolute, Mat3{}, false), AlarmError);
}

TEST(Toolholder, FineOffsetsCountWithTheSettingData) {
  ToolCarriers c(1);
  set(c, 3, 1, Value::real(5));
  set(c, 43, 1, Value::real(0.25));
  EXPECT_NEAR(c.pose(1, CarrierAngles::Absolute, Mat3{}, false).tool_offset.z, 5, 1e-12);
  EXPECT_NEAR(c.pose(1, CarrierAngles::Absolute, Mat3{}, true).tool_offset.z, 5.25, 1e-12);
}

TEST(Toolholder, DataReadBackWithTheirTypes) {
  ToolCarriers c(2);
  set(c, 21, 2, Value{lang::Type::Axis, 0, "b", {}});
  set(c, 34, 2, Value::string("HEAD"));
  Value out;
  const Value idx[] = {Value::integer(2)};
  ASSERT_TRUE(c.read("$TC_CARR21", idx, true, out));
  EXPECT_EQ(out.type, lang::Type::Axis);
  EXPECT_EQ(out.str, "B");
  ASSERT_TRUE(c.read("$TC_CARR34", idx, true, out));
  EXPECT_EQ(out.str, "HEAD");
  EXPECT_FALSE(c.read("$TC_DP1", idx, true, out));
  EXPECT_THROW(c.read("$TC_CARR50", idx, true, out), AlarmError);
  const Value bad[] = {Value::integer(3)};
  EXPECT_THROW(c.read("$TC_CARR1", bad, true, out), AlarmError);
  set(c, 1, 0, Value::integer(0));  // clears everything
  ASSERT_TRUE(c.read("$TC_CARR34", idx, true, out));
  EXPECT_EQ(out.str, "");
}

}  // namespace
}  // namespace ncoffset::tool
