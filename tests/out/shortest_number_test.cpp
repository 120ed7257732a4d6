// appendShortest must write exactly what {fmt}'s "{}" writes for every double (the CSV contract
// asks for the shortest round-trip representation); the fast path only saves time.
#include "out/shortest_number.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace ncoffset::out {
namespace {

std::string viaFast(double v) {
  fmt::memory_buffer b;
  appendShortest(b, v);
  return fmt::to_string(b);
}

std::string viaFmt(double v) {
  return fmt::format("{}", v + 0.0);
}

// Straight into a character array, as the CSV writer uses it.
std::string viaInline(double v) {
  char text[32];
  return std::string(text, writeShortest(text, v));
}

TEST(ShortestNumber, SameTextAsFmtForTypicalValues) {
  for (double v : {0.0,
                   -0.0,
                   1.0,
                   -1.0,
                   0.5,
                   10.25,
                   41.33974596215561,
                   15.527864045000421,
                   3.944271909999159,
                   0.1,
                   0.2,
                   0.3,
                   1e-4,
                   9.9999e-5,
                   1e-5,
                   123456.789012,
                   999999999.999999,
                   1e9,
                   -1e9,
                   1e15,
                   1e16,
                   1e300,
                   5e-324,
                   0.000125,
                   7.000001,
                   -2.5e-4,
                   100000000.0,
                   12345678.9,
                   0.1 + 0.2,
                   999999999.0,
                   -999999999.0,
                   4294967296.0,
                   1e10,
                   -7.0,
                   0.99999999999})
    EXPECT_EQ(viaFast(v), viaFmt(v)) << v;
  for (double v : {0.0, -0.0, 1.0, -1.0, 96.0, -20.0, 1000.0, 999999999.0, -999999999.0, 1e9,
                   4294967296.0, 1e10, 10.25, -0.5, std::nan(""), 1e300})
    EXPECT_EQ(viaInline(v), viaFmt(v)) << v;
}

TEST(ShortestNumber, SameTextAsFmtForRandomValues) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> any(-1e6, 1e6);
  std::uniform_int_distribution<long long> micro(-1000000000000LL, 1000000000000LL);
  std::uniform_int_distribution<int> decimals(0, 9);
  for (int i = 0; i < 200000; ++i) {
    double v = any(rng);
    ASSERT_EQ(viaFast(v), viaFmt(v)) << v;
    // Values with few decimals (the fast path) and their neighbours (not on it).
    double d = static_cast<double>(micro(rng)) / std::pow(10.0, decimals(rng));
    ASSERT_EQ(viaFast(d), viaFmt(d)) << d;
    ASSERT_EQ(viaInline(d), viaFmt(d)) << d;
    double n = std::nextafter(d, 1e300);
    ASSERT_EQ(viaFast(n), viaFmt(n)) << n;
  }
}

// Every fraction of up to six decimals (the fast path's two groups of three digits and the
// table of their trailing zeros), with random whole parts, both signs, against {fmt}.
TEST(ShortestNumber, EveryMicroFractionAsFmt) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<long long> large(0, 999999999), small(0, 999);
  for (long long f = 1; f < 1000000; ++f) {
    const long long whole = f % 2 ? small(rng) : large(rng);
    const double v = static_cast<double>(whole * 1000000 + f) / 1e6;
    ASSERT_EQ(viaInline(v), viaFmt(v)) << v;
    ASSERT_EQ(viaInline(-v), viaFmt(-v)) << -v;
  }
}

// The fast path's whole numbers (the signed conversion of the value itself, §37) against {fmt}:
// every one within ±100000 and its neighbours (no whole numbers: the fraction or slow path),
// random ones up to the 1e9 limit, and the limits themselves.
TEST(ShortestNumber, EveryWholeNumberAsFmt) {
  for (int i = -100000; i <= 100000; ++i) {
    const double v = i;
    ASSERT_EQ(viaInline(v), viaFmt(v)) << v;
    ASSERT_EQ(viaInline(std::nextafter(v, 1e300)), viaFmt(std::nextafter(v, 1e300))) << v;
    ASSERT_EQ(viaInline(std::nextafter(v, -1e300)), viaFmt(std::nextafter(v, -1e300))) << v;
  }
  std::mt19937_64 rng(37);
  std::uniform_int_distribution<int> any(-999999999, 999999999);
  for (int i = 0; i < 1000000; ++i) {
    const double v = any(rng);
    ASSERT_EQ(viaInline(v), viaFmt(v)) << v;
  }
  for (double v : {999999999.0, -999999999.0, 1e9, -1e9, std::nextafter(1e9, 0.0),
                   std::nextafter(-1e9, 0.0), 2147483647.0, -2147483648.0, 4294967295.0, -0.0, 0.0,
                   std::numeric_limits<double>::infinity()})
    EXPECT_EQ(viaInline(v), viaFmt(v)) << v;
}

