// Segment geometry for the writers (src/out/arc_geometry.hpp): sweep, helix, length, box.
#include "out/arc_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::arcSeg;
using test::lineSeg;
constexpr double kPi = 3.14159265358979323846;

TEST(ArcGeometry, SweepSenseFullCircleAndTurns) {
  const Vec3 z{0, 0, 1};
  EXPECT_NEAR(arcGeometry(arcSeg(1, Motion::G3, {10, 0, 0}, {0, 10, 0}, {}, z)).sweep, kPi / 2,
              1e-12);
  EXPECT_NEAR(arcGeometry(arcSeg(1, Motion::G2, {10, 0, 0}, {0, 10, 0}, {}, z)).sweep, -1.5 * kPi,
              1e-12);
  EXPECT_NEAR(arcGeometry(arcSeg(1, Motion::G2, {10, 0, 0}, {10, 0, 0}, {}, z)).sweep, -2 * kPi,
              1e-12);
  EXPECT_NEAR(arcGeometry(arcSeg(1, Motion::G3, {10, 0, 0}, {0, 10, 4}, {}, z, 1, 2)).sweep,
              4.5 * kPi, 1e-12);
  // Seen from -Z, G2 turns the other way.
  EXPECT_NEAR(arcGeometry(arcSeg(1, Motion::G2, {10, 0, 0}, {0, 10, 0}, {}, {0, 0, -1})).sweep,
              -kPi / 2, 1e-12);
}

TEST(ArcGeometry, PointsAlongAHelix) {
  ArcGeometry g = arcGeometry(arcSeg(1, Motion::G3, {10, 0, 0}, {0, 10, 5}, {}, {0, 0, 1}, 1, 1));
  EXPECT_NEAR(g.rise, 5, 1e-12);
  Vec3 mid = g.at(0.5);  // 225 degrees, half way up
  EXPECT_NEAR(mid.x, -10 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(mid.y, -10 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(mid.z, 2.5, 1e-12);
  Vec3 end = g.at(1);
  EXPECT_NEAR(end.x, 0, 1e-12);
  EXPECT_NEAR(end.y, 10, 1e-12);
}

TEST(ArcGeometry, Length) {
  EXPECT_DOUBLE_EQ(segmentLength(lineSeg(1, Motion::G1, {0, 0, 0}, {3, 4, 12})), 13);
  EXPECT_NEAR(segmentLength(arcSeg(1, Motion::G3, {10, 0, 0}, {0, 10, 0}, {}, {0, 0, 1})), 5 * kPi,
              1e-12);
  // Helix: the unrolled screw line, sqrt((r*phi)^2 + h^2).
  EXPECT_NEAR(segmentLength(arcSeg(1, Motion::G3, {10, 0, 0}, {10, 0, 7}, {}, {0, 0, 1})),
              std::hypot(20 * kPi, 7), 1e-9);
}

TEST(ArcGeometry, BoxHasTheArcsExtremes) {
  Box b;
  EXPECT_TRUE(b.empty());
  // G18 arc (normal +Y) from Z10 to X10 clockwise seen from +Y: three quarters through -Z, -X.
  b.add(arcSeg(1, Motion::G2, {0, 0, 10}, {10, 0, 0}, {}, {0, 1, 0}));
  EXPECT_NEAR(b.lo.x, -10, 1e-12);
  EXPECT_NEAR(b.hi.x, 10, 1e-12);
  EXPECT_NEAR(b.lo.z, -10, 1e-12);
  EXPECT_NEAR(b.hi.z, 10, 1e-12);
  EXPECT_EQ(b.lo.y, 0);
  EXPECT_EQ(b.hi.y, 0);
  Box q;
  q.add(arcSeg(1, Motion::G3, {0, 0, 10}, {10, 0, 0}, {}, {0, 1, 0}));  // the short quarter
  EXPECT_NEAR(q.lo.x, 0, 1e-12);
  EXPECT_NEAR(q.lo.z, 0, 1e-12);
}

}  // namespace
}  // namespace ncoffset::out
