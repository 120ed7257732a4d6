// appendShortest must write exactly what {fmt}'s "{}" writes for every double (the CSV contract
// asks for the shortest round-trip representation); the fast path only saves time.
#include "out/shortest_number.hpp"

#include <gtest/gtest.h>

#include <cmath>
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
