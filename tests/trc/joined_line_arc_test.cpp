// geom::joinedLineArcMiss (docs/performance.md §42), the fast reject of the approach's and
// retraction's G460 search into / out of an arc, against the search it saves: wherever it
// answers true, nearestCrossing with the callers' fraction tests (and the general intersect with
// the same tests) finds no crossing. Random arcs from small to large coordinates and radii, and
// lines from anywhere, from near the tangent and from inside the circle.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geom/contour.hpp"

namespace ncoffset::geom {
namespace {

// The fraction tests of radius compensation's callers (approach_retraction.cpp).
bool onBeforeEnd(double u, double len) {
  return tol::onElement(u, len) && tol::beforeEnd(u, len);
}
bool afterStartOn(double u, double len) {
  return tol::afterStart(u, len) && tol::onElement(u, len);
}

class Random {
 public:
  explicit Random(unsigned seed) : gen_(seed) {}
  double range(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(gen_);
  }
  // A magnitude from 1e-3 to 1e4 (log-uniform).
  double scale() { return std::pow(10.0, range(-3, 4)); }
  Vec2 around(Vec2 c, double s) { return {c.a + range(-s, s), c.o + range(-s, s)}; }

  // An arc about a random centre whose ends lie on one circle (not a spiral).
  Element arc() {
    Element e;
    e.arc = true;
    const double at = scale();
    e.c = {range(-at, at), range(-at, at)};
    const double r = scale(), a0 = range(-4, 4), a1 = range(-4, 4);
    e.p0 = {e.c.a + r * std::cos(a0), e.c.o + r * std::sin(a0)};
    e.p1 = {e.c.a + r * std::cos(a1), e.c.o + r * std::sin(a1)};
    e.ccw = range(0, 1) < 0.5;
    return e;
  }
  // The far end of a line through `at`: anywhere, near the tangent there, or inside the circle.
  Vec2 farEnd(const Element& e, Vec2 at) {
    const double r = length(at - e.c), kind = range(0, 3);
    if (kind < 1) return around(at, r * scale());
    const Vec2 t = leftNormal(unit(at - e.c));
    if (kind < 2)
      return at + (r * range(-3, 3)) * t + (r * std::pow(10.0, range(-12, 0))) * unit(at - e.c);
    return around(e.c, r * 0.9);
  }

 private:
  std::mt19937 gen_;
};

Element lineOf(Vec2 p0, Vec2 p1) {
  Element e;
  e.p0 = p0;
  e.p1 = p1;
  return e;
}

TEST(JoinedLineArcMiss, TheApproachLineFindsNoCrossingWhereItAnswersTrue) {
  Random rnd(42);
  int fast = 0;
  for (int i = 0; i < 200000; ++i) {
    const Element a = rnd.arc();
    const Element l = lineOf(rnd.farEnd(a, a.p0), a.p0);
    if (!joinedLineArcMiss(l, a, true)) continue;
    ++fast;
    const auto key = [](const Crossing& x) { return x.u1; };
    ASSERT_FALSE(nearestCrossing(l, a, tol::insideElement, tol::onElement, key)) << i;
    const auto accept = [](const Crossing& x) {
      return tol::insideElement(x.u1, x.len1) && tol::onElement(x.u2, x.len2);
    };
    ASSERT_FALSE(nearestCrossing(l, a, accept, key)) << i;
  }
  EXPECT_GT(fast, 20000);
}

TEST(JoinedLineArcMiss, TheRetractionLineFindsNoCrossingWhereItAnswersTrue) {
  Random rnd(7);
  int fast = 0;
  for (int i = 0; i < 200000; ++i) {
    const Element a = rnd.arc();
    const Element l = lineOf(a.p1, rnd.farEnd(a, a.p1));
    if (!joinedLineArcMiss(l, a, false)) continue;
    ++fast;
    const auto key = [](const Crossing& x) { return -x.u1; };
    ASSERT_FALSE(nearestCrossing(a, l, onBeforeEnd, afterStartOn, key)) << i;
    const auto accept = [](const Crossing& x) {
      return onBeforeEnd(x.u1, x.len1) && afterStartOn(x.u2, x.len2);
    };
    ASSERT_FALSE(nearestCrossing(a, l, accept, key)) << i;
  }
  EXPECT_GT(fast, 20000);
}

TEST(JoinedLineArcMiss, OnlyALineJoinedAtTheEndPointItNames) {
  Element a;
  a.arc = true;
  a.c = {0, 0};
  a.p0 = {10, 0};
  a.p1 = {0, 10};
  // Into the circle at p0 (the approach), out of it at p1 (the retraction).
  EXPECT_TRUE(joinedLineArcMiss(lineOf({30, -5}, a.p0), a, true));
  EXPECT_TRUE(joinedLineArcMiss(lineOf(a.p1, {-5, 30}), a, false));
  // Out of it at p0 / into it at p1: the other crossing lies on the line.
  EXPECT_FALSE(joinedLineArcMiss(lineOf({5, 1}, a.p0), a, true));
  EXPECT_FALSE(joinedLineArcMiss(lineOf(a.p1, {1, 5}), a, false));
  // Not ending at that point, or along the tangent.
  EXPECT_FALSE(joinedLineArcMiss(lineOf({30, -5}, {10, 1e-9}), a, true));
  EXPECT_FALSE(joinedLineArcMiss(lineOf({10, -20}, a.p0), a, true));
  EXPECT_FALSE(joinedLineArcMiss(lineOf(a.p0, {30, -5}), a, false));
  // A spiral (its end off the start's circle): intersect's search, not this one.
  Element s = a;
  s.p1 = {0, 10.5};
  EXPECT_FALSE(joinedLineArcMiss(lineOf(s.p1, {-5, 30}), s, false));
}

}  // namespace
}  // namespace ncoffset::geom
