// Chamfer and rounding geometry (PM-NC "Chamfer, rounding"; docs/contour-definitions.md): the
// tangent points of a rounding, the legs of CHF/CHR, the reduction of a value too large and the
// junctions where nothing is inserted.
#include "geom/corner_cut.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "elements.hpp"

namespace ncoffset::geom {
namespace {

using test::arc;
using test::line;

// Two lines at a 90 degree left turn at (40,0): the rounding of r = 5 touches 5 before and
// after the corner, its centre (35,5), counter-clockwise.
TEST(CornerCut, RoundingBetweenLines) {
  const CornerCut c = roundCorner(line({0, 0}, {40, 0}), line({40, 0}, {40, 30}), 5);
  ASSERT_TRUE(c.inserted);
  EXPECT_NEAR(c.q1.a, 35, 1e-9);
  EXPECT_NEAR(c.q1.o, 0, 1e-9);
  EXPECT_NEAR(c.q2.a, 40, 1e-9);
  EXPECT_NEAR(c.q2.o, 5, 1e-9);
  EXPECT_NEAR(c.centre.a, 35, 1e-9);
  EXPECT_NEAR(c.centre.o, 5, 1e-9);
  EXPECT_TRUE(c.ccw);
  EXPECT_NEAR(c.u1, 35.0 / 40, 1e-12);
  EXPECT_NEAR(c.u2, 5.0 / 30, 1e-12);
}

// A right turn: clockwise, the centre on the right.
TEST(CornerCut, RoundingRightTurn) {
  const CornerCut c = roundCorner(line({0, 0}, {0, 20}), line({0, 20}, {20, 20}), 2);
  ASSERT_TRUE(c.inserted);
  EXPECT_FALSE(c.ccw);
  EXPECT_NEAR(c.centre.a, 2, 1e-9);
  EXPECT_NEAR(c.centre.o, 18, 1e-9);
}

// A line into a clockwise arc (the golden case line_arc_g18): the centre 5 from the line and
// 25 from the arc's centre.
TEST(CornerCut, RoundingLineArc) {
  const CornerCut c = roundCorner(line({0, 0}, {20, 0}), arc({20, 0}, {60, 0}, {40, 0}, false), 5);
  ASSERT_TRUE(c.inserted);
  EXPECT_NEAR(c.centre.a, 40 - std::sqrt(600.0), 1e-9);
  EXPECT_NEAR(c.centre.o, 5, 1e-9);
  EXPECT_NEAR(c.q2.a, 40 - 20 * std::sqrt(600.0) / 25, 1e-9);
  EXPECT_NEAR(c.q2.o, 4, 1e-9);
}

// Too large for the second line (8 long): reduced to 8, the whole second line.
TEST(CornerCut, RoundingReduced) {
  const CornerCut c = roundCorner(line({0, 0}, {30, 0}), line({30, 0}, {30, 8}), 20);
  ASSERT_TRUE(c.inserted);
  EXPECT_NEAR(c.value, 8, 1e-9);
  EXPECT_NEAR(c.u2, 1, 1e-9);
}

// CHF: the chord is the chamfer's length (equal legs), CHR: the legs.
TEST(CornerCut, ChamferLengthAndLeg) {
  const Element a = line({0, 0}, {40, 0}), b = line({40, 0}, {40, 30});
  const CornerCut f = chamferCorner(a, b, ChamferKind::Length, 5);
  ASSERT_TRUE(f.inserted);
  EXPECT_NEAR(length(f.q2 - f.q1), 5, 1e-9);
  EXPECT_NEAR(f.q1.a, 40 - 5 / std::sqrt(2.0), 1e-9);
  const CornerCut r = chamferCorner(a, b, ChamferKind::Leg, 4);
  EXPECT_NEAR(r.q1.a, 36, 1e-12);
  EXPECT_NEAR(r.q2.o, 4, 1e-12);
  // A leg longer than the second line: reduced to it.
  const CornerCut big = chamferCorner(a, b, ChamferKind::Leg, 50);
  EXPECT_NEAR(big.value, 30, 1e-9);
}

// Straight on (tangent) and a reversal: nothing inserted.
TEST(CornerCut, NothingAtTangentOrReversal) {
  EXPECT_FALSE(roundCorner(line({0, 0}, {10, 0}), line({10, 0}, {20, 0}), 2).inserted);
  EXPECT_FALSE(roundCorner(line({0, 0}, {10, 0}), line({10, 0}, {0, 0}), 2).inserted);
  EXPECT_FALSE(
      chamferCorner(line({0, 0}, {10, 0}), line({10, 0}, {20, 0}), ChamferKind::Leg, 2).inserted);
}

}  // namespace
}  // namespace ncoffset::geom
