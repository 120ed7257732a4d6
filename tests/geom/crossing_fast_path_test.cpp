// The fast path of nearestCrossing (filteredCrossings, docs/performance.md §31) against its
// general twin (intersect into a vector, every fraction computed): on random lines and arcs,
// also sharing an end point or touching (the approach and retraction lines of radius
// compensation), both must give the same crossings bit for bit and the same nearest one. And
// equidistantInto against equidistant.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "elements.hpp"
#include "geom/contour.hpp"

namespace ncoffset::geom {
namespace {

using test::arc;
using test::line;

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool sameCrossing(const Crossing& a, const Crossing& b) {
  return sameBits(a.p.a, b.p.a) && sameBits(a.p.o, b.p.o) && sameBits(a.u1, b.u1) &&
         sameBits(a.u2, b.u2) && sameBits(a.len1, b.len1) && sameBits(a.len2, b.len2);
}

// The fraction tests of radius compensation's callers.
bool onBeforeEnd(double u, double len) {
  return tol::onElement(u, len) && tol::beforeEnd(u, len);
}
bool afterStartOn(double u, double len) {
  return tol::afterStart(u, len) && tol::onElement(u, len);
}
const FractionTest kTests[] = {nullptr,          tol::onElement, tol::insideElement, tol::pastEnd,
                               tol::beforeStart, onBeforeEnd,    afterStartOn};

class Random {
 public:
  explicit Random(unsigned seed) : gen_(seed) {}
  double range(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(gen_);
  }
  double coord() { return range(-60, 60); }
  Vec2 point() { return {coord(), coord()}; }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(gen_); }
  // A line or an arc (a circle through p0 about a random centre, cw or ccw; some full
  // circles), starting at `from` when given.
  Element element(const Vec2* from) {
    const Vec2 p0 = from ? *from : point();
    if (pick(2) == 0) return line(p0, point());
    const Vec2 c = point();
    const double r = length(p0 - c), phi = range(-4, 4);
    const Vec2 p1 = pick(8) == 0 ? p0 : Vec2{c.a + r * std::cos(phi), c.o + r * std::sin(phi)};
    return arc(p0, p1, c, pick(2) == 0);
  }

 private:
  std::mt19937 gen_;
};

// Both paths on e1, e2 with every pair of tests: the filtered crossings are the general ones
// that pass the tests, and the nearest of them is the general nearest with the tests in accept.
void expectSame(const Element& e1, const Element& e2) {
  const std::vector<Crossing> all = intersect(e1, e2);
  for (FractionTest on1 : kTests) {
    for (FractionTest on2 : kTests) {
      std::vector<Crossing> want;
      for (const Crossing& x : all)
        if ((!on1 || on1(x.u1, x.len1)) && (!on2 || on2(x.u2, x.len2))) want.push_back(x);
      CrossingPair got;
      ASSERT_TRUE(filteredCrossings(e1, e2, on1, on2, got));
      ASSERT_EQ(got.n, static_cast<int>(want.size()));
      for (int i = 0; i < got.n; ++i) EXPECT_TRUE(sameCrossing(got.x[i], want[i]));
      // The joined lines' shortcut of the fast nearestCrossing (§36): only where there is none.
      if (joinedLinesMiss(e1, e2, on1)) {
        EXPECT_EQ(want.size(), 0u);
      }
      auto accept = [&](const Crossing& x) {
        return (!on1 || on1(x.u1, x.len1)) && (!on2 || on2(x.u2, x.len2));
      };
      auto key = [](const Crossing& x) { return x.u2 - x.u1; };
      const auto general = nearestCrossing(e1, e2, accept, key);
      const auto fast = nearestCrossing(e1, e2, on1, on2, key);
      ASSERT_EQ(general.has_value(), fast.has_value());
      if (general) {
        EXPECT_TRUE(sameCrossing(*general, *fast));
      }
    }
  }
}

TEST(CrossingFastPath, SameAsIntersectOnRandomElements) {
  Random rnd(22);
  for (int i = 0; i < 4000; ++i) {
    SCOPED_TRACE(i);
    const Element e1 = rnd.element(nullptr);
    const Element e2 = rnd.element(nullptr);
    expectSame(e1, e2);
    expectSame(e2, e1);
  }
}

// The approach line ends where the first equidistant starts; the retraction line starts where
// the last one ends: a crossing at a common end point, often tangential.
TEST(CrossingFastPath, SameAsIntersectAtCommonEndPoints) {
  Random rnd(23);
  for (int i = 0; i < 4000; ++i) {
    SCOPED_TRACE(i);
    const Element first = rnd.element(nullptr);
    const Element approach = line(rnd.point(), first.p0);
    expectSame(approach, first);
    const Element retract = rnd.element(&first.p1);
    expectSame(first, retract);
    // Along the tangent at the end (touching an arc there).
    const Vec2 t = first.endTangent();
    expectSame(first, line(first.p1, first.p1 + rnd.range(1, 30) * t));
  }
}

TEST(CrossingFastPath, SpiralsTakeTheGeneralPath) {
  Element spiral = arc({10, 0}, {0, 12}, {0, 0}, true);
  CrossingPair got;
  EXPECT_FALSE(filteredCrossings(spiral, line({0, 0}, {20, 20}), nullptr, nullptr, got));
  EXPECT_FALSE(filteredCrossings(line({0, 0}, {20, 20}), spiral, nullptr, nullptr, got));
  auto all = [](const Crossing&) { return true; };
  auto key = [](const Crossing& x) { return x.u2; };
  const auto general = nearestCrossing(line({0, 0}, {20, 20}), spiral, all, key);
  const auto fast = nearestCrossing(line({0, 0}, {20, 20}), spiral, nullptr, nullptr, key);
  ASSERT_TRUE(general && fast);
  EXPECT_TRUE(sameCrossing(*general, *fast));
}

// equidistantInto (compensateInto writes the equidistant into the window's slot): the same
// element as equidistant, and the slot as it was when there is none (an inside arc, r <= R).
TEST(CrossingFastPath, EquidistantIntoAsEquidistant) {
  Random rnd(24);
  for (int i = 0; i < 4000; ++i) {
    const Element e = rnd.element(nullptr);
    const double d = rnd.range(-30, 30);
    Element into = line({1, 2}, {3, 4});
    const Element before = into;
    const bool has = equidistantInto(e, d, into);
    const auto want = equidistant(e, d);
    ASSERT_EQ(has, want.has_value());
    const Element& expect = want ? *want : before;
    EXPECT_TRUE(sameBits(into.p0.a, expect.p0.a) && sameBits(into.p0.o, expect.p0.o) &&
                sameBits(into.p1.a, expect.p1.a) && sameBits(into.p1.o, expect.p1.o) &&
                into.arc == expect.arc);
  }
}

}  // namespace
}  // namespace ncoffset::geom