// writeFixed<true> (CsvWriter's usual row): where it writes a text, {fmt}'s (writeFixed<true,
// true>: with a comma before it); it writes one for
// every whole number within ±9999 (the signed table, §49) and every decimal of at most six
// places from 1e-4 to below 10000, and none from 10000 on. Every whole number within ±100000 and
// its neighbours, 300,000 random decimals, and the limits.
TEST(ShortestNumber, SmallFixedAsFmt) {
  const auto check = [](double v, bool written) {
    char text[32];
    const char* end = writeFixed<true>(text, v);
    if (end) {
      ASSERT_EQ(std::string(static_cast<const char*>(text), end), viaFmt(v)) << v;
    }
    ASSERT_EQ(end != nullptr, written) << v;
    // The field (its comma from the table, §51): the same with a comma before it.
    const char* field_end = writeFixed<true, true>(text, v);
    if (field_end) {
      ASSERT_EQ(text[0], ',') << v;
      ASSERT_EQ(std::string(static_cast<const char*>(text) + 1, field_end), viaFmt(v)) << v;
    }
    ASSERT_EQ(field_end != nullptr, written) << v;
  };
  for (int i = -100000; i <= 100000; ++i) {
    check(i, i >= -9999 && i <= 9999);
    check(std::nextafter(static_cast<double>(i), 1e300), false);
    check(std::nextafter(static_cast<double>(i), -1e300), false);
  }
  std::mt19937_64 rng(49);
  std::uniform_int_distribution<int> places(0, 6);
  const double scale[] = {1, 10, 100, 1000, 10000, 100000, 1000000};
  for (int i = 0; i < 300000; ++i) {
    const int k = places(rng);
    const auto limit = static_cast<long long>(1e4 * scale[k]) - 1;
    const double v =
        static_cast<double>(std::uniform_int_distribution<long long>(-limit, limit)(rng)) /
        scale[k];
    check(v, v == 0 || std::fabs(v) >= 1e-4);
  }
  for (double v : {-0.0, 0.0, 9999.0, -9999.0, 9999.999999, -9999.999999, 1e-4, 2.5})
    check(v, true);
  for (double v : {10000.0, -10000.0, 2147483647.0, -2147483648.0, 1e-5, 2.7889999999999997,
                   std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(), std::nan("")})
    check(v, false);
}

std::string viaSlow(double v) {
  char text[32];
  return std::string(text, writeShortestSlow(text, v));
}

std::string viaFmtTwin(double v) {
  char text[32];
  return std::string(text, writeShortestFmt(text, v));
}

// writeShortestSlow (Dragonbox's decimal laid out by ncoffset) against its twin, {fmt}'s "{}":
// every exponent and both notations (random bit patterns), the coordinates' range, sums of
// short decimals (2.7889999999999997), the neighbours of short decimals, and the limits.
TEST(ShortestNumber, SlowPathAsFmtForMillionsOfValues) {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> coord(-1e4, 1e4);
  std::uniform_int_distribution<long long> milli(-100000000, 100000000);
  for (int i = 0; i < 1000000; ++i) {
    double bits;
    const unsigned long long r = rng();
    std::memcpy(&bits, &r, sizeof bits);
    ASSERT_EQ(viaSlow(bits), viaFmtTwin(bits)) << r;
    const double c = coord(rng);
    ASSERT_EQ(viaSlow(c), viaFmtTwin(c)) << c;
    const double sum =
        static_cast<double>(milli(rng)) / 1000 + static_cast<double>(milli(rng)) / 8000;
    ASSERT_EQ(viaSlow(sum), viaFmtTwin(sum)) << sum;
    const double next = std::nextafter(static_cast<double>(milli(rng)) / 1000, 1e300);
    ASSERT_EQ(viaSlow(next), viaFmtTwin(next)) << next;
  }
  for (int e = -330; e <= 310; ++e)
    for (double m : {1.0, 1.5, 9.999999999999999, 2.7889999999999997, -3.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      ASSERT_EQ(viaSlow(v), viaFmtTwin(v)) << v;
      ASSERT_EQ(viaSlow(std::nextafter(v, 0.0)), viaFmtTwin(std::nextafter(v, 0.0))) << v;
    }
  for (double v : {0.0, -0.0, 5e-324, -5e-324, 2.2250738585072014e-308, 1.7976931348623157e308,
                   1e-5, 9.999e-5, 1e-4, 1e15, 1e16, 9999999999999998.0, 1e100, 1e-100, 0.1 + 0.2,
                   std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(), std::nan("")})
    EXPECT_EQ(viaSlow(v), viaFmtTwin(v)) << v;
  EXPECT_EQ(viaFmtTwin(-0.0), "0");
}

TEST(ShortestNumber, UnsignedAsToString) {
  char text[16];
  for (unsigned v = 0; v < 100000; ++v)
    ASSERT_EQ(std::string(text, writeUnsigned(text, v)), std::to_string(v));
  for (unsigned v = 100000; v < 100000000; v += 9973)
    ASSERT_EQ(std::string(text, writeUnsigned(text, v)), std::to_string(v));
  for (unsigned v : {999999u, 1000000u, 10000000u, 99999999u, 100000000u, 123456789u, 4294967295u})
    EXPECT_EQ(std::string(text, writeUnsigned(text, v)), std::to_string(v));
}

TEST(ShortestNumber, NonFiniteAsFmt) {
  EXPECT_EQ(viaFast(std::numeric_limits<double>::infinity()),
            viaFmt(std::numeric_limits<double>::infinity()));
  EXPECT_EQ(viaFast(std::nan("")), viaFmt(std::nan("")));
}

}  // namespace
}  // namespace ncoffset::out
