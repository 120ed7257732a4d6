// The tangent junction's test without the root (trc::detail::surelyBelowPoint,
// docs/performance.md §48): wherever it answers true, the distance geom::length measures is
// below tol::kPoint, so joinTangent's decision is the one the root gives.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "geom/contour.hpp"
#include "trc/compensation_internal.hpp"

namespace ncoffset::trc {
namespace {

namespace tol = geom::tol;

// joinTangent's decision both ways: joined (true) or not.
bool joinedWithRoot(double d2) {
  return !(std::sqrt(d2) >= tol::kPoint);
}
bool joinedFast(double d2) {
  return detail::surelyBelowPoint(d2) || !(std::sqrt(d2) >= tol::kPoint);
}

TEST(JoinTangent, SquareBelowTheBoundIsADistanceBelowThePoint) {
  // Every double around the bound and around kPoint^2, ulp by ulp.
  for (double centre : {0.99 * tol::kPoint * tol::kPoint, tol::kPoint * tol::kPoint}) {
    double d2 = centre;
    for (int i = 0; i < 20000; ++i) d2 = std::nextafter(d2, 0.0);
    for (int i = 0; i < 40000; ++i, d2 = std::nextafter(d2, 1.0)) {
      if (detail::surelyBelowPoint(d2)) {
        EXPECT_LT(std::sqrt(d2), tol::kPoint) << d2;
      }
      EXPECT_EQ(joinedFast(d2), joinedWithRoot(d2)) << d2;
    }
  }
  EXPECT_TRUE(detail::surelyBelowPoint(0.0));
  EXPECT_FALSE(detail::surelyBelowPoint(tol::kPoint * tol::kPoint));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(joinedFast(nan), joinedWithRoot(nan));
}

TEST(JoinTangent, DistancesOfVectorsNearThePoint) {
  // Vectors of length about kPoint in every direction: the square summed as geom::length sums it.
  std::mt19937_64 rng(48);
  std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), scale(0.9, 1.1);
  int below = 0;
  for (int i = 0; i < 200000; ++i) {
    const double t = angle(rng), r = scale(rng) * tol::kPoint;
    const geom::Vec2 d{r * std::cos(t), r * std::sin(t)};
    const double d2 = d.a * d.a + d.o * d.o;
    EXPECT_EQ(joinedFast(d2), geom::length(d) < tol::kPoint);
    below += detail::surelyBelowPoint(d2) ? 1 : 0;
  }
  EXPECT_GT(below, 20000);
}

}  // namespace
}  // namespace ncoffset::trc
