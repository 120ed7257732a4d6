// --decimals N (shortest_number.hpp: writeRounded, Number): at most N decimals, fixed notation,
// "-0" never, the shortest round-trip text where it is short enough; and the writers that use it
// (CSV, JSON Lines, MPF).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "out/mpf_writer.hpp"
#include "out/shortest_number.hpp"
#include "out/writers.hpp"
#include "writer_test_support.hpp"

namespace ncoffset::out {
namespace {

using test::File;
using test::lineSeg;
using test::readAll;

std::string rounded(double v, int decimals) {
  char text[kRoundedRoom];
  return std::string(text, writeRounded(text, v, decimals));
}

TEST(RoundedNumber, NoiseOfTheArithmeticGoes) {
  EXPECT_EQ(rounded(30.000000000000004, 3), "30");
  EXPECT_EQ(rounded(-7.1e-15, 3), "0");  // never "-0"
  EXPECT_EQ(rounded(-7.1e-15, 0), "0");
  EXPECT_EQ(rounded(-0.0, 5), "0");
  EXPECT_EQ(rounded(-0.4, 0), "0");
  EXPECT_EQ(rounded(0.1 + 0.2, 6), "0.3");
  EXPECT_EQ(rounded(29.999999999999996, 14), "30");
  EXPECT_EQ(rounded(-12.3400001, 4), "-12.34");
}

TEST(RoundedNumber, AtMostNDecimalsRoundedToTheNearest) {
  EXPECT_EQ(rounded(1.0 / 3.0, 0), "0");
  EXPECT_EQ(rounded(2.0 / 3.0, 0), "1");
  EXPECT_EQ(rounded(1.0 / 3.0, 4), "0.3333");
  EXPECT_EQ(rounded(2.0 / 3.0, 4), "0.6667");
  EXPECT_EQ(rounded(-2.0 / 3.0, 2), "-0.67");
  EXPECT_EQ(rounded(134.64101615137756, 3), "134.641");
  EXPECT_EQ(rounded(134.64101615137756, 0), "135");
  EXPECT_EQ(rounded(0.00004, 4), "0");  // {fmt} would write 4e-05
  EXPECT_EQ(rounded(0.00006, 4), "0.0001");
  EXPECT_EQ(rounded(1.5e-5, 17), "0.000015");  // no exponent
  EXPECT_EQ(rounded(1e-300, 17), "0");
  EXPECT_EQ(rounded(123456789.123, 2), "123456789.12");
  // Exact ties of the binary value go to even, as printf's %.Nf.
  EXPECT_EQ(rounded(0.125, 2), "0.12");
  EXPECT_EQ(rounded(2.5, 0), "2");
}

TEST(RoundedNumber, ShortestTextWhereItHasFewEnoughDecimals) {
  EXPECT_EQ(rounded(0.1, 17), "0.1");  // not 0.10000000000000001
  EXPECT_EQ(rounded(100, 0), "100");
  EXPECT_EQ(rounded(-2.5, 1), "-2.5");
  EXPECT_EQ(rounded(30.000000000000004, 17), "30.000000000000004");
  EXPECT_EQ(rounded(30.000000000000004, 15), "30.000000000000004");
  EXPECT_EQ(rounded(30.000000000000004, 14), "30");
}

TEST(RoundedNumber, HugeAndNonFiniteAsWithoutDecimals) {
  EXPECT_EQ(rounded(1e300, 3), "1e+300");
  EXPECT_EQ(rounded(-1e17, 3), "-1e+17");
  EXPECT_EQ(rounded(-1e15 - 0.125, 1), "-1000000000000000.1");  // the shortest text
  EXPECT_EQ(rounded(std::numeric_limits<double>::infinity(), 3), "inf");
  EXPECT_EQ(rounded(999999999999999.9, 0), "1000000000000000");
}

// Random values: at most N decimals, no exponent, never "-0", within half a unit of the last
// decimal (plus the double's own spacing) of the value.
TEST(RoundedNumber, RandomValuesAreCloseAndShort) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-20, 12), decimals(0, kMaxDecimals);
  for (int i = 0; i < 20000; ++i) {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    const int d = decimals(rng);
    const std::string t = rounded(v, d);
    ASSERT_EQ(t.find('e'), std::string::npos) << v;
    ASSERT_NE(t, "-0") << v;
    const auto dot = t.find('.');
    if (dot != std::string::npos) {
      ASSERT_LE(static_cast<int>(t.size() - dot - 1), d) << v << " " << t;
      ASSERT_NE(t.back(), '0') << t;
    }
    const double back = std::strtod(t.c_str(), nullptr);
    ASSERT_LE(std::fabs(back - v), 0.5 * std::pow(10.0, -d) * (1 + 1e-9) + std::fabs(v) * 1e-15)
        << v << " " << d << " " << t;
  }
}

TEST(RoundedNumber, FormatterKeepsTheDefault) {
  EXPECT_EQ(fmt::format("{}", Number{0.1 + 0.2}), "0.30000000000000004");
  EXPECT_EQ(fmt::format("{}", Number{-0.0}), "-0");  // "{}" as it is: callers add 0.0
  EXPECT_EQ(fmt::format("{} {}", Number{0.1 + 0.2, 3}, Number{-1e-9, 3}), "0.3 0");
}

Segment arcSegment() {
  Segment s = lineSeg(2, Motion::G2, {0, 0, 0}, {10.000000000000002, -3e-15, 0}, 99.99999999999999);
  s.centre = {5.0000001, 1.0 / 3.0, 0};
  return s;
}

TEST(RoundedNumber, CsvWithDecimals) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    RoundedCsvWriter w(f.get(), 3);
    w.segment(lineSeg(1, Motion::G0, {0, 0, 0}, {30.000000000000004, -7.1e-15, 2.0 / 3.0}));
    w.segment(arcSegment());
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(f.get()),
            "line,motion,x,y,z,cx,cy,cz,feed\n"
            "1,G0,30,0,0.667,,,,\n"
            "2,G2,10,0,0,5,0.333,0,100\n");
}

TEST(RoundedNumber, JsonLinesWithDecimals) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  static const std::string kName = "P.MPF";
  {
    JsonLinesWriter w(
        f.get(), [](int) -> const std::string& { return kName; }, 2);
    Segment s = arcSegment();
    s.normal = {-1e-17, 0, 1};
    w.segment(s);
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(f.get()),
            "{\"line\":2,\"file\":\"P.MPF\",\"motion\":\"G2\",\"x\":10,\"y\":0,\"z\":0,"
            "\"cx\":5,\"cy\":0.33,\"cz\":0,\"normal\":[0,0,1],\"turns\":0,\"feed\":100,\"feed_"
            "unit\":\"mm/min\"}\n");
}

TEST(RoundedNumber, MpfWithDecimals) {
  File f(std::tmpfile());
  ASSERT_TRUE(f);
  {
    MpfWriter w(f.get(), "wcs", {}, 1);
    w.segment(lineSeg(1, Motion::G1, {0, 0, 0}, {30.000000000000004, -7.1e-15, 2.0 / 3.0}, 12.34));
    w.finish(nullptr);
  }
  EXPECT_EQ(readAll(f.get()), mpfHeader("wcs") + "N1 G1 X30 Y0 Z0.7 F12.3 ; line 1\nM30\n");
}

}  // namespace
}  // namespace ncoffset::out
